#pragma once
// The rotational symmetry of a solid: the axis, the order N (a turn of 2π/N maps the part onto
// itself) and the faces that map onto one another under that turn. Tested with points sampled
// inside every face, so a face an exporter split at a seam, or merged with its neighbour, still
// finds its copies, and copies whose areas differ by an exporter's approximation still match.
#include "FaceGraph.h"

#include <gp_Ax1.hxx>

#include <vector>

namespace aeronc::impeller {

struct RotationalSymmetry {
    gp_Ax1 axis;
    int order = 0;                   // N; 0 when no axis gives a turn of 2π/N, N >= 3, onto the part
    // Orbits of faces (1-based face numbers): a face and the faces the turns take it to; a face of
    // revolution about the axis (the hub, the bore, the rim...) is an orbit of its own.
    std::vector<std::vector<int>> orbits;
    // Faces that the turn takes off the part (no copy a turn on): where blades differ.
    std::vector<int> unmatched;
};

// tol: how far a turned sample may lie from the part's boundary, mm. Faces of sliverArea or less
// (slivers an exporter leaves along intersections) do not decide the order.
RotationalSymmetry findRotationalSymmetry(const TopoDS_Shape& shape, const FaceGraph& g, double tol, double sliverArea = 0);

}  // namespace aeronc::impeller
