// Centrifugal-impeller test-part generator.
//
// Construction (mm, axis +Z):
//   * Body of revolution: the profile back face (z = 0, bore to rim), rim cylinder (r = outer,
//     up to rimHeight), hub arc, nose top plane (z = noseHeight, nose to bore), bore cylinder.
//     The hub arc runs from (noseRadius, noseHeight) to (outerRadius, rimHeight) on the circle
//     centred at (outerRadius, zc) through both, so it meets the rim radially and is concave.
//   * Blade k: a camber line θ(r) = θk + wrap·s², s = (r − leading)/(trailing − leading), offset
//     by ±thickness/2 (pressure side +θ, suction side −θ) and closed by half circles at both
//     ends, so the root loop is tangent-continuous (a robust fillet chain). The section is placed
//     below the hub and, turned by the lean angle, above the shroud; the blade is the ruled
//     solid between the two (OCCT ThruSections, ruled), clipped by the solid of revolution under
//     the shroud (the hub profile raised by bladeHeight). Splitters use the same camber turned by
//     half a pitch, from splitterStart of the span.
//   * The blades are fused to the body in one Boolean, and every edge where a blade meets the
//     hub gets the root fillet.
// A face of revolution has a seam meridian; a blade crossing it would have its root edge split
// and so one fillet face more than its copies. The body is therefore revolved from the meridian
// with the widest clearance to every blade footprint, and a spec whose blades leave none is
// refused.
// The wider families: a hub meridian interpolated by a B-spline (the hub one revolved B-spline
// face), the hub's seam under blade 0 (its root edges and fillets split there, as a revolved hub
// fused with blades comes from other CAD systems), straight radial blades (wrap 0: side walls
// ruled between straight lines, planes without lean) and an open pump impeller (a flat back plate
// from the bore to the rim whose top plane is the hub, no nose, a flat blade tip).
// The truth follows every face through the operations' histories; the minimum channel width is
// OCCT's distance between the wall faces of two adjacent blades of the finished part.
#include <aeronc/testparts/ImpellerGenerator.h>

#include <aeronc/core/Error.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeShape.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRep_Builder.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <TopLoc_Location.hxx>
#include <gp_Ax1.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <memory>
#include <cmath>
#include <string>
#include <vector>

