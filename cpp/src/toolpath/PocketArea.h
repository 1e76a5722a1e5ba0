#pragma once
// The area a pocket unit may machine, as Clipper regions.
#include "Clip.h"

#include <aeronc/toolpath/PocketClearing.h>

namespace aeronc::toolpath {

struct PocketArea {
    clip::Paths material;  // the contour less the islands: what the pocket removes
    clip::Paths region;    // the same, extended across the open edges by `extension`
};

// Checks the loops and open edges (aeronc::inputError). Each open edge adds the rectangle of
// depth `extension` on its outer side: open edges are taken to lie on the blank's boundary,
// with nothing beyond them at the pocket's levels. openCorners: where two open edges meet at a
// convex corner, the rectangles also run on past it (the corner's quadrant taken as open).
PocketArea pocketArea(const PocketUnit& unit, double extension, bool openCorners = false);

}  // namespace aeronc::toolpath
