#pragma once
// A part exported as several bodies (an impeller's hub and each blade a body of its own) made
// one solid for recognition: the bodies fused to the largest one, one at a time.
#include <TopoDS_Shape.hxx>
#include <string>

namespace aeronc::impeller {

struct FusedBodies {
    TopoDS_Shape solid;
    int bodies = 0;          // solids in the input
    int fused = 0;           // of those, fused into the result (the largest included)
    int dropped = 0;         // degenerate bodies left out (no volume to speak of)
    double fuzzyValue = 0;   // the largest fuzzy value a step needed, mm
    std::string summary;     // one line for the user
};

// The number of solids in the shape.
int solidCount(const TopoDS_Shape& shape);

// Fuses the solids of `shape` into one valid solid. Bodies of less than 1e-4 of the largest's
// volume (slivers an exporter leaves) are dropped. Each body is fused to the growing solid alone,
// with a fuzzy value of 1e-3 mm, else 1e-2 mm (exported bodies overlap or touch to their
// export tolerance), and the step is kept only when it leaves one solid that OCCT's checker
// accepts, once faces of one surface are merged again. Throws aeronc::inputError when the shape holds
// no solid or a body does not touch the others, geometryError when a step fails at every value.
FusedBodies fuseBodies(const TopoDS_Shape& shape);

}  // namespace aeronc::impeller
