#include "FaceCatalogue.h"
#include "Workers.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <TopoDS_Wire.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Cone.hxx>
#include <gp_Trsf.hxx>
#include <TopLoc_Location.hxx>
#include <gp_Lin.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Pln.hxx>
#include <gp_Torus.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aeronc::recognition {
namespace {
Vec3 v3(const gp_XYZ& p) { return {p.X(), p.Y(), p.Z()}; }

std::shared_ptr<const RuledSpline> ruledSpline(const TopoDS_Face& face) {
    const Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face));
    if (b.IsNull()) return nullptr;
    auto r = std::make_shared<RuledSpline>();
    r->surface = b;
    if (b->VDegree() == 1 && b->NbVPoles() == 2) r->linearInV = true;
    else if (b->UDegree() == 1 && b->NbUPoles() == 2) r->linearInV = false;
    else return nullptr;
    const int n = r->linearInV ? b->NbUPoles() : b->NbVPoles();
    auto pole = [&](int i, int row) { return r->linearInV ? b->Pole(i, row) : b->Pole(row, i); };
    auto weight = [&](int i, int row) { return r->linearInV ? b->Weight(i, row) : b->Weight(row, i); };
    const gp_XYZ d0 = pole(1, 2).XYZ() - pole(1, 1).XYZ();
    bool extruded = d0.Modulus() > 1e-9;
    for (int i = 1; i <= n; ++i) {
        if (std::fabs(weight(i, 1) - weight(i, 2)) > 1e-12 * std::fabs(weight(i, 1))) return nullptr;
        const gp_XYZ d = pole(i, 2).XYZ() - pole(i, 1).XYZ();
        extruded = extruded && (d - d0).Modulus() <= 1e-9 * (1 + d0.Modulus());
    }
    if (extruded) r->extrusion = v3(d0 / d0.Modulus());
    return r;
}
}  // namespace

