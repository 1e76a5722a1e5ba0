#pragma once
// Checks of the input shared by the operations; each throws aeronc::inputError with the name
// of what is wrong.
#include <aeronc/toolpath/Toolpath.h>

#include <string>

namespace aeronc::toolpath {

void requireFinite(double value, const std::string& what);

// The loop without repeated points (a closing copy of the first point included), checked:
// finite, within 10^6 mm of the origin, at least 3 points, some area, not crossing or
// touching itself.
Loop checkedLoop(const Loop& loop, const std::string& what);

void checkCutter(const Cutter& cutter, const std::string& what = "the cutter");

// Heights and parameters of a milling unit; returns the step-over in mm.
double checkMilling(const CutParameters& p, const Cutter& cutter, double top, double bottom);

// The plane of the rapids between cuts and the height where the unit starts and ends.
struct Heights {
    double clearance;  // top + clearance
    double safe;       // safeHeight, or the clearance plane
};
Heights heightsOf(const CutParameters& p, double top);

}  // namespace aeronc::toolpath
