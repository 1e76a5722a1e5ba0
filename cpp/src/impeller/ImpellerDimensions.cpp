// Dimension analysis (impeller paper §2): bore, channel width, root fillet radius, blade height.
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/FaceSampling.h>

#include <aeronc/core/Error.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepTools.hxx>
#include <GProp_GProps.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_IntCS.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_Line.hxx>
#include <Geom_Surface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Lin.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

namespace aeronc::impeller {

namespace {

struct Frame {
    gp_Pnt point;
    gp_Dir dir;
    double axial(const gp_Pnt& p) const { return gp_Vec(point, p).Dot(gp_Vec(dir)); }
    double radius(const gp_Pnt& p) const { return gp_Lin(point, dir).Distance(p); }
};

// Points along every edge of `s` (ends included), for extents about the axis.
std::vector<gp_Pnt> edgePoints(const TopoDS_Shape& s, int perEdge = 24) {
    std::vector<gp_Pnt> pts;
    for (TopExp_Explorer ex(s, TopAbs_EDGE); ex.More(); ex.Next()) {
        const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
        if (BRep_Tool::Degenerated(e)) continue;
        BRepAdaptor_Curve c(e);
        for (int i = 0; i <= perEdge; ++i)
            pts.push_back(c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * i / perEdge));
    }
    return pts;
}

TopoDS_Compound compound(const TopTools_IndexedMapOfShape& faces, const std::vector<int>& ids) {
    TopoDS_Compound c;
    BRep_Builder b;
    b.MakeCompound(c);
    for (int id : ids) b.Add(c, faces(id));
    return c;
}

double distance(const TopoDS_Shape& a, const TopoDS_Shape& b, gp_Pnt* onA = nullptr) {
    BRepExtrema_DistShapeShape d(a, b);
    if (!d.IsDone() || d.NbSolution() == 0) throw geometryError("impeller: channel width: distance failed");
    if (onA) *onA = d.PointOnShape1(1);
    return d.Value();
}

// The channel from blade a to the next, b, station by station along the radius: the depth is
// the axial extent of a's walls in the station's band (its walls run from the hub, or the
// fillets, to the tip), the width the least distance from a point of a's walls to b's walls
// (the leading edge's round may come nearer than the pressure side). `exactAt` (a point of a's walls where the exact narrowest gap
// is) gets the depth of its station.
constexpr int kStations = 40;
std::vector<ChannelStation> channelStations(const TopTools_IndexedMapOfShape& faces, const Blade& a, const Blade& b,
                                            const Frame& axis, const gp_Pnt& exactAt, double& exactDepth) {
    struct Sample {
        gp_Pnt p;
        double r, z;
    };
    std::vector<Sample> samples;
    double rLo = 1e300, rHi = -1e300;
    // Inside the walls, and along their edges (the narrowest gap is often at a wall's top, root
    // or end).
    for (int id : a.walls) {
        auto pts = pointsInsideFace(TopoDS::Face(faces(id)), 60, 12);
        const auto rim = edgePoints(faces(id), 60);
        pts.insert(pts.end(), rim.begin(), rim.end());
        for (const auto& p : pts) {
            samples.push_back({p, axis.radius(p), axis.axial(p)});
            rLo = std::min(rLo, samples.back().r), rHi = std::max(rHi, samples.back().r);
        }
    }
    if (samples.empty() || rHi <= rLo) return {};
    auto band = [&](double r) { return std::clamp(static_cast<int>((r - rLo) / (rHi - rLo) * kStations), 0, kStations - 1); };
    std::vector<double> zLo(kStations, 1e300), zHi(kStations, -1e300), width(kStations, 1e300);
    for (const auto& s : samples) {
        const int k = band(s.r);
        zLo[k] = std::min(zLo[k], s.z), zHi[k] = std::max(zHi[k], s.z);
    }
    const TopoDS_Compound walls = compound(faces, b.walls);
    for (const auto& s : samples) {
        const int k = band(s.r);
        width[k] = std::min(width[k], distance(BRepBuilderAPI_MakeVertex(s.p).Vertex(), walls));
    }
    std::vector<ChannelStation> out;
    for (int k = 0; k < kStations; ++k)
        if (width[k] < 1e300)
            out.push_back({rLo + (k + 0.5) * (rHi - rLo) / kStations, std::max(0.0, zHi[k] - zLo[k]), width[k]});
    const int e = band(axis.radius(exactAt));
    exactDepth = zHi[e] >= zLo[e] ? zHi[e] - zLo[e] : 0;
    return out;
}

double circumradius(const gp_Pnt& a, const gp_Pnt& b, const gp_Pnt& c) {
    const double ab = a.Distance(b), bc = b.Distance(c), ca = c.Distance(a);
    const double twiceArea = gp_Vec(a, b).Crossed(gp_Vec(a, c)).Magnitude();
    return twiceArea < 1e-12 ? 0 : ab * bc * ca / (2 * twiceArea);
}

// A rolling-ball fillet's cross sections are circular arcs of its radius, and they are the
// iso-curves of its surface in the direction across the fillet (the shorter one). The radius is
// the median circumradius of three points on several such iso-curves.
double filletRadius(const TopoDS_Face& f) {
    double u0, u1, v0, v1;
    BRepTools::UVBounds(f, u0, u1, v0, v1);
    BRepAdaptor_Surface s(f);
    std::vector<double> alongU, alongV;  // radii of iso-curves u = const (varying v), and v = const
    double chordU = 0, chordV = 0;
    for (double t : {0.3, 0.4, 0.5, 0.6, 0.7}) {
        const double u = u0 + t * (u1 - u0), v = v0 + t * (v1 - v0);
        const gp_Pnt a = s.Value(u, v0), b = s.Value(u, 0.5 * (v0 + v1)), c = s.Value(u, v1);
        alongU.push_back(circumradius(a, b, c));
        chordU += a.Distance(c);
        const gp_Pnt d = s.Value(u0, v), e = s.Value(0.5 * (u0 + u1), v), h = s.Value(u1, v);
        alongV.push_back(circumradius(d, e, h));
        chordV += d.Distance(h);
    }
    auto& r = chordU < chordV ? alongU : alongV;
    std::sort(r.begin(), r.end());
    return r[r.size() / 2];
}

// Height of the shroud face above the hub along the axis, through the shroud's centroid.
double heightAboveHub(const TopoDS_Face& shroud, const gp_Pnt& centroid, const TopoDS_Face& hub, const gp_Dir& dir) {
    GeomAPI_ProjectPointOnSurf onShroud(centroid, BRep_Tool::Surface(shroud));
    if (onShroud.NbPoints() == 0) throw geometryError("impeller: blade height: no point on the shroud");
    const gp_Pnt p = onShroud.NearestPoint();
    Handle(Geom_Line) line = new Geom_Line(p, dir);
    GeomAPI_IntCS hit(line, BRep_Tool::Surface(hub));
    double best = 1e300;
    if (hit.IsDone())
        for (int i = 1; i <= hit.NbPoints(); ++i) {
            const double t = gp_Vec(p, hit.Point(i)).Dot(gp_Vec(dir));
            if (t < 0 && -t < best) best = -t;
        }
    if (best == 1e300) throw geometryError("impeller: blade height: the hub is not below the shroud");
    return best;
}

}  // namespace