FaceCatalogue::FaceCatalogue(const TopoDS_Shape& solid) {
    TopExp::MapShapes(solid, TopAbs_FACE, map_);
    interior_.assign(static_cast<std::size_t>(map_.Extent()), {false, Vec3{0, 0, 0}});
    boundaries_.resize(static_cast<std::size_t>(map_.Extent()));
    wireIndex_.resize(static_cast<std::size_t>(map_.Extent()));
    faces_.resize(static_cast<std::size_t>(map_.Extent()));
    for (int i = 0; i < map_.Extent(); ++i) {
        FaceInfo& f = faces_[static_cast<std::size_t>(i)];
        f.face = TopoDS::Face(map_(i + 1));
        const bool reversed = f.face.Orientation() == TopAbs_REVERSED;
        BRepAdaptor_Surface s(f.face, false);
        switch (s.GetType()) {
            case GeomAbs_Plane: {
                f.kind = SurfaceKind::Plane;
                const gp_Ax3 pos = s.Plane().Position();
                gp_Dir n = pos.Direction();
                if (!pos.Direct()) n.Reverse();
                if (reversed) n.Reverse();
                f.normal = v3(n.XYZ());
                f.plane = s.Plane();
                f.planePoint = v3(pos.Location().XYZ());
                break;
            }
            case GeomAbs_Cylinder: {
                f.kind = SurfaceKind::Cylinder;
                const gp_Cylinder c = s.Cylinder();
                f.axisDir = v3(c.Axis().Direction().XYZ());
                f.axisPoint = v3(c.Axis().Location().XYZ());
                f.radius = c.Radius();
                // The natural normal of a direct cylinder points away from the axis.
                f.concave = (c.Position().Direct() == reversed);
                break;
            }
            case GeomAbs_Cone: {
                f.kind = SurfaceKind::Cone;
                const gp_Cone c = s.Cone();
                f.axisDir = v3(c.Axis().Direction().XYZ());
                f.axisPoint = v3(c.Axis().Location().XYZ());
                f.radius = c.RefRadius();
                f.semiAngle = c.SemiAngle();
                f.concave = (c.Position().Direct() == reversed);
                break;
            }
            case GeomAbs_Torus: {
                f.kind = SurfaceKind::Torus;
                const gp_Torus t = s.Torus();
                f.axisDir = v3(t.Axis().Direction().XYZ());
                f.axisPoint = v3(t.Axis().Location().XYZ());
                f.radius = t.MinorRadius();
                break;
            }
            case GeomAbs_Sphere:
                f.kind = SurfaceKind::Sphere;
                f.radius = s.Sphere().Radius();
                f.axisDir = v3(s.Sphere().Position().Direction().XYZ());
                f.axisPoint = v3(s.Sphere().Location().XYZ());  // the centre
                break;
            case GeomAbs_BSplineSurface:
                f.kind = SurfaceKind::Other;
                f.ruled = ruledSpline(f.face);
                break;
            default:
                f.kind = SurfaceKind::Other;
        }
        if (f.kind == SurfaceKind::Cylinder || f.kind == SurfaceKind::Torus || f.kind == SurfaceKind::Sphere || f.ruled)
            BRepTools::UVBounds(f.face, f.uMin, f.uMax, f.vMin, f.vMax);
        Bnd_Box box;
        BRepBndLib::Add(f.face, box, false);
        double x0, y0, z0, x1, y1, z1;
        box.Get(x0, y0, z0, x1, y1, z1);
        const double g = box.GetGap();
        f.boxMin = {x0 + g, y0 + g, z0 + g};
        f.boxMax = {x1 - g, y1 - g, z1 - g};
    }
    TopExp::MapShapes(solid, TopAbs_EDGE, edges_);
    faceEdges_.resize(faces_.size());
    for (std::size_t i = 0; i < faces_.size(); ++i)
        for (TopExp_Explorer ex(faces_[i].face, TopAbs_EDGE); ex.More(); ex.Next()) {
            const int e = edges_.FindIndex(ex.Current());
            if (e > 0 && std::find(faceEdges_[i].begin(), faceEdges_[i].end(), e) == faceEdges_[i].end())
                faceEdges_[i].push_back(e);
        }
    // Points along each edge: its ends, and 16 more along a curved one.
    std::vector<std::vector<Vec3>> alongEdge(static_cast<std::size_t>(edges_.Extent()) + 1);
    edgeShapes_.resize(static_cast<std::size_t>(edges_.Extent()) + 1);
    for (int e = 1; e <= edges_.Extent(); ++e) {
        const TopoDS_Edge& edge = TopoDS::Edge(edges_(e));
        EdgeShape& shape = edgeShapes_[static_cast<std::size_t>(e)];
        if (BRep_Tool::Degenerated(edge)) {
            // A pole or an apex: its vertex bounds the face.
            TopoDS_Vertex v0, v1;
            TopExp::Vertices(edge, v0, v1);
            if (!v0.IsNull()) shape.kind = EdgeShape::Line, shape.a = shape.b = BRep_Tool::Pnt(v0);
            continue;
        }
        BRepAdaptor_Curve c(edge);
        shape.t0 = c.FirstParameter(), shape.t1 = c.LastParameter();
        if (c.GetType() == GeomAbs_Line) {
            shape.kind = EdgeShape::Line, shape.a = c.Value(shape.t0), shape.b = c.Value(shape.t1);
        } else if (c.GetType() == GeomAbs_Circle) {
            shape.kind = EdgeShape::Arc, shape.circle = c.Circle();
        } else {
            shape.kind = EdgeShape::Other;
        }
        const int n = c.GetType() == GeomAbs_Line ? 1 : 16;
        for (int k = 0; k <= n; ++k) {
            const gp_Pnt p = c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * k / n);
            alongEdge[static_cast<std::size_t>(e)].push_back({p.X(), p.Y(), p.Z()});
        }
    }
    edgePoints_.resize(faces_.size());
    for (std::size_t i = 0; i < faces_.size(); ++i)
        for (int e : faceEdges_[i])
            edgePoints_[i].insert(edgePoints_[i].end(), alongEdge[static_cast<std::size_t>(e)].begin(),
                                  alongEdge[static_cast<std::size_t>(e)].end());
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndUniqueAncestors(solid, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    for (int e = 1; e <= edgeFaces.Extent(); ++e) {
        const TopTools_ListOfShape& fl = edgeFaces(e);
        std::vector<int> idx;
        for (const TopoDS_Shape& s : fl) idx.push_back(indexOf(s));
        for (int a : idx)
            for (int b : idx)
                if (a != b && a >= 0 && b >= 0) faces_[static_cast<std::size_t>(a)].neighbours.push_back(b);
    }
    for (FaceInfo& f : faces_) {
        std::sort(f.neighbours.begin(), f.neighbours.end());
        f.neighbours.erase(std::unique(f.neighbours.begin(), f.neighbours.end()), f.neighbours.end());
    }
}

