#pragma once
// Chamfers on the edges of the blank: a plane slanted across one principal axis that joins
// the two sides of the part's box meeting at that edge. They are chamfers, machined along
// the edge, not floors of open pockets seen along their own normal.
#include "FaceCatalogue.h"
#include "Tolerances.h"

#include <vector>

namespace aeronc::recognition {

// Per face: whether it is such a chamfer. axes: the part's principal axes (± pairs, as
// principalAxes gives them).
std::vector<bool> findEdgeChamfers(const FaceCatalogue& faces, const Tolerances& tol, const std::vector<Vec3>& axes);

}  // namespace aeronc::recognition
