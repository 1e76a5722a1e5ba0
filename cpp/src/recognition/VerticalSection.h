#pragma once
// Fast section of a face with the plane h = const, done in the face's parameter space where
// the section is straight lines: planes not parallel to the slice, cylinders and cones about
// the setup axis, cylinders square to it (along their rulings), tori and spheres about it
// (along their circles), ruled B-splines whose two rows of poles each lie at one height
// (along their iso-curves). Other faces are meshed (MeshSection) or go through OCCT's section.
#include <aeronc/recognition/SetupFrame.h>

#include "FaceCatalogue.h"

#include <BRepTopAdaptor_FClass2d.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <TopoDS_Face.hxx>
#include <vector>

namespace aeronc::recognition {

// Appends the section polylines of `face` at height h; false when the face's surface is
// not one this handles (the caller then uses the general section).
bool sectionVerticalFace(const FaceInfo& face, const std::vector<Handle(Geom2d_TrimmedCurve)>& boundaryUV,
                         BRepTopAdaptor_FClass2d& classifier, const SetupFrame& frame, double h, double chordTol,
                         std::vector<std::vector<P2>>& out);

}  // namespace aeronc::recognition
