#include <aeronc/testparts/HoleTruth.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Cylinder.hxx>

#include <array>
#include <cmath>

namespace aeronc::testparts {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Axis {
    gp_Pnt point;  // on the axis, nearest the origin
    gp_Dir dir;    // sign fixed: first non-zero component positive
    double radius;
    gp_Dir x, y;   // the group's reference frame square to dir
};

Axis axisOf(const gp_Cylinder& c) {
    gp_Dir d = c.Axis().Direction();
    const double comps[3] = {d.X(), d.Y(), d.Z()};
    for (double v : comps)
        if (std::fabs(v) > 1e-9) {
            if (v < 0) d.Reverse();
            break;
        }
    const gp_XYZ o = c.Axis().Location().XYZ();
    const gp_Pnt p(o - d.XYZ() * o.Dot(d.XYZ()));
    const gp_Dir x = c.Position().XDirection();
    const gp_Dir y = d.Crossed(x);
    return {p, d, c.Radius(), x, y};
}

bool sameAxis(const Axis& a, const Axis& b) {
    const double tol = 1e-4 * (1 + a.radius);
    return a.dir.IsParallel(b.dir, 1e-6) && a.point.Distance(b.point) <= tol && std::fabs(a.radius - b.radius) <= tol;
}

}  // namespace

std::vector<bool> holeWallsByGeometry(const TopoDS_Shape& solid, double minSpanDegrees) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    std::vector<bool> out(static_cast<std::size_t>(faces.Extent()), false);
    std::vector<Axis> groups;
    std::vector<std::array<bool, 360>> covered;
    std::vector<std::vector<int>> members;
    std::vector<gp_Pnt> axisMid;  // per group: its axis at the first face's mid-height
    for (int i = 1; i <= faces.Extent(); ++i) {
        const TopoDS_Face face = TopoDS::Face(faces(i));
        BRepAdaptor_Surface s(face, true);
        if (s.GetType() != GeomAbs_Cylinder) continue;
        const gp_Cylinder cyl = s.Cylinder();
        double u0, u1, v0, v1;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        BRepTopAdaptor_FClass2d cls(face, 1e-9);
        BRepGProp_Face normals(face);
        Axis a = axisOf(cyl);
        std::size_t g = 0;
        while (g < groups.size() && !sameAxis(groups[g], a)) ++g;
        if (g == groups.size()) {
            groups.push_back(a);
            covered.push_back({});
            members.push_back({});
            const gp_Pnt on = s.Value(0.5 * (u0 + u1), 0.5 * (v0 + v1));
            const gp_Vec r(a.point, on);
            axisMid.push_back(a.point.Translated(gp_Vec(a.dir) * r.Dot(gp_Vec(a.dir))));
        }
        const Axis& ref = groups[g];
        bool concave = false, seen = false;
        std::vector<int> bins;
        const int samples = static_cast<int>(std::ceil((u1 - u0) * 180 / kPi * 2)) + 2;  // two per degree
        for (int k = 0; k <= samples; ++k) {
            const double u = u0 + (u1 - u0) * k / samples;
            for (double fv : {0.5, 0.25, 0.75}) {
                const double v = v0 + (v1 - v0) * fv;
                if (cls.Perform(gp_Pnt2d(u, v)) != TopAbs_IN) continue;
                gp_Pnt p;
                gp_Vec n;
                normals.Normal(u, v, p, n);  // out of the material: it follows the face's orientation
                const gp_Vec r(ref.point, p);
                const gp_Vec radial = r - gp_Vec(ref.dir) * r.Dot(gp_Vec(ref.dir));
                if (!seen) concave = n.Dot(radial) < 0, seen = true;  // the normal points at the axis
                double ang = std::atan2(radial.Dot(gp_Vec(ref.y)), radial.Dot(gp_Vec(ref.x))) * 180 / kPi;
                if (ang < 0) ang += 360;
                bins.push_back(static_cast<int>(ang) % 360);
                break;
            }
        }
        if (!seen || !concave) continue;
        for (int b : bins) covered[g][static_cast<std::size_t>(b)] = true;
        members[g].push_back(i - 1);
    }
    BRepClass3d_SolidClassifier inside;
    inside.Load(solid);
    for (std::size_t g = 0; g < groups.size(); ++g) {
        int span = 0;
        for (bool c : covered[g]) span += c;
        if (span < minSpanDegrees || members[g].empty()) continue;
        // A hole is empty along its axis and all round it inside its wall; a groove round a
        // boss is not (even where a mark engraved in the boss opens the axis, milled_003's).
        const Axis& a = groups[g];
        bool empty = true;
        for (double part : {0.0, 0.25, 0.5, 0.75, 0.9})
            for (int k = 0; k < (part > 0 ? 8 : 1) && empty; ++k) {
                const double t = 2 * kPi * k / 8;
                const gp_Vec off = (gp_Vec(a.x) * std::cos(t) + gp_Vec(a.y) * std::sin(t)) * (part * a.radius);
                inside.Perform(axisMid[g].Translated(off), 1e-6);
                empty = inside.State() == TopAbs_OUT;
            }
        if (empty)
            for (int f : members[g]) out[static_cast<std::size_t>(f)] = true;
    }
    return out;
}

}  // namespace aeronc::testparts
