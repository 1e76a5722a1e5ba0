#pragma once
// Helical hole milling: an end mill interpolates a hole larger than itself.
#include <aeronc/toolpath/Hole.h>

namespace aeronc::toolpath {

struct HelicalHoleParameters : CutParameters {
    double finishingAllowance = 0;  // radial allowance of the finishing circle, at most radialAllowance
    double breakThrough = 0.5;      // below bottom for a through hole, beyond the cutter's corner radius
};

// Per hole: a helix at radialAllowance down to the floor at a pitch of at most stepDown (and
// at most the ramp angle's), a full circle there, then a finishing circle at
// finishingAllowance. A cutter under half the hole (it would leave a core) clears it level by
// level instead: a helix round a circle inside the cutter's radius, then rings at most a
// step-over apart out to the wall (HelicalHole.cpp). Climb milling runs clockwise.
Toolpath helicalHole(const std::vector<Hole>& holes, const Cutter& cutter, const HelicalHoleParameters& parameters);

}  // namespace aeronc::toolpath
