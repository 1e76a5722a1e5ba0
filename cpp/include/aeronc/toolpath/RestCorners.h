#pragma once
// Rest machining of corners: only the material that a previous, larger cutter left in the
// pocket and that this one can reach.
#include <aeronc/toolpath/PocketClearing.h>

namespace aeronc::toolpath {

// The rest is the pocket's opening by R less its opening by R0 (each opening: eroded, then
// dilated), both at parameters.radialAllowance, cleared at the same levels as the pocket. An
// empty toolpath when the previous cutter left nothing that this one reaches.
Toolpath restCorners(const PocketUnit& unit, const Cutter& previous, const Cutter& cutter,
                     const PocketParameters& parameters);

}  // namespace aeronc::toolpath
