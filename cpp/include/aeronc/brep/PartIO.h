#pragma once
#include <TopoDS_Shape.hxx>
#include <string>
#include <vector>

namespace aeronc {

// Reads a STEP or BREP file (format from its content, not its name) and returns the
// one solid it holds. Throws aeronc::Error with a message a user can act on for: a
// missing or empty file, an unknown format, no solid or several, an open shell, and
// a B-rep that fails OCCT's checker.
TopoDS_Shape loadPart(const std::string& path);

// The whole shape of a STEP or BREP file, without loadPart's one-solid checks (a part exported
// as several bodies).
TopoDS_Shape loadShape(const std::string& path);

// loadPart for a STEP file, plus the STEP entity name of every face of the solid in
// FaceN order ("" where the file gives none). Labelled data sets key faces by these names.
TopoDS_Shape loadStepWithFaceNames(const std::string& path, std::vector<std::string>& faceNames);

// Same checks for a shape passed as BREP text (FreeCAD's Shape.exportBrepToString()).
TopoDS_Shape partFromBrepText(const std::string& text);

// The whole shape of BREP text, unchecked (it may hold free shapes besides a solid).
TopoDS_Shape shapeFromBrepText(const std::string& text);

// Same checks for a shape already in memory.
TopoDS_Shape validatedSolid(const TopoDS_Shape& shape, const std::string& origin);

void writeStep(const TopoDS_Shape& shape, const std::string& path);
void writeBrep(const TopoDS_Shape& shape, const std::string& path);

}  // namespace aeronc