double ImpellerDimensions::channelWidth(double depth) const {
    if (channelProfile.empty()) return minChannelWidth;
    double deepest = minChannelDepth;
    for (const auto& s : channelProfile) deepest = std::max(deepest, s.depth);
    const double h = std::min(depth, deepest);
    if (minChannelDepth >= h - 1e-9) return minChannelWidth;  // the exact narrowest gap is deep enough
    double w = 1e300;
    for (const auto& s : channelProfile)
        if (s.depth >= h - 1e-9) w = std::min(w, s.width);
    return std::max(w, minChannelWidth);
}

ImpellerDimensions measureImpeller(const TopoDS_Shape& shape, const ImpellerFeatures& ft) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(shape, TopAbs_FACE, faces);
    if (faces.Extent() != ft.faceCount || ft.blades.size() < 2 || ft.hub < 1 || ft.hub > faces.Extent())
        throw inputError("measureImpeller: the features do not belong to this shape");
    const Frame axis{gp_Pnt(ft.axisPoint[0], ft.axisPoint[1], ft.axisPoint[2]),
                     gp_Dir(ft.axisDirection[0], ft.axisDirection[1], ft.axisDirection[2])};
    ImpellerDimensions d;

    if (ft.bore) {
        BRepAdaptor_Surface s(TopoDS::Face(faces(ft.bore)));
        d.boreDiameter = 2 * s.Cylinder().Radius();
        double lo = 1e300, hi = -1e300;
        for (const auto& p : edgePoints(faces(ft.bore))) lo = std::min(lo, axis.axial(p)), hi = std::max(hi, axis.axial(p));
        d.boreDepth = hi - lo;
    }
    double lo = 1e300, hi = -1e300;
    for (const auto& p : edgePoints(shape, 8)) {
        d.outerRadius = std::max(d.outerRadius, axis.radius(p));
        lo = std::min(lo, axis.axial(p)), hi = std::max(hi, axis.axial(p));
    }
    d.axialLength = hi - lo;

    // Channels: blade 0 to 1 and 1 to 2 cover both kinds (main to splitter, splitter to main).
    const int n = static_cast<int>(ft.blades.size());
    d.minChannelWidth = 1e300;
    for (int i = 0; i < std::min(n, 2); ++i) {
        const int j = (i + 1) % n;
        gp_Pnt at;
        const double w = distance(compound(faces, ft.blades[i].walls), compound(faces, ft.blades[j].walls), &at);
        double depth = 0;
        // Without splitters both pairs are the same kind of channel: one profile is enough.
        if (i == 0 || ft.splitterCount > 0) {
            const auto stations = channelStations(faces, ft.blades[i], ft.blades[j], axis, at, depth);
            d.channelProfile.insert(d.channelProfile.end(), stations.begin(), stations.end());
        } else {
            depth = d.minChannelDepth;
        }
        if (w < d.minChannelWidth)
            d.minChannelWidth = w, d.minChannelDepth = depth, d.channelBlades[0] = i, d.channelBlades[1] = j;
    }

    // Root fillet: the largest fillet face of the first blade (along a side wall, where the
    // blade's own curvature is smallest).
    const auto& fl = ft.blades[0].fillets;
    if (!fl.empty()) {
        int largest = fl.front();
        double area = -1;
        for (int f : fl) {
            BRepAdaptor_Surface s(TopoDS::Face(faces(f)));
            double u0, u1, v0, v1;
            BRepTools::UVBounds(TopoDS::Face(faces(f)), u0, u1, v0, v1);
            const double size = s.Value(u0, v0).Distance(s.Value(u1, v1));
            if (size > area) area = size, largest = f;
        }
        d.filletRadius = filletRadius(TopoDS::Face(faces(largest)));
    }

    auto height = [&](const Blade& b) {
        const TopoDS_Face& sf = TopoDS::Face(faces(b.shroud));
        GProp_GProps g;
        BRepGProp::SurfaceProperties(sf, g);
        return heightAboveHub(sf, g.CentreOfMass(), TopoDS::Face(faces(ft.hub)), axis.dir);
    };
    for (const auto& b : ft.blades) {
        if (!b.splitter && d.bladeHeight == 0) d.bladeHeight = height(b);
        if (b.splitter && d.splitterHeight == 0) d.splitterHeight = height(b);
    }
    return d;
}

}  // namespace aeronc::impeller