double FaceCatalogue::boundaryTop(int i, const Vec3& d) const {
    double top = -std::numeric_limits<double>::max();
    for (const Vec3& p : edgePoints_[static_cast<std::size_t>(i)]) top = std::max(top, dot(p, d));
    if (edgePoints_[static_cast<std::size_t>(i)].empty()) {  // no edge: the box
        double lo;
        heightRange(i, d, lo, top);
    }
    return top;
}

double FaceCatalogue::area(int i) const {
    std::lock_guard<std::recursive_mutex> lock(cache_);
    const FaceInfo& f = faces_[static_cast<std::size_t>(i)];
    if (f.area < 0) {
        GProp_GProps props;
        BRepGProp::SurfaceProperties(f.face, props);
        f.area = props.Mass();
    }
    return f.area;
}

void FaceCatalogue::heightRange(int i, const Vec3& d, double& lo, double& hi) const {
    const FaceInfo& f = faces_[static_cast<std::size_t>(i)];
    lo = std::numeric_limits<double>::max();
    hi = -lo;
    for (int c = 0; c < 8; ++c) {
        const Vec3 p{(c & 1) ? f.boxMax[0] : f.boxMin[0], (c & 2) ? f.boxMax[1] : f.boxMin[1],
                     (c & 4) ? f.boxMax[2] : f.boxMin[2]};
        const double h = dot(p, d);
        lo = std::min(lo, h);
        hi = std::max(hi, h);
    }
}

std::vector<FaceCatalogue::HeightRange> FaceCatalogue::heightRanges(const Vec3& u, const Vec3& v, const Vec3& w) const {
    gp_Trsf t;
    t.SetValues(u[0], u[1], u[2], 0, v[0], v[1], v[2], 0, w[0], w[1], w[2], 0);
    const TopLoc_Location loc(t);
    std::vector<std::pair<double, double>> edge(static_cast<std::size_t>(edges_.Extent()) + 1);
    for (int e = 1; e <= edges_.Extent(); ++e) {
        const EdgeShape& shape = edgeShapes_[static_cast<std::size_t>(e)];
        if (shape.kind == EdgeShape::None) {
            edge[static_cast<std::size_t>(e)] = {0, -1};
            continue;
        }
        if (shape.kind == EdgeShape::Line) {
            const double ha = dot(v3(shape.a.XYZ()), w), hb = dot(v3(shape.b.XYZ()), w);
            edge[static_cast<std::size_t>(e)] = {std::min(ha, hb), std::max(ha, hb)};
            continue;
        }
        if (shape.kind == EdgeShape::Arc) {
            // h(t) = c + r (cos t X.w + sin t Y.w): the ends, and the extremes inside the range.
            const gp_Ax2& ax = shape.circle.Position();
            const double c = dot(v3(ax.Location().XYZ()), w), r = shape.circle.Radius();
            const double x = dot(v3(ax.XDirection().XYZ()), w), y = dot(v3(ax.YDirection().XYZ()), w);
            auto at = [&](double t) { return c + r * (std::cos(t) * x + std::sin(t) * y); };
            double lo = std::min(at(shape.t0), at(shape.t1)), hi = std::max(at(shape.t0), at(shape.t1));
            const double phi = std::atan2(y, x), amp = r * std::hypot(x, y);
            for (int k = -4; k <= 4; ++k) {
                const double t = phi + k * M_PI;
                if (t > shape.t0 && t < shape.t1) lo = std::min(lo, c + (k % 2 ? -amp : amp)), hi = std::max(hi, c + (k % 2 ? -amp : amp));
            }
            edge[static_cast<std::size_t>(e)] = {lo, hi};
            continue;
        }
        Bnd_Box b;
        BRepBndLib::Add(edges_(e).Moved(loc), b, false);
        if (b.IsVoid()) {
            edge[static_cast<std::size_t>(e)] = {0, -1};
            continue;
        }
        double x0, y0, z0, x1, y1, z1;
        b.Get(x0, y0, z0, x1, y1, z1);
        const double g = b.GetGap();
        edge[static_cast<std::size_t>(e)] = {z0 + g, z1 - g};
    }
    std::vector<HeightRange> out(faces_.size());
    for (std::size_t i = 0; i < faces_.size(); ++i) {
        double lo = std::numeric_limits<double>::max(), hi = -lo;
        for (int e : faceEdges_[i]) {
            const auto& r = edge[static_cast<std::size_t>(e)];
            if (r.second < r.first) continue;
            lo = std::min(lo, r.first), hi = std::max(hi, r.second);
        }
        if (lo > hi) heightRange(static_cast<int>(i), w, lo, hi);  // no usable edge (closed surface)
        // Edges that do not reach the top bound the face from below.
        double base = lo;
        const double tol = 1e-6 * (1 + std::fabs(hi));
        for (int e : faceEdges_[i]) {
            const auto& r = edge[static_cast<std::size_t>(e)];
            if (r.second >= r.first && r.second < hi - tol) base = std::max(base, r.second);
        }
        out[i] = {lo, hi, base};
    }
    return out;
}

