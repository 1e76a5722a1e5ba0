#pragma once
// Points inside a face, for measures over its area (channel depths and widths, wall samples).
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>

#include <vector>

namespace aeronc::impeller {

// The points of a grid of (nu + 1) x (nv + 1) over the face's parameter range that its
// classifier puts inside the face (points on or outside its boundary are left out).
std::vector<gp_Pnt> pointsInsideFace(const TopoDS_Face& face, int nu, int nv);

}  // namespace aeronc::impeller