namespace aeronc::testparts {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;
constexpr int kCamberSamples = 25;

[[noreturn]] void fail(const std::string& what) { throw inputError("makeImpeller: " + what); }
[[noreturn]] void broken(const std::string& what) { throw geometryError("makeImpeller: " + what); }

// The hub profile: the arc through (r1, zTop) and (R2, rimZ) centred at (R2, zc).
struct HubProfile {
    double r1, zTop, r2, rimZ, zc, rho;
    HubProfile(double r1_, double zTop_, double r2_, double rimZ_) : r1(r1_), zTop(zTop_), r2(r2_), rimZ(rimZ_) {
        zc = ((r2 - r1) * (r2 - r1) + zTop * zTop - rimZ * rimZ) / (2 * (zTop - rimZ));
        rho = zc - rimZ;
    }
    double z(double r) const { return zc - std::sqrt(rho * rho - (r - r2) * (r - r2)); }
    // The arc raised by dz, as an edge in the XZ plane; with `spline`, a B-spline interpolating
    // it (within 1e-7 mm).
    TopoDS_Edge edge(double dz, bool spline = false) const {
        const double rm = 0.5 * (r1 + r2);
        if (spline) {
            constexpr int kPoints = 61;
            Handle(TColgp_HArray1OfPnt) pts = new TColgp_HArray1OfPnt(1, kPoints);
            for (int i = 0; i < kPoints; ++i) {
                const double r = r2 + (r1 - r2) * i / (kPoints - 1);
                pts->SetValue(i + 1, gp_Pnt(r, 0, z(r) + dz));
            }
            GeomAPI_Interpolate in(pts, false, 1e-9);
            in.Perform();
            if (!in.IsDone()) throw geometryError("makeImpeller: hub meridian spline");
            return BRepBuilderAPI_MakeEdge(in.Curve());
        }
        Handle(Geom_TrimmedCurve) arc = GC_MakeArcOfCircle(gp_Pnt(r2, 0, rimZ + dz), gp_Pnt(rm, 0, z(rm) + dz),
                                                           gp_Pnt(r1, 0, zTop + dz))
                                            .Value();
        return BRepBuilderAPI_MakeEdge(arc);
    }
};

TopoDS_Edge line(const gp_Pnt& a, const gp_Pnt& b) { return BRepBuilderAPI_MakeEdge(a, b); }

// The wire through `edges`, which are replaced by the wire's own edges (MakeWire may copy an
// edge to share a vertex with its neighbour), so that histories can follow them.
TopoDS_Wire wireOf(std::vector<TopoDS_Edge*> edges) {
    BRepBuilderAPI_MakeWire mw;
    for (const auto* e : edges) mw.Add(*e);
    if (!mw.IsDone()) broken("wire");
    const TopoDS_Wire w = mw.Wire();
    for (auto* e : edges) {
        BRepAdaptor_Curve c(*e);
        const gp_Pnt mid = c.Value(0.5 * (c.FirstParameter() + c.LastParameter()));
        bool found = false;
        for (TopExp_Explorer ex(w, TopAbs_EDGE); ex.More() && !found; ex.Next()) {
            BRepAdaptor_Curve o(TopoDS::Edge(ex.Current()));
            if (o.Value(0.5 * (o.FirstParameter() + o.LastParameter())).Distance(mid) < 1e-7) {
                *e = TopoDS::Edge(ex.Current());
                found = true;
            }
        }
        if (!found) broken("wire edge");
    }
    return w;
}

// The images of `s` in an operation's result: none when deleted, itself when untouched.
std::vector<TopoDS_Shape> images(BRepBuilderAPI_MakeShape& op, const TopoDS_Shape& s) {
    std::vector<TopoDS_Shape> out;
    if (op.IsDeleted(s)) return out;
    const TopTools_ListOfShape& mod = op.Modified(s);
    if (mod.IsEmpty()) {
        out.push_back(s);
    } else {
        for (const auto& m : mod) out.push_back(m);
    }
    return out;
}

TopoDS_Shape image(BRepBuilderAPI_MakeShape& op, const TopoDS_Shape& s, const std::string& what) {
    auto im = images(op, s);
    if (im.size() != 1) broken(what + " became " + std::to_string(im.size()) + " faces");
    return im.front();
}

// One blade's section in the plane z = 0 and its camber geometry.
struct BladeSection {
    TopoDS_Wire wire;
    TopoDS_Edge pressure, trailing, suction, leading;
};

struct Camber {
    double rle, rte, theta0, wrap;  // start/end radius of the main camber, angle, turn
    double s(double r) const { return (r - rle) / (rte - rle); }
    double theta(double r) const { return theta0 + wrap * s(r) * s(r); }
    gp_Pnt point(double r) const { return gp_Pnt(r * std::cos(theta(r)), r * std::sin(theta(r)), 0); }
    gp_Vec tangent(double r) const {
        const double t = theta(r), dt = 2 * wrap * s(r) / (rte - rle);
        gp_Vec v(std::cos(t) - r * std::sin(t) * dt, std::sin(t) + r * std::cos(t) * dt, 0);
        return v.Normalized();
    }
};

// Section of a blade whose camber runs from r0 to r1 along `c`, thickness t.
BladeSection section(const Camber& c, double r0, double r1, double t) {
    const double h = t / 2;
    auto side = [&](double sign) {
        if (c.wrap == 0) {  // a straight radial blade: its sides are straight lines
            const gp_Vec n(-c.tangent(r0).Y(), c.tangent(r0).X(), 0);
            return TopoDS_Edge(BRepBuilderAPI_MakeEdge(c.point(r0).Translated(n * (sign * h)),
                                                       c.point(r1).Translated(n * (sign * h))));
        }
        Handle(TColgp_HArray1OfPnt) pts = new TColgp_HArray1OfPnt(1, kCamberSamples);
        for (int i = 0; i < kCamberSamples; ++i) {
            const double r = r0 + (r1 - r0) * i / (kCamberSamples - 1);
            const gp_Vec tv = c.tangent(r);
            const gp_Vec n(-tv.Y(), tv.X(), 0);  // +θ side
            pts->SetValue(i + 1, c.point(r).Translated(n * (sign * h)));
        }
        GeomAPI_Interpolate in(pts, false, 1e-9);
        in.Load(c.tangent(r0), c.tangent(r1));  // exact end tangents: G1 with the end rounds
        in.Perform();
        if (!in.IsDone()) broken("blade side curve");
        return TopoDS_Edge(BRepBuilderAPI_MakeEdge(in.Curve()));
    };
    auto round = [&](double r, double towards) {
        const gp_Vec tv = c.tangent(r), n(-tv.Y(), tv.X(), 0);
        const gp_Pnt p = c.point(r);
        Handle(Geom_TrimmedCurve) arc =
            GC_MakeArcOfCircle(p.Translated(n * h), p.Translated(tv * (towards * h)), p.Translated(n * -h)).Value();
        return TopoDS_Edge(BRepBuilderAPI_MakeEdge(arc));
    };
    BladeSection s;
    s.pressure = side(+1);
    s.suction = side(-1);
    s.trailing = round(r1, +1);
    s.leading = round(r0, -1);
    s.wire = wireOf({&s.pressure, &s.trailing, &s.suction, &s.leading});
    return s;
}

struct BladeBuild {
    bool splitter;
    double angle;
    TopoDS_Shape solid;                 // clipped by the shroud envelope
    TopoDS_Shape walls[4];              // pressure, trailing, suction, leading (after clipping)
    TopoDS_Shape shroud;
};

double minDistance(const TopoDS_Shape& a, const TopoDS_Shape& b) {
    BRepExtrema_DistShapeShape d(a, b);
    if (!d.IsDone() || d.NbSolution() == 0) broken("distance between blades");
    return d.Value();
}

TopoDS_Compound compoundOf(const std::vector<TopoDS_Shape>& shapes) {
    TopoDS_Compound c;
    BRep_Builder b;
    b.MakeCompound(c);
    for (const auto& s : shapes) b.Add(c, s);
    return c;
}

void checkSpec(const ImpellerSpec& s) {
    if (s.bladeCount < 3 || s.bladeCount > 40) fail("blade count must be 3 to 40");
    if (s.offPitchBlade >= s.bladeCount || std::abs(s.offPitchDeg) > 1)
        fail("offPitchBlade must name a main blade, turned off its pitch by at most 1 degree");
    if (s.pumpPlate) {
        if (!(s.plateThickness > 0)) fail("the back plate's thickness must be positive");
        if (s.hubSpline || s.seamAcrossBlade) fail("a pump impeller's hub is a plane: no hub spline, no seam");
        if (!(s.boreDiameter > 0) || !(s.boreDiameter / 2 + 1 < s.leadingRadius))
            fail("the bore must be narrower than the blades' inlet");
        if (!(s.bladeThickness > 0) || !(s.bladeHeight > 0)) fail("blade thickness and height must be positive");
        if (s.filletRadius < 0) fail("the fillet radius cannot be negative");
        const double reach = s.bladeThickness / 2 + s.filletRadius;
        if (!(s.leadingRadius - reach > s.boreDiameter / 2 + 0.5) || !(s.trailingRadius + reach < s.outerRadius - 0.5) ||
            !(s.leadingRadius < s.trailingRadius))
            fail("the blades with their fillets must stand on the plate (bore radius < leading < trailing < outer radius)");
        if (!(s.splitterStart > 0 && s.splitterStart < 0.9)) fail("splitterStart must be between 0 and 0.9");
        if (std::abs(s.wrapDeg) > 90 || std::abs(s.leanDeg) > 20) fail("wrap up to 90 and lean up to 20 degrees");
        if (s.omitSplitter >= s.bladeCount || (s.omitSplitter >= 0 && !s.splitters))
            fail("omitSplitter must name one of the splitters");
        return;
    }
    if (!(s.boreDiameter > 0) || s.boreDiameter / 2 >= s.noseRadius) fail("the bore must be narrower than the nose");
    if (!(s.noseRadius < s.outerRadius)) fail("the nose radius must be below the outer radius");
    if (!(s.rimHeight > 0 && s.rimHeight < s.noseHeight)) fail("the rim height must be between 0 and the nose height");
    if (!(s.outerRadius - s.noseRadius > s.noseHeight - s.rimHeight))
        fail("the hub arc needs a radial span larger than its axial drop");
    if (!(s.bladeThickness > 0) || !(s.bladeHeight > 0)) fail("blade thickness and height must be positive");
    if (s.filletRadius < 0) fail("the fillet radius cannot be negative");
    const double reach = s.bladeThickness / 2 + s.filletRadius;
    if (!(s.leadingRadius - reach > s.noseRadius + 0.5) || !(s.trailingRadius + reach < s.outerRadius - 0.5) ||
        !(s.leadingRadius < s.trailingRadius))
        fail("the blades with their fillets must stand inside the hub (nose radius < leading < trailing < outer radius)");
    if (!(s.splitterStart > 0 && s.splitterStart < 0.9)) fail("splitterStart must be between 0 and 0.9");
    if (std::abs(s.wrapDeg) > 90 || std::abs(s.leanDeg) > 20) fail("wrap up to 90 and lean up to 20 degrees");
    if (s.omitSplitter >= s.bladeCount || (s.omitSplitter >= 0 && !s.splitters))
        fail("omitSplitter must name one of the splitters");
}

}  // namespace

