#pragma once
// Holes by geometry, for measuring hole recognition on parts without labels: a face is a
// hole wall when it is a concave (inner) cylinder, the cylinders of the part on its axis with
// its radius cover more than half the circle, and its axis and the space round it inside its
// wall are empty. A corner fillet (a quarter), a slot's round end (a half) or a groove round a
// boss is no hole; a hole cut through by another feature still is.
#include <TopoDS_Shape.hxx>

#include <vector>

namespace aeronc::testparts {

// Per face of the solid in TopExp::MapShapes order (FaceN - 1): whether it is a hole wall.
// minSpanDegrees: how much of the circle the coaxial cylinders must cover.
std::vector<bool> holeWallsByGeometry(const TopoDS_Shape& solid, double minSpanDegrees = 185);

}  // namespace aeronc::testparts
