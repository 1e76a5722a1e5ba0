#pragma once
// The OCCT side of the verification: a B-rep solid as the triangle mesh the dexel model reads.
#include <aeronc/core/TriangleMesh.h>

#include <TopoDS_Shape.hxx>

namespace aeronc {

// Meshes the shape with BRepMesh_IncrementalMesh (absolute linear deflection in mm, angular
// deflection in radians) and returns its triangles oriented outward, each tagged with its face's
// 1-based index in TopExp::MapShapes(shape, TopAbs_FACE) order (FreeCAD's FaceN). Throws
// aeronc::Error when a face gets no triangulation.
TriangleMesh meshShape(const TopoDS_Shape& shape, double deflection = 0.005, double angularDeflection = 0.5);

}  // namespace aeronc
