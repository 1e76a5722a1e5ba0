#pragma once
#include <TopoDS_Shape.hxx>
#include <string>

namespace aeronc {

// Reads a STEP or BREP file (format from its content, not its name) and returns the
// one solid it holds. Throws aeronc::Error with a message a user can act on for: a
// missing or empty file, an unknown format, no solid or several, an open shell, and
// a B-rep that fails OCCT's checker.
TopoDS_Shape loadPart(const std::string& path);

// Same checks for a shape passed as BREP text (FreeCAD's Shape.exportBrepToString()).
TopoDS_Shape partFromBrepText(const std::string& text);

// Same checks for a shape already in memory.
TopoDS_Shape validatedSolid(const TopoDS_Shape& shape, const std::string& origin);

void writeStep(const TopoDS_Shape& shape, const std::string& path);
void writeBrep(const TopoDS_Shape& shape, const std::string& path);

}  // namespace aeronc
