#pragma once
// A unit's geometry in its setup's frame, from its domain element: contour and islands as loops
// (counter-clockwise outside, clockwise islands), the island tops it faces, the edges open to the
// blank, where it stands, and the hole it makes.
#include <aeronc/chain/MachiningChain.h>
#include <aeronc/recognition/DomainTree.h>
#include <aeronc/recognition/SetupFrame.h>

namespace aeronc::chain::detail {

// Fills u's contour, islands, islandTops (a pocket unit: the islands standing in the element's
// own cavity, above its floor and below `ceiling`), openEdges, at and holes (a hole from `top`
// down to `bottom` along the setup's axis).
void outlineUnit(MachiningUnit& u, const recognition::DomainElement& e, const recognition::SetupFrame& frame,
                 double ceiling, double top, double bottom);

}  // namespace aeronc::chain::detail
