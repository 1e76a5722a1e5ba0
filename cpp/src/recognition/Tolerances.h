#pragma once
// The recognition's tolerances in the forms its tests use.
#include <aeronc/recognition/Recogniser.h>

#include <cmath>

namespace aeronc::recognition {

struct Tolerances {
    explicit Tolerances(const RecogniseOptions& o)
        : linear(o.linearTolerance),
          parallelCos(std::cos(o.angularTolerance)),
          squareSin(std::sin(o.angularTolerance)),
          chord(o.chordTolerance) {}
    double linear;       // mm: heights equal, points coincide
    double parallelCos;  // directions are parallel when |cos| >= parallelCos
    double squareSin;    // and square when |cos| <= squareSin
    double chord;        // mm: sagitta when curves become polylines
};

}  // namespace aeronc::recognition
