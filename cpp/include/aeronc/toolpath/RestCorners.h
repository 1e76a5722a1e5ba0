#pragma once
// Rest machining of corners: only the material that a previous, larger cutter left in the
// pocket and that this one can reach.
#include <aeronc/toolpath/PocketClearing.h>

#include <optional>

namespace aeronc::toolpath {

// The rest is what this cutter reaches at parameters.radialAllowance (the pocket eroded by
// R + allowance, dilated by R) less what the previous cutter cleared at the radial allowance it
// left, previousAllowance (eroded by R0 + that allowance, dilated by R0), cleared at the same
// levels as the pocket. When the previous unit left more than this one leaves, the band between
// the two along the walls is part of the rest: it is material, and the entries and links keep
// out of it. previousAllowance unset: the same as this unit's. An empty toolpath when the
// previous cutter left nothing that this one reaches.
Toolpath restCorners(const PocketUnit& unit, const Cutter& previous, const Cutter& cutter,
                     const PocketParameters& parameters, std::optional<double> previousAllowance = std::nullopt);

}  // namespace aeronc::toolpath