Impeller makeImpeller(const ImpellerSpec& spec) {
    checkSpec(spec);
    const int m = spec.bladeCount;
    const double pitch = 2 * kPi / m;
    const double rb = spec.boreDiameter / 2, t = spec.bladeThickness, h = spec.bladeHeight;
    const bool pump = spec.pumpPlate;
    const HubProfile hub(spec.noseRadius, spec.noseHeight, spec.outerRadius, spec.rimHeight);
    const double plateTop = spec.plateThickness;
    auto hubZ = [&](double r) { return pump ? plateTop : hub.z(r); };
    const double zBottom = pump ? plateTop / 2 : spec.rimHeight / 2;                   // blade sections: below the hub ...
    const double zTopSection = (pump ? plateTop : spec.noseHeight) + h + 2;            // ... and above the shroud
    const double lean = spec.leanDeg * kDeg;
    const double splitR0 = spec.leadingRadius + spec.splitterStart * (spec.trailingRadius - spec.leadingRadius);

    // The seam meridian (of the hub and of the shroud): the angle farthest from every blade's
    // footprint from the hub to the shroud (turned by the lean, widened by half the thickness and
    // the fillet).
    std::vector<std::pair<double, double>> covered;  // angular intervals, mod 2π
    const double reach = t / 2 + spec.filletRadius + 0.3;
    for (int k = 0; k < m; ++k) {
        for (int kind = 0; kind < (spec.splitters ? 2 : 1); ++kind) {
            const Camber c{spec.leadingRadius, spec.trailingRadius, k * pitch + kind * pitch / 2, spec.wrapDeg * kDeg};
            const double r0 = kind ? splitR0 : spec.leadingRadius;
            for (int i = -2; i <= 42; ++i) {
                const double r = std::clamp(r0 + (spec.trailingRadius - r0) * i / 40.0, pump ? rb : spec.noseRadius,
                                            spec.outerRadius);
                const double qHub = (hubZ(r) - zBottom) / (zTopSection - zBottom);
                const double qTip = (hubZ(r) + h - zBottom) / (zTopSection - zBottom);
                const double mid = c.theta(std::clamp(r, r0, spec.trailingRadius));
                const double half = std::asin(std::min(1.0, reach / r));
                covered.push_back({mid + lean * std::min(qHub, qTip) - half, mid + lean * std::max(qHub, qTip) + half});
            }
        }
    }
    double seam = 0, best = -1;
    for (int i = 0; i < 3600; ++i) {
        const double a = 2 * kPi * i / 3600;
        double clear = kPi;
        for (const auto& [lo, hi] : covered) {
            auto wrapd = [](double x) { return std::remainder(x, 2 * kPi); };
            double d = 0;
            if (wrapd(a - lo) > 0 && wrapd(hi - a) > 0) d = -std::min(wrapd(a - lo), wrapd(hi - a));
            else d = std::min(std::abs(wrapd(a - lo)), std::abs(wrapd(a - hi)));
            clear = std::min(clear, d);
        }
        if (clear > best) best = clear, seam = a;
    }
    if (best <= 0)
        fail("no meridian clear of the blades for the hub's seam: lower the wrap, lean, blade count or thickness");
    // The shroud envelope keeps its seam clear (the blades' tips stay one face each); the body's
    // may run under blade 0's middle, where the hub meets it.
    double hubSeam = seam;
    if (spec.seamAcrossBlade) {
        const Camber c0{spec.leadingRadius, spec.trailingRadius, 0, spec.wrapDeg * kDeg};
        const double rMid = 0.5 * (spec.leadingRadius + spec.trailingRadius);
        hubSeam = c0.theta(rMid) + lean * (hubZ(rMid) - zBottom) / (zTopSection - zBottom);
    }

    // Body of revolution (a pump impeller's: the plate, its top the hub, no nose).
    const gp_Pnt A(rb, 0, 0), B(spec.outerRadius, 0, 0), C(spec.outerRadius, 0, pump ? plateTop : spec.rimHeight),
        D(spec.noseRadius, 0, spec.noseHeight), E(rb, 0, pump ? plateTop : spec.noseHeight);
    TopoDS_Edge back = line(A, B), rim = line(B, C), hubArc = pump ? line(C, E) : hub.edge(0, spec.hubSpline),
                nose = pump ? TopoDS_Edge() : line(D, E), bore = line(E, A);
    BRepBuilderAPI_MakeFace bodyFace(pump ? wireOf({&back, &rim, &hubArc, &bore})
                                          : wireOf({&back, &rim, &hubArc, &nose, &bore}),
                                     true);
    auto turnAbout = [](double angle) {
        gp_Trsf t;
        t.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), angle);
        return TopLoc_Location(t);
    };
    const TopLoc_Location seamLoc = turnAbout(seam), hubSeamLoc = turnAbout(hubSeam);
    const gp_Ax1 axis(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
    BRepPrimAPI_MakeRevol bodyRev(bodyFace.Face(), axis, 2 * kPi, true);  // copy: full history
    if (!bodyRev.IsDone()) broken("body of revolution");
    const TopoDS_Shape body = bodyRev.Shape().Moved(hubSeamLoc);
    auto sweptFace = [&](const TopoDS_Edge& e) {
        const TopTools_ListOfShape& g = bodyRev.Generated(e);
        if (g.Extent() != 1) broken("body face of a profile edge");
        return g.First().Moved(hubSeamLoc);
    };
    const TopoDS_Shape backFace = sweptFace(back), rimFace = sweptFace(rim), hubFace = sweptFace(hubArc),
                       noseFace = pump ? TopoDS_Shape() : sweptFace(nose), boreFace = sweptFace(bore);

    // Envelope under the shroud.
    const double rIn = 1, rOut = spec.outerRadius + 10, zLow = -1;
    const gp_Pnt s0(spec.outerRadius, 0, (pump ? plateTop : spec.rimHeight) + h),
        s1(pump ? rb : spec.noseRadius, 0, (pump ? plateTop : spec.noseHeight) + h);
    TopoDS_Edge shroudArc = pump ? line(s0, s1) : hub.edge(h, spec.hubSpline);
    TopoDS_Edge e1 = line(gp_Pnt(rIn, 0, zLow), gp_Pnt(rOut, 0, zLow)), e2 = line(gp_Pnt(rOut, 0, zLow), gp_Pnt(rOut, 0, s0.Z())),
                e3 = line(gp_Pnt(rOut, 0, s0.Z()), s0), e4 = line(s1, gp_Pnt(rIn, 0, s1.Z())),
                e5 = line(gp_Pnt(rIn, 0, s1.Z()), gp_Pnt(rIn, 0, zLow));
    const TopoDS_Wire envWire = wireOf({&e1, &e2, &e3, &shroudArc, &e4, &e5});
    BRepBuilderAPI_MakeFace envFace(envWire, true);
    BRepPrimAPI_MakeRevol envRev(envFace.Face(), axis, 2 * kPi, true);
    if (!envRev.IsDone()) broken("shroud envelope");
    const TopoDS_Shape envelope = envRev.Shape().Moved(seamLoc);
    const TopTools_ListOfShape& shroudGen = envRev.Generated(shroudArc);
    if (shroudGen.Extent() != 1) broken("shroud surface");
    const TopoDS_Shape shroudSurface = shroudGen.First().Moved(seamLoc);

    // One main blade and one splitter, built at angle 0 and half a pitch; the others are copies
    // turned about the axis (same geometry, so their faces are congruent up to the Boolean).
    BladeBuild proto[2];
    for (int kind = 0; kind < (spec.splitters ? 2 : 1); ++kind) {
        const double theta0 = kind * pitch / 2;
        const Camber c{spec.leadingRadius, spec.trailingRadius, theta0, spec.wrapDeg * kDeg};
        const BladeSection sec = section(c, kind ? splitR0 : spec.leadingRadius, spec.trailingRadius, t);
        gp_Trsf down, up;
        down.SetTranslation(gp_Vec(0, 0, zBottom));
        up.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), lean);
        up.SetTranslationPart(gp_Vec(0, 0, zTopSection));
        BRepBuilderAPI_Transform lower(sec.wire, down, true), upper(sec.wire, up, true);
        BRepOffsetAPI_ThruSections ruled(true, true, 1e-6);
        ruled.AddWire(TopoDS::Wire(lower.Shape()));
        ruled.AddWire(TopoDS::Wire(upper.Shape()));
        ruled.Build();
        if (!ruled.IsDone()) broken("ruled blade");
        BRepAlgoAPI_Common clip(ruled.Shape(), envelope);
        if (!clip.IsDone() || clip.HasErrors()) broken("blade clipped by the shroud");
        BladeBuild& b = proto[kind];
        b.splitter = kind == 1;
        b.angle = theta0;
        b.solid = clip.Shape();
        const TopoDS_Edge* secEdges[4] = {&sec.pressure, &sec.trailing, &sec.suction, &sec.leading};
        for (int w = 0; w < 4; ++w) {
            const TopoDS_Shape& lateral = ruled.GeneratedFace(lower.ModifiedShape(*secEdges[w]));
            if (lateral.IsNull()) broken("ruled blade wall");
            b.walls[w] = image(clip, lateral, "blade wall");
        }
        b.shroud = image(clip, shroudSurface, "shroud face");
    }
    std::vector<BladeBuild> blades;  // in angular order
    for (int k = 0; k < m; ++k) {
        const double angle = k * pitch + (k == spec.offPitchBlade ? spec.offPitchDeg * kDeg : 0.0);
        gp_Trsf turn;
        turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), angle);
        const TopLoc_Location loc(turn);
        for (int kind = 0; kind < (spec.splitters ? 2 : 1); ++kind) {
            if (kind == 1 && k == spec.omitSplitter) continue;
            BladeBuild b = proto[kind];
            b.angle += angle;
            b.solid = b.solid.Moved(loc);
            for (auto& w : b.walls) w = w.Moved(loc);
            b.shroud = b.shroud.Moved(loc);
            blades.push_back(b);
        }
    }

    // Fuse all blades to the body at once.
    BRepAlgoAPI_Fuse fuse;
    TopTools_ListOfShape args, tools;
    args.Append(body);
    for (const auto& b : blades) tools.Append(b.solid);
    fuse.SetArguments(args);
    fuse.SetTools(tools);
    fuse.Build();
    if (!fuse.IsDone() || fuse.HasErrors()) broken("fusing the blades to the hub");
    TopoDS_Shape part = fuse.Shape();
    const TopoDS_Shape fusedHub = image(fuse, hubFace, "hub");

    // Root edges: those the hub shares with a blade wall.
    TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
    TopExp::MapShapesAndAncestors(part, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
    std::vector<std::array<TopoDS_Shape, 4>> fusedWalls(blades.size());
    for (size_t i = 0; i < blades.size(); ++i)
        for (int w = 0; w < 4; ++w) fusedWalls[i][w] = image(fuse, blades[i].walls[w], "blade wall in the fuse");
    struct Root {
        TopoDS_Edge edge;
        size_t blade;
        int wall;
    };
    std::vector<Root> roots;
    for (TopExp_Explorer ex(fusedHub, TopAbs_EDGE); ex.More(); ex.Next()) {
        const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
        for (const auto& f : edgeFaces.FindFromKey(e)) {
            for (size_t i = 0; i < blades.size(); ++i)
                for (int w = 0; w < 4; ++w)
                    if (f.IsSame(fusedWalls[i][w])) roots.push_back({e, i, w});
        }
    }
    // Four or more per blade: the hub's seam splits those of the blade it crosses, and OCCT's
    // intersection may split the curve where a plane wall meets a torus hub.
    std::vector<int> rootsOf(blades.size(), 0);
    for (const auto& r : roots) ++rootsOf[r.blade];
    for (size_t i = 0; i < blades.size(); ++i)
        if (rootsOf[i] < 4) broken("blade " + std::to_string(i) + " has " + std::to_string(rootsOf[i]) + " root edges");
    const int seamBlade = spec.seamAcrossBlade ? 0 : -1;
    if (spec.seamAcrossBlade && rootsOf[0] == 4) broken("the hub's seam does not split blade 0's root");

    // Root fillets.
    std::unique_ptr<BRepFilletAPI_MakeFillet> fillet;
    if (spec.filletRadius > 0) {
        fillet = std::make_unique<BRepFilletAPI_MakeFillet>(part);
        for (const auto& r : roots) fillet->Add(spec.filletRadius, r.edge);
        fillet->Build();
        if (!fillet->IsDone()) broken("root fillets failed");
        part = fillet->Shape();
    }
    auto final = [&](const TopoDS_Shape& fusedFace, const std::string& what) {
        return fillet ? image(*fillet, fusedFace, what) : fusedFace;
    };

    TopoDS_Shape solid;
    int solids = 0;
    for (TopExp_Explorer ex(part, TopAbs_SOLID); ex.More(); ex.Next(), ++solids) solid = ex.Current();
    if (solids != 1) broken("the part has " + std::to_string(solids) + " solids");
    if (!BRepCheck_Analyzer(solid).IsValid()) broken("the part fails OCCT's checker");

    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    auto index = [&](const TopoDS_Shape& f, const std::string& what) {
        const int i = faces.FindIndex(f);
        if (i == 0) broken(what + " is not a face of the part");
        return i;
    };

    Impeller out;
    out.shape = solid;
    ImpellerTruth& tr = out.truth;
    tr.bladeCount = m;
    tr.hub = index(final(fusedHub, "hub"), "hub");
    tr.bore = index(final(image(fuse, boreFace, "bore"), "bore"), "bore");
    tr.rim = index(final(image(fuse, rimFace, "rim"), "rim"), "rim");
    if (!pump) tr.planes.push_back(index(final(image(fuse, noseFace, "nose"), "nose"), "nose"));
    tr.planes.push_back(index(final(image(fuse, backFace, "back"), "back"), "back"));
    tr.seamBlade = seamBlade;
    std::vector<std::vector<TopoDS_Shape>> wallShapes(blades.size());
    for (size_t i = 0; i < blades.size(); ++i) {
        BladeTruth bt;
        bt.splitter = blades[i].splitter;
        bt.angleDeg = blades[i].angle / kDeg;
        int* slots[4] = {&bt.pressure, &bt.trailing, &bt.suction, &bt.leading};
        for (int w = 0; w < 4; ++w) {
            const TopoDS_Shape f = final(fusedWalls[i][w], "blade wall");
            *slots[w] = index(f, "blade wall");
            wallShapes[i].push_back(f);
        }
        bt.shroud = index(final(image(fuse, blades[i].shroud, "shroud"), "shroud"), "shroud");
        if (fillet) {
            for (int w = 0; w < 4; ++w)
                for (const auto& r : roots)
                    if (r.blade == i && r.wall == w)
                        for (const auto& g : fillet->Generated(r.edge)) {
                            const int fi = index(g, "fillet");  // a face may come from two edges of the chain
                            if (std::find(bt.fillets.begin(), bt.fillets.end(), fi) == bt.fillets.end())
                                bt.fillets.push_back(fi);
                        }
        }
        tr.blades.push_back(bt);
    }
    tr.boreDiameter = spec.boreDiameter;
    tr.boreDepth = pump ? plateTop : spec.noseHeight;
    tr.filletRadius = spec.filletRadius;
    tr.bladeHeight = h;
    tr.minChannelWidth = 1e300;
    const size_t pairs = std::min<size_t>(blades.size(), spec.splitters ? 2 : 1);
    for (size_t i = 0; i < pairs; ++i)
        tr.minChannelWidth = std::min(tr.minChannelWidth, minDistance(compoundOf(wallShapes[i]),
                                                                      compoundOf(wallShapes[(i + 1) % blades.size()])));
    return out;
}

