#include "MeshSection.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Poly_PolygonOnTriangulation.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>

namespace aeronc::recognition {
namespace {

long long key(int a, int b) {
    if (a > b) std::swap(a, b);
    return static_cast<long long>(a) * 2147483647LL + b;
}

}  // namespace

MeshSection::MeshSection(const FaceCatalogue& faces, double chordTol)
    : faces_(faces),
      chordTol_(chordTol),
      meshes_(static_cast<std::size_t>(faces.size())),
      once_(new std::once_flag[static_cast<std::size_t>(faces.size())]) {}

const MeshSection::Mesh& MeshSection::mesh(int i) {
    auto& m = meshes_[static_cast<std::size_t>(i)];
    std::call_once(once_[static_cast<std::size_t>(i)], [&] {
        auto made = std::make_unique<Mesh>();
        build(i, *made);
        m = std::move(made);
    });
    return *m;
}

void MeshSection::build(int i, Mesh& m) const {
    // A copy, so that the part keeps no triangulation of ours.
    BRepBuilderAPI_Copy copy(faces_[i].face, true, false);
    const TopoDS_Face face = TopoDS::Face(copy.Shape());
    // The chord tolerance, eased on large faces to 1/500 of their size (at most 0.1 mm): a
    // region's outline needs no finer, and a fine mesh of a large torus costs more than the
    // section saves.
    const FaceInfo& f = faces_[i];
    const double size = std::sqrt(std::pow(f.boxMax[0] - f.boxMin[0], 2) + std::pow(f.boxMax[1] - f.boxMin[1], 2) +
                                  std::pow(f.boxMax[2] - f.boxMin[2], 2));
    const double deflection = std::clamp(0.002 * size, chordTol_, std::max(chordTol_, 0.1));
    BRepMesh_IncrementalMesh(face, deflection, false, 0.5, false);
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || tri->NbTriangles() == 0) return;
    const gp_Trsf t = loc.Transformation();
    m.nodes.resize(static_cast<std::size_t>(tri->NbNodes()));
    for (int k = 1; k <= tri->NbNodes(); ++k) m.nodes[static_cast<std::size_t>(k - 1)] = tri->Node(k).Transformed(t);
    m.triangles.reserve(static_cast<std::size_t>(tri->NbTriangles()));
    for (int k = 1; k <= tri->NbTriangles(); ++k) {
        int a, b, c;
        tri->Triangle(k).Get(a, b, c);
        m.triangles.push_back({a - 1, b - 1, c - 1});
    }
    for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
        const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
        if (BRep_Tool::Degenerated(e)) continue;
        const Handle(Poly_PolygonOnTriangulation) poly = BRep_Tool::PolygonOnTriangulation(e, tri, loc);
        if (poly.IsNull() || !poly->HasParameters()) continue;
        const int c = static_cast<int>(m.curves.size());
        m.curves.push_back(e);
        for (int k = 1; k < poly->NbNodes(); ++k) {
            int a = poly->Node(k) - 1, b = poly->Node(k + 1) - 1;
            double ta = poly->Parameter(k), tb = poly->Parameter(k + 1);
            if (a > b) std::swap(a, b), std::swap(ta, tb);
            m.boundary[key(a, b)] = {c, ta, tb};
        }
    }
    m.ok = true;
}

