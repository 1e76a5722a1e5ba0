#pragma once
// Chamfers on the edges of the blank: a plane slanted across one principal axis that joins
// the two sides of the part's box meeting at that edge. They are chamfers, machined along
// the edge, not floors of open pockets seen along their own normal. One that rises from a
// floor square to the edge is the wall of a blind step across the edge instead: machined
// from that floor's side, not along its own normal either.
#include "FaceCatalogue.h"
#include "Tolerances.h"

#include <vector>

namespace aeronc::recognition {

struct EdgeCuts {
    std::vector<bool> chamfers;   // per face: a chamfer on an edge of the blank
    std::vector<bool> stepWalls;  // per face: the slanted wall of a blind step across an edge
    std::vector<bool> boxSides;   // per face: a plane on a side of the part's box (the blank's own)
};

// axes: the part's principal axes (± pairs, as principalAxes gives them).
EdgeCuts findEdgeChamfers(const FaceCatalogue& faces, const Tolerances& tol, const std::vector<Vec3>& axes);

}  // namespace aeronc::recognition
