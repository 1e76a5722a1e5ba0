#pragma once
// Section of the faces the fast section does not handle (blends, splines, tori, cylinders
// across the axis) by their triangulation: each face is meshed once per part to the chord
// tolerance, and a plane cuts its triangles. Where the plane crosses the face's boundary the
// point is put on the exact edge, so the pieces join their neighbours' exact sections.
// OCCT's general section, which this replaces, cost 10 to 50 ms per face and level.
#include <aeronc/recognition/SetupFrame.h>

#include "FaceCatalogue.h"

#include <TopoDS_Edge.hxx>
#include <gp_Pnt.hxx>

#include <array>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace aeronc::recognition {

class MeshSection {
public:
    MeshSection(const FaceCatalogue& faces, double chordTol);
    // Appends the section polylines of face i with the plane at height h along frame.w;
    // false when the face could not be meshed (the caller then uses OCCT's section). A face is
    // meshed when it is first cut; threads may cut faces at once.
    bool section(int i, const SetupFrame& frame, double h, std::vector<std::vector<P2>>& out);

private:
    struct BoundarySpan {
        int edge;        // index into Mesh::curves
        double t0, t1;   // the edge's parameters at the mesh edge's two nodes (lower node first)
    };
    struct Mesh {
        bool ok = false;
        std::vector<gp_Pnt> nodes;
        std::vector<std::array<int, 3>> triangles;
        std::vector<TopoDS_Edge> curves;  // an adaptor keeps a cache: each section makes its own
        std::unordered_map<long long, BoundarySpan> boundary;  // by mesh edge (lower node, upper node)
    };
    const Mesh& mesh(int i);
    void build(int i, Mesh& m) const;

    const FaceCatalogue& faces_;
    double chordTol_;
    std::vector<std::unique_ptr<Mesh>> meshes_;
    std::unique_ptr<std::once_flag[]> once_;  // per face: its mesh is built once
};

}  // namespace aeronc::recognition
