#include "FaceGraph.h"

#include "FaceProperties.h"

#include <aeronc/core/Error.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom2d_Curve.hxx>
#include <Geom_Surface.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <atomic>
#include <thread>

namespace aeronc::impeller {

namespace {

// Normals of faces meeting tangentially (a fillet and its supports) differ by the fillet's
// approximation only; sharp edges of an impeller are tens of degrees.
constexpr double kTangentAngle = 0.035;  // rad, 2 degrees

bool normalAt(const TopoDS_Face& f, const gp_Pnt2d& uv, gp_Vec& n) {
    BRepAdaptor_Surface s(f, false);
    gp_Pnt p;
    gp_Vec du, dv;
    s.D1(uv.X(), uv.Y(), p, du, dv);
    n = du.Crossed(dv);
    if (n.Magnitude() < 1e-12) return false;
    n.Normalize();
    if (f.Orientation() == TopAbs_REVERSED) n.Reverse();
    return true;
}

// Whether the two faces have the same normal at two points of their shared edge.
bool meetTangentially(const TopoDS_Edge& e, const TopoDS_Face& a, const TopoDS_Face& b) {
    double f0, l0, f1, l1;
    Handle(Geom2d_Curve) ca = BRep_Tool::CurveOnSurface(e, a, f0, l0);
    Handle(Geom2d_Curve) cb = BRep_Tool::CurveOnSurface(e, b, f1, l1);
    if (ca.IsNull() || cb.IsNull()) return false;
    int checked = 0;
    for (double t : {0.3, 0.5, 0.7}) {
        gp_Vec na, nb;
        if (!normalAt(a, ca->Value(f0 + t * (l0 - f0)), na) || !normalAt(b, cb->Value(f1 + t * (l1 - f1)), nb))
            continue;
        if (na.Angle(nb) > kTangentAngle) return false;
        ++checked;
    }
    return checked > 0;
}

}  // namespace

FaceGraph::FaceGraph(const TopoDS_Shape& shape) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    info_.resize(faces.Extent());
    neighbours_.resize(faces.Extent());
    for (int i = 1; i <= faces.Extent(); ++i) {
        info_[i - 1].face = TopoDS::Face(faces(i));
        info_[i - 1].type = BRepAdaptor_Surface(info_[i - 1].face, false).GetType();
    }
    // Area and centroid of each face are independent: two threads take the next face in turn
    // (the faces trimmed by the hub and the shroud cost OCCT's boundary integration).
    std::atomic<size_t> next{0};
    auto integrate = [this, &next] {
        for (size_t i; (i = next++) < info_.size();) {
            const AreaAndCentroid a = areaAndCentroid(info_[i].face);
            info_[i].area = a.area;
            info_[i].centroid = a.centroid;
        }
    };
    std::thread second(integrate);
    integrate();
    second.join();

    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    for (int e = 1; e <= edgeFaces.Extent(); ++e) {
        std::vector<int> ids;
        for (const auto& f : edgeFaces(e)) {
            const int id = faces.FindIndex(f);
            if (std::find(ids.begin(), ids.end(), id) == ids.end()) ids.push_back(id);
        }
        if (ids.size() != 2) continue;  // seam edges
        const TopoDS_Edge& edge = TopoDS::Edge(edgeFaces.FindKey(e));
        const bool t = meetTangentially(edge, info_[ids[0] - 1].face, info_[ids[1] - 1].face);
        for (int k = 0; k < 2; ++k) {
            auto& list = neighbours_[ids[k] - 1];
            const int other = ids[1 - k];
            auto it = std::find_if(list.begin(), list.end(), [&](const Neighbour& n) { return n.face == other; });
            if (it == list.end()) list.push_back({other, t});
            else it->tangent = it->tangent || t;
        }
    }
}

bool FaceGraph::tangent(int a, int b) const {
    for (const auto& n : neighbours(a))
        if (n.face == b) return n.tangent;
    return false;
}

bool FaceGraph::adjacent(int a, int b) const {
    for (const auto& n : neighbours(a))
        if (n.face == b) return true;
    return false;
}

gp_Dir FaceGraph::normalNear(int face, const gp_Pnt& p) const {
    const TopoDS_Face& f = (*this)[face].face;
    Handle(Geom_Surface) s = BRep_Tool::Surface(f);
    GeomAPI_ProjectPointOnSurf proj(p, s);
    if (proj.NbPoints() == 0) throw geometryError("impeller: cannot project onto face " + std::to_string(face));
    double u, v;
    proj.LowerDistanceParameters(u, v);
    gp_Vec n;
    if (!normalAt(f, gp_Pnt2d(u, v), n)) throw geometryError("impeller: no normal on face " + std::to_string(face));
    return gp_Dir(n);
}

}  // namespace aeronc::impeller