Vec3 FaceCatalogue::interiorPoint(int i) const {
    std::lock_guard<std::recursive_mutex> lock(cache_);
    auto& cached = interior_[static_cast<std::size_t>(i)];
    if (cached.first) return cached.second;
    cached.first = true;
    cached.second = searchInterior(i);
    return cached.second;
}

BRepTopAdaptor_FClass2d& FaceCatalogue::classifier(int i) const {
    std::lock_guard<std::recursive_mutex> lock(cache_);
    const std::size_t w = static_cast<std::size_t>(workerSlot());
    if (classifiers_.size() <= w) classifiers_.resize(w + 1);
    auto& mine = classifiers_[w];
    if (mine.empty()) mine.resize(faces_.size());
    auto& c = mine[static_cast<std::size_t>(i)];
    if (!c) c = std::make_unique<BRepTopAdaptor_FClass2d>(faces_[static_cast<std::size_t>(i)].face, 1e-9);
    return *c;
}

IntCurvesFace_Intersector& FaceCatalogue::intersector(int i) const {
    std::lock_guard<std::recursive_mutex> lock(cache_);
    const std::size_t w = static_cast<std::size_t>(workerSlot());
    if (intersectors_.size() <= w) intersectors_.resize(w + 1);
    auto& mine = intersectors_[w];
    if (mine.empty()) mine.resize(faces_.size());
    auto& x = mine[static_cast<std::size_t>(i)];
    if (!x) x = std::make_unique<IntCurvesFace_Intersector>(faces_[static_cast<std::size_t>(i)].face, 1e-7);
    return *x;
}

bool FaceCatalogue::WirePolygon::contains(double u, double v) const {
    if (u < u0 || u > u1 || v < v0 || v > v1) return false;
    bool in = false;
    for (std::size_t a = 0, b = pts.size() - 1; a < pts.size(); b = a++) {
        const auto& p = pts[a];
        const auto& q = pts[b];
        if ((p.second > v) != (q.second > v) && u < (q.first - p.first) * (v - p.second) / (q.second - p.second) + p.first)
            in = !in;
    }
    return in;
}

