#include <aeronc/core/Error.h>
#include <aeronc/brep/ShapeMesh.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace aeronc {

namespace {

// One face's triangulation in the part's frame, with each node's (u, v) on the face's surface.
struct FaceMesh {
    std::vector<gp_Pnt> points;
    std::vector<gp_Pnt2d> uv;
    std::vector<std::array<int, 3>> triangles;
};

// BRepMesh does not always hold its deflection: on milled_004's extruded B-spline wall (face 26)
// it leaves slivers 12 mm long across the curve whose middle lies 0.17 mm off the surface, on
// the pocket's side of a concave stretch; the dexels then put material where the part has none
// and the gate took exact toolpaths for gouges. Every edge inside the face whose middle lies
// further than `limit` from the surface at its (u, v) middle is split there, on the surface
// (a triangle with one, two or three split edges becomes two, three or four), until none does.
// The face's boundary edges are the B-rep edges' discretisation, shared with the neighbouring
// faces and within the deflection: they are never split, so the mesh stays closed.
void refineToSurface(FaceMesh& m, const BRepAdaptor_Surface& surface, double limit) {
    for (int round = 0; round < 12; ++round) {
        std::map<std::pair<int, int>, int> uses;  // interior edge (lower, higher node) -> triangles using it
        for (const auto& t : m.triangles)
            for (int k = 0; k < 3; ++k) ++uses[std::minmax(t[k], t[(k + 1) % 3])];
        std::map<std::pair<int, int>, int> split;  // edge -> the node at its middle
        for (const auto& [edge, n] : uses) {
            if (n != 2) continue;
            const gp_Pnt2d& a = m.uv[std::size_t(edge.first)];
            const gp_Pnt2d& b = m.uv[std::size_t(edge.second)];
            const gp_Pnt2d mid((a.X() + b.X()) / 2, (a.Y() + b.Y()) / 2);
            const gp_Pnt on = surface.Value(mid.X(), mid.Y());
            const gp_Pnt& pa = m.points[std::size_t(edge.first)];
            const gp_Pnt& pb = m.points[std::size_t(edge.second)];
            const gp_Pnt chord((pa.X() + pb.X()) / 2, (pa.Y() + pb.Y()) / 2, (pa.Z() + pb.Z()) / 2);
            // A sagitta larger than a quarter of the chord is no chord of a smooth surface: the
            // edge's (u, v) middle lies elsewhere (across a periodic surface's seam, at a pole).
            const double off = on.Distance(chord);
            if (off <= limit || off > 0.25 * pa.Distance(pb)) continue;
            split[edge] = int(m.points.size());
            m.points.push_back(on);
            m.uv.push_back(mid);
        }
        if (split.empty()) return;
        std::vector<std::array<int, 3>> out;
        out.reserve(m.triangles.size() + 3 * split.size());
        for (const auto& t : m.triangles) {
            int mids[3];
            int count = 0;
            for (int k = 0; k < 3; ++k) {
                const auto it = split.find(std::minmax(t[k], t[(k + 1) % 3]));
                mids[k] = it == split.end() ? -1 : it->second;
                count += mids[k] >= 0;
            }
            if (count == 0) {
                out.push_back(t);
                continue;
            }
            // Rotate so that the first edge (t0, t1) is split; the winding stays as it was.
            int r = 0;
            if (count == 1) r = mids[0] >= 0 ? 0 : mids[1] >= 0 ? 1 : 2;
            if (count == 2) r = mids[0] < 0 ? 1 : mids[1] < 0 ? 2 : 0;  // the unsplit edge last
            const int a = t[r], b = t[(r + 1) % 3], c = t[(r + 2) % 3];
            const int ab = mids[r], bc = mids[(r + 1) % 3], ca = mids[(r + 2) % 3];
            if (count == 1) {
                out.push_back({a, ab, c});
                out.push_back({ab, b, c});
            } else if (count == 2) {  // ab and bc split, ca not
                out.push_back({a, ab, c});
                out.push_back({ab, bc, c});
                out.push_back({ab, b, bc});
            } else {
                out.push_back({a, ab, ca});
                out.push_back({ab, b, bc});
                out.push_back({ca, bc, c});
                out.push_back({ab, bc, ca});
            }
        }
        m.triangles = std::move(out);
    }
}

}  // namespace

TriangleMesh meshShape(const TopoDS_Shape& shape, double deflection, double angularDeflection) {
    if (shape.IsNull()) throw inputError("no shape to mesh");
    if (!(deflection > 0) || !(angularDeflection > 0))
        throw inputError("the mesh deflections must be positive");
    BRepMesh_IncrementalMesh mesher(shape, deflection, false, angularDeflection, true);
    if (!mesher.IsDone()) throw geometryError("OCCT could not mesh the part");

    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    TriangleMesh mesh;
    for (int f = 1; f <= faces.Extent(); ++f) {
        const TopoDS_Face& face = TopoDS::Face(faces(f));
        TopLoc_Location loc;
        const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
        if (tri.IsNull() || tri->NbTriangles() == 0)
            throw geometryError("face " + std::to_string(f) + " of the part could not be meshed");
        const gp_Trsf trsf = loc.Transformation();
        FaceMesh fm;
        for (int k = 1; k <= tri->NbNodes(); ++k) {
            fm.points.push_back(tri->Node(k).Transformed(trsf));
            fm.uv.push_back(tri->HasUVNodes() ? tri->UVNode(k) : gp_Pnt2d());
        }
        for (int k = 1; k <= tri->NbTriangles(); ++k) {
            int a, b, c;
            tri->Triangle(k).Get(a, b, c);
            fm.triangles.push_back({a - 1, b - 1, c - 1});
        }
        // Twice the deflection: the mesher's own edges may pass it a little; what matters is
        // what lies well beyond it, and the gate's tolerance (0.01 mm) is five times 0.002.
        if (tri->HasUVNodes()) refineToSurface(fm, BRepAdaptor_Surface(face, false), 2 * deflection);
        const int base = int(mesh.vertices.size());
        for (const gp_Pnt& p : fm.points) mesh.addVertex(p.X(), p.Y(), p.Z());
        // A reversed face's triangles wind the other way round its outward normal.
        const bool reversed = face.Orientation() == TopAbs_REVERSED;
        for (auto [a, b, c] : fm.triangles) {
            if (reversed) std::swap(b, c);
            mesh.addTriangle(base + a, base + b, base + c, f);
        }
    }
    // A solid stored inside out still gives the right dexels once turned outward.
    if (signedVolume(mesh) < 0)
        for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
    return mesh;
}

}  // namespace aeronc
