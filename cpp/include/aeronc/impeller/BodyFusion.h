#pragma once
// A part exported as several bodies (an impeller's hub and each blade a body of its own) made
// one solid for recognition: the bodies fused to the largest one in one Boolean.
#include <TopoDS_Shape.hxx>
#include <string>

namespace aeronc::impeller {

struct FusedBodies {
    TopoDS_Shape solid;
    int bodies = 0;          // solids in the input
    int fused = 0;           // of those, fused into the result (the largest included)
    int dropped = 0;         // degenerate bodies left out (no volume to speak of)
    double fuzzyValue = 0;   // the fuzzy value the fuse needed, mm
    int facesFixed = 0;      // faces of the fuse OCCT's checker refused, fixed
    double seconds = 0;      // the time it took
    std::string summary;     // one line for the user
};

// The number of solids in the shape.
int solidCount(const TopoDS_Shape& shape);

// Fuses the solids of `shape` into one valid solid. Bodies of less than 1e-4 of the largest's
// volume (slivers an exporter leaves) are dropped. The others are fused to the largest in one
// Boolean, with a fuzzy value of 0, else 1e-3 mm, else 1e-2 mm (exported bodies overlap, or touch
// to their export tolerance); faces OCCT's checker refuses are fixed (ShapeFix_Face), and the
// faces the fuse split on one surface merged again (FaceMerging.h). The fuse stops at its next
// check once `timeLimit` seconds have passed. Throws aeronc::inputError when the shape holds no
// solid or bodies do not touch the largest (naming them), geometryError when no fuzzy value
// gives one valid solid, or the time limit is reached.
FusedBodies fuseBodies(const TopoDS_Shape& shape, double timeLimit = 300);

}  // namespace aeronc::impeller
