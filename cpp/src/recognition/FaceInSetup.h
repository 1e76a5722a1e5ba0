#pragma once
// How each face of the part stands relative to one setup direction.
#include <aeronc/recognition/SetupFrame.h>

#include "FaceCatalogue.h"
#include "Tolerances.h"

#include <vector>

namespace aeronc::recognition {

enum class Attitude { Up, Down, Vertical, Inclined, Curved };

struct FaceInSetup {
    Attitude att = Attitude::Curved;
    double lo = 0, hi = 0;  // height range
    double base = 0;        // top of its lower boundary (see FaceCatalogue::HeightRange)
    double h = 0;           // planes normal to the axis: their height
};

// One entry per face of the catalogue, in its order. Planes are up, down, vertical or
// inclined; cylinders about the axis are vertical; every other face is curved.
std::vector<FaceInSetup> classifyFaces(const FaceCatalogue& faces, const SetupFrame& frame, const Tolerances& tol);

}  // namespace aeronc::recognition