std::string truthToJson(const ImpellerTruth& t) {
    using nlohmann::json;
    json blades = json::array();
    for (const auto& b : t.blades)
        blades.push_back({{"splitter", b.splitter},
                          {"angleDeg", b.angleDeg},
                          {"pressure", b.pressure},
                          {"suction", b.suction},
                          {"leading", b.leading},
                          {"trailing", b.trailing},
                          {"shroud", b.shroud},
                          {"fillets", b.fillets}});
    json doc = {{"units", "mm"},
                {"axis", {0, 0, 1}},
                {"bladeCount", t.bladeCount},
                {"hub", t.hub},
                {"bore", t.bore},
                {"rim", t.rim},
                {"planes", t.planes},
                {"seamBlade", t.seamBlade},
                {"blades", blades},
                {"boreDiameter", t.boreDiameter},
                {"boreDepth", t.boreDepth},
                {"filletRadius", t.filletRadius},
                {"bladeHeight", t.bladeHeight},
                {"minChannelWidth", t.minChannelWidth}};
    return doc.dump(1);
}

ImpellerSpec impellerSpecFromJson(const std::string& text) {
    ImpellerSpec s;
    if (text.empty()) return s;
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw inputError(std::string("impeller spec: not valid JSON: ") + e.what());
    }
    if (!j.is_object()) throw inputError("impeller spec: expected a JSON object");
    for (auto it = j.begin(); it != j.end(); ++it) {
        const std::string& k = it.key();
        const auto& v = it.value();
        auto number = [&](double& field) {
            if (!v.is_number()) throw inputError("impeller spec: " + k + " must be a number");
            field = v.get<double>();
        };
        auto integer = [&](int& field) {
            if (!v.is_number_integer()) throw inputError("impeller spec: " + k + " must be a whole number");
            field = v.get<int>();
        };
        if (k == "bladeCount") integer(s.bladeCount);
        else if (k == "omitSplitter") integer(s.omitSplitter);
        else if (k == "offPitchBlade") integer(s.offPitchBlade);
        else if (k == "offPitchDeg") number(s.offPitchDeg);
        else if (k == "splitters") {
            if (!v.is_boolean()) throw inputError("impeller spec: splitters must be true or false");
            s.splitters = v.get<bool>();
        } else if (k == "boreDiameter") number(s.boreDiameter);
        else if (k == "noseRadius") number(s.noseRadius);
        else if (k == "noseHeight") number(s.noseHeight);
        else if (k == "outerRadius") number(s.outerRadius);
        else if (k == "rimHeight") number(s.rimHeight);
        else if (k == "bladeHeight") number(s.bladeHeight);
        else if (k == "bladeThickness") number(s.bladeThickness);
        else if (k == "leadingRadius") number(s.leadingRadius);
        else if (k == "trailingRadius") number(s.trailingRadius);
        else if (k == "splitterStart") number(s.splitterStart);
        else if (k == "wrapDeg") number(s.wrapDeg);
        else if (k == "leanDeg") number(s.leanDeg);
        else if (k == "filletRadius") number(s.filletRadius);
        else if (k == "plateThickness") number(s.plateThickness);
        else if (k == "hubSpline" || k == "seamAcrossBlade" || k == "pumpPlate") {
            if (!v.is_boolean()) throw inputError("impeller spec: " + k + " must be true or false");
            (k == "hubSpline" ? s.hubSpline : k == "seamAcrossBlade" ? s.seamAcrossBlade : s.pumpPlate) = v.get<bool>();
        }
        else throw inputError("impeller spec: unknown key " + k);
    }
    return s;
}

}  // namespace aeronc::testparts
