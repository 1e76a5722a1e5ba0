#pragma once
// Arcs, circles and helices written as feed moves within the chord tolerance.
#include "MoveWriter.h"

namespace aeronc::toolpath {

// Segments for `angle` radians of an arc of `radius` within `chordTolerance` (at least 1).
// Throws aeronc::inputError beyond 10^6 segments.
std::size_t arcSegments(double radius, double angle, double chordTolerance);

// Arc length over chord length of the segments arcSegments() gives at most: a descent spread
// over an arc by its length is this much steeper along the chords.
double chordFactor(double radius, double chordTolerance);

// From the tool's position, on the circle (centre, radius) at angle a0, round by `angle`
// radians (positive: counter-clockwise) while h falls linearly from the tool's h to hEnd.
// Returns the end angle.
double helixMoves(MoveWriter& w, const Point& centre, double radius, double a0, double angle, double hEnd,
                  double chordTolerance);

Point onCircle(const Point& centre, double radius, double angle);

}  // namespace aeronc::toolpath