bool MeshSection::section(int i, const SetupFrame& frame, double h, std::vector<std::vector<P2>>& out) {
    const Mesh& m = mesh(i);
    if (!m.ok) return false;
    const Vec3& w = frame.w;
    // Heights relative to the plane; a node on it counts as above, so no triangle is cut
    // through a vertex and every crossing lies on one mesh edge.
    std::vector<double> d(m.nodes.size());
    for (std::size_t k = 0; k < m.nodes.size(); ++k) {
        const gp_Pnt& p = m.nodes[k];
        d[k] = p.X() * w[0] + p.Y() * w[1] + p.Z() * w[2] - h;
    }
    auto above = [&](int k) { return d[static_cast<std::size_t>(k)] >= 0; };
    // The crossing on mesh edge (a, b): on the exact edge curve for a boundary edge.
    std::unordered_map<long long, P2> point;
    std::vector<std::unique_ptr<BRepAdaptor_Curve>> adaptors(m.curves.size());
    auto crossing = [&](int a, int b) -> long long {
        const long long k = key(a, b);
        if (point.count(k)) return k;
        const auto it = m.boundary.find(k);
        const gp_Pnt& pa = m.nodes[static_cast<std::size_t>(a)];
        const gp_Pnt& pb = m.nodes[static_cast<std::size_t>(b)];
        const double da = d[static_cast<std::size_t>(a)], db = d[static_cast<std::size_t>(b)];
        gp_Pnt x = pa.XYZ() + (pb.XYZ() - pa.XYZ()) * (da / (da - db));
        if (it != m.boundary.end()) {
            // Bisection on the edge between the two nodes' parameters.
            auto& adaptor = adaptors[static_cast<std::size_t>(it->second.edge)];
            if (!adaptor) adaptor = std::make_unique<BRepAdaptor_Curve>(m.curves[static_cast<std::size_t>(it->second.edge)]);
            const BRepAdaptor_Curve& c = *adaptor;
            const int lo = std::min(a, b);
            double t0 = it->second.t0, t1 = it->second.t1;
            double f0 = d[static_cast<std::size_t>(lo)];
            for (int n = 0; n < 50 && std::fabs(t1 - t0) > 1e-12; ++n) {
                const double tm = 0.5 * (t0 + t1);
                const gp_Pnt q = c.Value(tm);
                const double fm = q.X() * w[0] + q.Y() * w[1] + q.Z() * w[2] - h;
                if ((fm >= 0) == (f0 >= 0)) t0 = tm, f0 = fm;
                else t1 = tm;
            }
            x = c.Value(0.5 * (t0 + t1));
        }
        point[k] = frame.project({x.X(), x.Y(), x.Z()});
        return k;
    };
    // Segments between crossing points, then joined into polylines through shared points.
    std::vector<std::pair<long long, long long>> segs;
    std::unordered_map<long long, std::vector<int>> at;
    for (const auto& tr : m.triangles) {
        long long ends[2];
        int n = 0;
        for (int e = 0; e < 3; ++e) {
            const int a = tr[static_cast<std::size_t>(e)], b = tr[static_cast<std::size_t>((e + 1) % 3)];
            if (above(a) != above(b)) ends[n++] = crossing(a, b);
        }
        if (n != 2) continue;
        const int s = static_cast<int>(segs.size());
        segs.push_back({ends[0], ends[1]});
        at[ends[0]].push_back(s);
        at[ends[1]].push_back(s);
    }
    std::vector<bool> used(segs.size(), false);
    auto walk = [&](int s, long long from) {
        std::vector<P2> pl{point[from]};
        long long cur = from;
        while (s >= 0 && !used[static_cast<std::size_t>(s)]) {
            used[static_cast<std::size_t>(s)] = true;
            const auto& sg = segs[static_cast<std::size_t>(s)];
            cur = sg.first == cur ? sg.second : sg.first;
            pl.push_back(point[cur]);
            int next = -1;
            for (int o : at[cur])
                if (!used[static_cast<std::size_t>(o)]) next = o;
            s = next;
        }
        if (pl.size() >= 2) out.push_back(std::move(pl));
    };
    for (auto& [k, list] : at)  // open pieces start at the boundary
        if (list.size() == 1 && !used[static_cast<std::size_t>(list[0])]) walk(list[0], k);
    for (std::size_t s = 0; s < segs.size(); ++s)  // closed ones anywhere
        if (!used[s]) walk(static_cast<int>(s), segs[s].first);
    return true;
}

}  // namespace aeronc::recognition
