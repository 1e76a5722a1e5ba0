#pragma once
// A clearing plan as moves, level by level: each chain entered by its helix, ramp or plunge
// from just above the level before, then its feed moves at the level.
#include "ClearingPlan.h"
#include "MoveWriter.h"

namespace aeronc::toolpath {

struct EntrySettings {
    double clearancePlane = 0;  // rapids between chains
    double approach = 1;        // rapid down to this far above the material, then enter
    double rampAngleDeg = 3;
    double chordTolerance = 0.01;
    bool climb = true;          // helices clockwise
};

void chainMoves(MoveWriter& w, const Chain& chain, double level, double above, const EntrySettings& s);

// Every chain at every level; `top` is where the material starts above the first level.
void clearingMoves(MoveWriter& w, const ClearingPlan& plan, const std::vector<double>& levels, double top,
                   const EntrySettings& s);

}  // namespace aeronc::toolpath
