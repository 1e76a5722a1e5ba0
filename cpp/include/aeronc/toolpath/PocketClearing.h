#pragma once
// Pocket clearing: concentric offset rings of the tool-centre region, level by level.
#include <aeronc/toolpath/Toolpath.h>

namespace aeronc::toolpath {

// The operation geometry of a generalised pocket at one setup.
struct PocketUnit {
    Loop contour;
    std::vector<Loop> islands;
    // Pieces of the contour open to the blank: nothing beyond them is material, so they do not
    // hold the tool back.
    std::vector<Segment> openEdges;
    double top = 0;     // top constraint height
    double bottom = 0;  // floor height
    double floorFilletRadius = 0;  // of the floor's edge along the walls; the cutter keeps out of it
    // Per island (empty: none): where it stops short of the top, the height of its top; NaN
    // where it stands through the unit. Above its top plus the axial allowance an island is
    // not in the way, and a level at that height clears around it.
    std::vector<double> islandTops;
    // A floor unit: the lower islands' tops are floors of it too, each faced at its height.
    bool faceIslandTops = false;
};

struct PocketParameters : CutParameters {
    bool finishingPass = false;     // after the clearing, once round the walls at every level
    double finishingAllowance = 0;  // radial allowance of that pass, at most radialAllowance
};

// Throws aeronc::inputError on bad geometry or parameters and when the cutter does not fit.
Toolpath pocketClearing(const PocketUnit& unit, const Cutter& cutter, const PocketParameters& parameters);

}  // namespace aeronc::toolpath
