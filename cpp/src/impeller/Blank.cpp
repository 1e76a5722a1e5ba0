#include <aeronc/impeller/Blank.h>

#include <aeronc/core/Error.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Ax1.hxx>
#include <gp_Ax3.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <cmath>

namespace aeronc::impeller {

namespace {

constexpr double kPi = 3.14159265358979323846;

gp_Ax1 axisOf(const ImpellerFeatures& f) {
    return gp_Ax1(gp_Pnt(f.axisPoint[0], f.axisPoint[1], f.axisPoint[2]),
                  gp_Dir(f.axisDirection[0], f.axisDirection[1], f.axisDirection[2]));
}

}  // namespace

BlankProfile outerProfile(const TopoDS_Shape& part, const ImpellerFeatures& f, double allowance, int stations,
                          double deflection) {
    if (!(allowance >= 0)) throw inputError("impeller blank: the allowance must be zero or more");
    if (stations < 2) throw inputError("impeller blank: at least two stations along the axis");
    const gp_Ax1 axis = axisOf(f);
    const gp_Lin line(axis);
    // Meshes the part's faces (a finer triangulation they already have is kept).
    const TopoDS_Shape& s = part;
    BRepMesh_IncrementalMesh mesh(s, deflection, false, 0.3, false);
    // Triangles as (lowest, highest axial station, largest radius): the distance from the axis
    // is convex, so over a triangle it is largest at a corner.
    struct Span {
        double lo, hi, r;
    };
    std::vector<Span> spans;
    double lo = 1e300, hi = -1e300;
    for (TopExp_Explorer ex(s, TopAbs_FACE); ex.More(); ex.Next()) {
        TopLoc_Location loc;
        const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(TopoDS::Face(ex.Current()), loc);
        if (tri.IsNull()) throw geometryError("impeller blank: a face has no triangulation");
        for (int t = 1; t <= tri->NbTriangles(); ++t) {
            int n[3];
            tri->Triangle(t).Get(n[0], n[1], n[2]);
            Span sp{1e300, -1e300, 0};
            for (int k : n) {
                const gp_Pnt p = tri->Node(k).Transformed(loc.Transformation());
                const double z = gp_Vec(axis.Location(), p).Dot(gp_Vec(axis.Direction()));
                sp.lo = std::min(sp.lo, z), sp.hi = std::max(sp.hi, z), sp.r = std::max(sp.r, line.Distance(p));
            }
            spans.push_back(sp);
            lo = std::min(lo, sp.lo), hi = std::max(hi, sp.hi);
        }
    }
    if (spans.empty() || hi <= lo) throw inputError("impeller blank: the part has no extent along its axis");
    std::vector<double> r(stations, 0.0);
    const double step = (hi - lo) / stations;
    for (const auto& sp : spans) {
        const int i0 = std::clamp(static_cast<int>(std::floor((sp.lo - lo) / step)), 0, stations - 1);
        const int i1 = std::clamp(static_cast<int>(std::floor((sp.hi - lo) / step)), 0, stations - 1);
        for (int i = i0; i <= i1; ++i) r[i] = std::max(r[i], sp.r);
    }
    // Between its corners a triangle's edge may lie inside the surface by up to the deflection:
    // neighbouring stations bound each other, and the deflection is added to the allowance.
    std::vector<double> grown(stations);
    for (int i = 0; i < stations; ++i) {
        grown[i] = r[i];
        if (i > 0) grown[i] = std::max(grown[i], r[i - 1]);
        if (i + 1 < stations) grown[i] = std::max(grown[i], r[i + 1]);
        grown[i] += allowance + deflection;
    }
    BlankProfile p;
    p.axial.push_back(lo - allowance);
    for (int i = 0; i < stations; ++i) {
        const double end = i + 1 == stations ? hi + allowance : lo + (i + 1) * step;
        if (!p.radius.empty() && std::abs(p.radius.back() - grown[i]) < 1e-9) {
            p.axial.back() = end;  // same radius: one longer step
        } else {
            p.radius.push_back(grown[i]);
            p.axial.push_back(end);
        }
    }
    return p;
}

TopoDS_Shape revolveProfile(const BlankProfile& p, const ImpellerFeatures& f) {
    if (p.radius.empty() || p.axial.size() != p.radius.size() + 1)
        throw inputError("impeller blank: a profile needs one more station than radii");
    const gp_Ax1 axis = axisOf(f);
    // A frame whose Z is the axis; the profile lies in its XZ plane.
    const gp_Ax3 frame(axis.Location(), axis.Direction());
    auto at = [&](double rad, double z) {
        return gp_Pnt(axis.Location().XYZ() + frame.XDirection().XYZ() * rad + axis.Direction().XYZ() * z);
    };
    BRepBuilderAPI_MakePolygon poly;
    poly.Add(at(0, p.axial.front()));
    for (size_t i = 0; i < p.radius.size(); ++i) {
        poly.Add(at(p.radius[i], p.axial[i]));
        poly.Add(at(p.radius[i], p.axial[i + 1]));
    }
    poly.Add(at(0, p.axial.back()));
    poly.Close();
    if (!poly.IsDone()) throw geometryError("impeller blank: the profile is not a closed polygon");
    BRepBuilderAPI_MakeFace face(poly.Wire(), true);
    if (!face.IsDone()) throw geometryError("impeller blank: the profile is not a face");
    BRepPrimAPI_MakeRevol rev(face.Face(), axis, 2 * kPi);
    if (!rev.IsDone()) throw geometryError("impeller blank: revolving the profile failed");
    return rev.Shape();
}

}  // namespace aeronc::impeller