TopAbs_State FaceCatalogue::classifyUV(int i, double u, double v) const {
    const TopoDS_Face& face = faces_[static_cast<std::size_t>(i)].face;
    if (faceEdges_[static_cast<std::size_t>(i)].size() <= 64) return classifier(i).Perform(gp_Pnt2d(u, v));
    std::unique_lock<std::recursive_mutex> lock(cache_);
    auto& idx = wireIndex_[static_cast<std::size_t>(i)];
    if (!idx) {
        idx = std::make_unique<std::vector<WirePolygon>>();
        const TopoDS_Wire outer = BRepTools::OuterWire(face);
        std::vector<TopoDS_Wire> wires{outer};
        for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next())
            if (!w.Current().IsSame(outer)) wires.push_back(TopoDS::Wire(w.Current()));
        for (const TopoDS_Wire& w : wires) {
            WirePolygon poly;
            for (BRepTools_WireExplorer ex(w, face); ex.More(); ex.Next()) {
                double f, l;
                Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(ex.Current(), face, f, l);
                if (pc.IsNull()) continue;
                const int n = Geom2dAdaptor_Curve(pc).GetType() == GeomAbs_Line ? 1 : 24;
                const bool rev = ex.Current().Orientation() == TopAbs_REVERSED;
                for (int k = 0; k < n; ++k) {
                    const double t = rev ? l - (l - f) * k / n : f + (l - f) * k / n;
                    const gp_Pnt2d q = pc->Value(t);
                    poly.pts.push_back({q.X(), q.Y()});
                }
            }
            if (poly.pts.size() < 3) continue;
            poly.u0 = poly.u1 = poly.pts[0].first, poly.v0 = poly.v1 = poly.pts[0].second;
            for (const auto& q : poly.pts) {
                poly.u0 = std::min(poly.u0, q.first), poly.u1 = std::max(poly.u1, q.first);
                poly.v0 = std::min(poly.v0, q.second), poly.v1 = std::max(poly.v1, q.second);
            }
            idx->push_back(std::move(poly));
        }
    }
    lock.unlock();  // built once, then only read
    if (idx->empty() || !(*idx)[0].contains(u, v)) return TopAbs_OUT;
    for (std::size_t k = 1; k < idx->size(); ++k)
        if ((*idx)[k].contains(u, v)) return TopAbs_OUT;
    return TopAbs_IN;
}

const std::vector<Handle(Geom2d_TrimmedCurve)>& FaceCatalogue::boundaryUV(int i) const {
    std::lock_guard<std::recursive_mutex> lock(cache_);
    auto& b = boundaries_[static_cast<std::size_t>(i)];
    if (!b) {
        b = std::make_unique<std::vector<Handle(Geom2d_TrimmedCurve)>>();
        const TopoDS_Face& face = faces_[static_cast<std::size_t>(i)].face;
        for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
            double f, l;
            Handle(Geom2d_Curve) pc = BRep_Tool::CurveOnSurface(TopoDS::Edge(ex.Current()), face, f, l);
            b->push_back(pc.IsNull() ? Handle(Geom2d_TrimmedCurve)() : new Geom2d_TrimmedCurve(pc, f, l));
        }
    }
    return *b;
}

Vec3 FaceCatalogue::searchInterior(int i) const {
    const TopoDS_Face& face = faces_[static_cast<std::size_t>(i)].face;
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    BRepTopAdaptor_FClass2d& cls = classifier(i);
    BRepAdaptor_Surface s(face, true);
    // Search a refining grid; the centre first, which is inside for most faces.
    for (int n = 1; n <= 65; n = n * 2 + 1) {
        for (int a = 0; a < n; ++a)
            for (int b = 0; b < n; ++b) {
                const double u = u0 + (u1 - u0) * (a + 0.5) / n;
                const double v = v0 + (v1 - v0) * (b + 0.5) / n;
                if (cls.Perform(gp_Pnt2d(u, v)) == TopAbs_IN) return v3(s.Value(u, v).XYZ());
            }
    }
    const gp_Pnt p = s.Value(0.5 * (u0 + u1), 0.5 * (v0 + v1));
    return v3(p.XYZ());
}

}  // namespace aeronc::recognition
