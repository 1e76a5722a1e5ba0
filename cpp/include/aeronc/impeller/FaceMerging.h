#pragma once
// The faces a Boolean fuse leaves split on one surface merged again, without the hangs of a
// general merge: OCCT 7.6's ShapeUpgrade_UnifySameDomain does not merge the pieces of a periodic
// B-spline face that meet at its seam, and it does not return on the shared impeller's bore,
// whose pieces lie on cylinders of opposite axes.
#include <TopoDS_Shape.hxx>

namespace aeronc::impeller {

// Merges adjacent faces of one surface in `solid`: pieces of one face (the same surface) and
// coplanar faces by ShapeUpgrade_UnifySameDomain limited to those edges, then the pieces it
// leaves (across a periodic surface's seam, or on coincident cylinders) one group at a time,
// keeping a group's merge only when the solid stays one valid solid and the merged face has its
// pieces' area. Returns `solid` itself when nothing merges.
TopoDS_Shape mergeFacesOfOneSurface(const TopoDS_Shape& solid);

}  // namespace aeronc::impeller
