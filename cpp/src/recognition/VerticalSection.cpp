#include "VerticalSection.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAPI_InterCurveCurve.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <gp_Circ2d.hxx>
#include <gp_Lin2d.hxx>
#include <Geom2d_Line.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <gp_Cone.hxx>

#include <algorithm>
#include <cmath>

namespace aeronc::recognition {
namespace {
double dotp(const gp_XYZ& a, const Vec3& b) { return a.X() * b[0] + a.Y() * b[1] + a.Z() * b[2]; }
}  // namespace

namespace {

// A straight line a*u + b*v = c of the face's parameter space where the plane cuts the
// surface; along it the surface runs straight (rulings, planes) or round an axis parallel to
// the setup's (arc: a circle of that radius, sampled to the chord tolerance).
struct IsoLine {
    double a, b, c;
    bool arc = false;
    double radius = 0;
    Handle(Geom_Curve) iso;  // else: the surface along the line, sampled to the chord tolerance
    bool isoAlongU = true;   // iso's parameter is u (a line v = c), else v (a line u = c)
};

// The values x + 2*pi*k inside [lo, hi] (a periodic parameter put into the face's range).
void periodicIn(double x, double lo, double hi, std::vector<double>& out) {
    const double eps = 1e-9;
    x += 2 * M_PI * std::ceil((lo - eps - x) / (2 * M_PI));
    for (; x <= hi + eps; x += 2 * M_PI) out.push_back(x);
}

// A ruled B-spline cut at height h: along one iso-curve when each row of poles lies at one
// height (the height runs linearly across the rows), along the rulings where a row is at h
// when it is extruded square to the axis (a fillet along a floor's edge). False: neither.
bool ruledLines(const RuledSpline& ruled, const SetupFrame& frame, double h, std::vector<IsoLine>& lines) {
    const Geom_BSplineSurface& b = *ruled.surface;
    const bool inV = ruled.linearInV;
    const int n = inV ? b.NbUPoles() : b.NbVPoles();
    double u0, u1, v0, v1;
    b.Bounds(u0, u1, v0, v1);
    if (norm(ruled.extrusion) > 0 && std::fabs(dot(ruled.extrusion, frame.w)) <= 1e-9) {
        const Handle(Geom_Curve) row = inV ? b.VIso(v0) : b.UIso(u0);
        const double q0 = inV ? u0 : v0, q1 = inV ? u1 : v1;
        auto f = [&](double q) { return dotp(row->Value(q).XYZ(), frame.w) - h; };
        // Sign changes on a grid finer than the poles, then bisection.
        const int m = 16 * n;
        double qa = q0, fa = f(q0);
        for (int k = 1; k <= m; ++k) {
            const double qb = q0 + (q1 - q0) * k / m, fb = f(qb);
            if ((fa < 0) != (fb < 0)) {
                double lo = qa, hi = qb, flo = fa;
                for (int it = 0; it < 60 && hi - lo > 1e-14 * (1 + std::fabs(hi)); ++it) {
                    const double mid = 0.5 * (lo + hi), fm = f(mid);
                    if ((fm < 0) == (flo < 0)) lo = mid, flo = fm;
                    else hi = mid;
                }
                const double q = 0.5 * (lo + hi);
                lines.push_back(inV ? IsoLine{1, 0, q} : IsoLine{0, 1, q});
            }
            qa = qb, fa = fb;
        }
        return true;
    }
    auto height = [&](int i, int row) { return dotp((inV ? b.Pole(i, row) : b.Pole(row, i)).XYZ(), frame.w); };
    const double a0 = height(1, 1), a1 = height(1, 2);
    const double tol = 1e-9 * (1 + std::fabs(a0) + std::fabs(a1));
    if (std::fabs(a1 - a0) <= 1e3 * tol) return false;
    for (int i = 2; i <= n; ++i)
        if (std::fabs(height(i, 1) - a0) > tol || std::fabs(height(i, 2) - a1) > tol) return false;
    const double t = (h - a0) / (a1 - a0);
    if (t <= 0 || t >= 1) return true;  // the plane misses the surface
    IsoLine L{0, 0, 0};
    if (inV) L.b = 1, L.c = v0 + t * (v1 - v0), L.iso = b.VIso(L.c), L.isoAlongU = true;
    else L.a = 1, L.c = u0 + t * (u1 - u0), L.iso = b.UIso(L.c), L.isoAlongU = false;
    lines.push_back(L);
    return true;
}

// Where the section crosses the face along one iso-line: appends the pieces inside the face
// to out; false when OCCT must decide (the line runs along a boundary curve).
bool sectionAlong(const IsoLine& L, const std::vector<Handle(Geom2d_TrimmedCurve)>& boundaryUV,
                  BRepTopAdaptor_FClass2d& cls, const BRepAdaptor_Surface& s, const SetupFrame& frame,
                  double chordTol, std::vector<std::vector<P2>>& out) {
    const double a = L.a, b = L.b, c = L.c;
    const double n = std::hypot(a, b);
    if (n < 1e-12) return false;
    // Line through the point closest to the origin, along (-b, a): parameter t along it.
    const gp_Pnt2d p0(a * c / (n * n), b * c / (n * n));
    const gp_Dir2d dir(-b / n, a / n);
    Handle(Geom2d_Line) line = new Geom2d_Line(p0, dir);

    std::vector<double> ts;
    const double lx = -b / n, ly = a / n;  // the line's direction
    for (const Handle(Geom2d_TrimmedCurve)& tc : boundaryUV) {
        if (tc.IsNull()) return false;
        // Lines and circles in closed form: most boundaries are, and the general
        // intersection costs tens of microseconds each.
        const Geom2dAdaptor_Curve ac(tc);
        if (ac.GetType() == GeomAbs_Line) {
            const gp_Lin2d l = ac.Line();
            const double dx = l.Direction().X(), dy = l.Direction().Y();
            const double den = lx * dy - ly * dx;
            if (std::fabs(den) < 1e-12) {
                const double off = (l.Location().X() - p0.X()) * ly - (l.Location().Y() - p0.Y()) * lx;
                if (std::fabs(off) < 1e-9) return false;  // along the section: let OCCT decide
                continue;
            }
            const double qx = l.Location().X() - p0.X(), qy = l.Location().Y() - p0.Y();
            const double t = (qx * dy - qy * dx) / den;  // along the section line
            const double s = (qx * ly - qy * lx) / den;  // along the boundary line
            const double f = ac.FirstParameter(), g = ac.LastParameter();
            if (s >= f - 1e-9 && s <= g + 1e-9) ts.push_back(t);
            continue;
        }
        if (ac.GetType() == GeomAbs_Circle) {
            const gp_Circ2d c = ac.Circle();
            const double cx = c.Location().X() - p0.X(), cy = c.Location().Y() - p0.Y(), r = c.Radius();
            const double mid = cx * lx + cy * ly;                 // foot of the centre on the line
            const double off2 = cx * cx + cy * cy - mid * mid;     // squared distance centre-line
            if (off2 > r * r + 1e-18) continue;
            const double half = std::sqrt(std::max(0.0, r * r - off2));
            const gp_Ax22d& ax = c.Position();
            for (double t : {mid - half, mid + half}) {
                const double px = p0.X() + t * lx - c.Location().X(), py = p0.Y() + t * ly - c.Location().Y();
                // The circle's parameter of the point, within the trimmed range (periodic).
                double u = std::atan2(px * ax.YDirection().X() + py * ax.YDirection().Y(),
                                      px * ax.XDirection().X() + py * ax.XDirection().Y());
                const double f = ac.FirstParameter(), g = ac.LastParameter();
                while (u < f - 1e-9) u += 2 * M_PI;
                while (u > f + 2 * M_PI) u -= 2 * M_PI;
                if (u <= g + 1e-9) ts.push_back(t);
                if (half < 1e-12) break;  // tangent: one point
            }
            continue;
        }
        Geom2dAPI_InterCurveCurve inter(tc, line, 1e-9);
        for (int k = 1; k <= inter.NbPoints(); ++k) {
            const gp_Pnt2d q = inter.Point(k);
            ts.push_back((q.X() - p0.X()) * dir.X() + (q.Y() - p0.Y()) * dir.Y());
        }
        if (inter.NbSegments() > 0) return false;  // an edge along the section: let OCCT decide
    }
    std::sort(ts.begin(), ts.end());
    ts.erase(std::unique(ts.begin(), ts.end(), [](double x, double y) { return std::fabs(x - y) < 1e-9; }), ts.end());
    if (ts.size() < 2) return true;  // the plane misses the face

    auto uv = [&](double t) { return gp_Pnt2d(p0.X() + t * dir.X(), p0.Y() + t * dir.Y()); };
    auto at = [&](double t) {
        const gp_Pnt p = s.Value(uv(t).X(), uv(t).Y());
        return frame.project({p.X(), p.Y(), p.Z()});
    };
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
        const double t0 = ts[k], t1 = ts[k + 1];
        if (cls.Perform(uv(0.5 * (t0 + t1))) != TopAbs_IN) continue;
        std::vector<P2> pts;
        if (!L.iso.IsNull()) {
            const double q0 = L.isoAlongU ? uv(t0).X() : uv(t0).Y(), q1 = L.isoAlongU ? uv(t1).X() : uv(t1).Y();
            GeomAdaptor_Curve c(L.iso);
            GCPnts_QuasiUniformDeflection d(c, chordTol, std::min(q0, q1), std::max(q0, q1));
            if (!d.IsDone() || d.NbPoints() < 2) return false;
            for (int i = 1; i <= d.NbPoints(); ++i) {
                const gp_Pnt p = d.Value(q0 <= q1 ? i : d.NbPoints() + 1 - i);
                pts.push_back(frame.project({p.X(), p.Y(), p.Z()}));
            }
        } else if (L.arc) {
            // t runs along u (the angle) up to the sign of the direction.
            const double span = std::fabs(t1 - t0) * std::fabs(dir.X());
            const double step = L.radius > chordTol ? 2 * std::acos(1 - chordTol / L.radius) : span;
            const int m = std::max(1, static_cast<int>(std::ceil(span / std::max(step, 1e-6))));
            for (int i = 0; i <= m; ++i) pts.push_back(at(t0 + (t1 - t0) * i / m));
        } else {
            pts = {at(t0), at(t1)};
        }
        out.push_back(std::move(pts));
    }
    return true;
}

}  // namespace

bool sectionVerticalFace(const FaceInfo& info, const std::vector<Handle(Geom2d_TrimmedCurve)>& boundaryUV,
                         BRepTopAdaptor_FClass2d& cls, const SetupFrame& frame, double h, double chordTol,
                         std::vector<std::vector<P2>>& out) {
    BRepAdaptor_Surface s(info.face, false);  // already carries the face's location
    const RuledSpline* ruled = info.ruled.get();
    std::vector<IsoLine> lines;
    // The face's parameter range, for the periodic parameters of round surfaces.
    auto range = [&](bool u, double& lo, double& hi) {
        lo = u ? info.uMin : info.vMin, hi = u ? info.uMax : info.vMax;
    };
    if (s.GetType() == GeomAbs_Plane) {
        const gp_Ax3 pos = s.Plane().Position();
        if (std::fabs(dotp(pos.Direction().XYZ(), frame.w)) > 1 - 1e-6) return false;  // (nearly) parallel to the slice
        lines.push_back({dotp(pos.XDirection().XYZ(), frame.w), dotp(pos.YDirection().XYZ(), frame.w),
                         h - dotp(pos.Location().XYZ(), frame.w)});
    } else if (s.GetType() == GeomAbs_Cone) {
        // P(u, v) = O + (R + v sin a)(cos u X + sin u Y) + v cos a Z: height is linear in v.
        const gp_Cone cone = s.Cone();
        const gp_Ax3 pos = cone.Position();
        const double k = dotp(pos.Direction().XYZ(), frame.w);
        if (std::fabs(std::fabs(k) - 1) > 1e-9) return false;
        const double b = k * std::cos(cone.SemiAngle()), c = h - dotp(pos.Location().XYZ(), frame.w);
        lines.push_back({0, b, c, true, std::fabs(cone.RefRadius() + (c / b) * std::sin(cone.SemiAngle()))});
    } else if (s.GetType() == GeomAbs_Cylinder) {
        const gp_Ax3 pos = s.Cylinder().Position();
        const double r = s.Cylinder().Radius();
        const double k = dotp(pos.Direction().XYZ(), frame.w);
        const double c = h - dotp(pos.Location().XYZ(), frame.w);
        if (std::fabs(std::fabs(k) - 1) <= 1e-9) {
            lines.push_back({0, k, c, true, r});
        } else if (std::fabs(k) <= 1e-9) {
            // Axis square to the setup's (a floor fillet, a cross hole): the height is
            // r cos(u - phi), so the plane cuts along the rulings u = phi +- acos(c / r).
            const double phi = std::atan2(dotp(pos.YDirection().XYZ(), frame.w), dotp(pos.XDirection().XYZ(), frame.w));
            const double q = c / r;
            if (std::fabs(q) >= 1) return true;  // above or below it, or touching along a ruling
            double lo, hi;
            range(true, lo, hi);
            std::vector<double> us;
            for (double u : {phi + std::acos(q), phi - std::acos(q)}) periodicIn(u, lo, hi, us);
            for (double u : us) lines.push_back({1, 0, u});
        } else {
            return false;
        }
    } else if (s.GetType() == GeomAbs_Torus || s.GetType() == GeomAbs_Sphere) {
        // About an axis parallel to the setup's: the height is r sin v (plus the centre's), so
        // the plane cuts along the circles v = asin(c / r) and pi - asin(c / r).
        const bool torus = s.GetType() == GeomAbs_Torus;
        const gp_Ax3 pos = torus ? s.Torus().Position() : s.Sphere().Position();
        const double r = torus ? s.Torus().MinorRadius() : s.Sphere().Radius();
        const double R = torus ? s.Torus().MajorRadius() : 0;
        const double k = dotp(pos.Direction().XYZ(), frame.w);
        if (std::fabs(std::fabs(k) - 1) > 1e-9) return false;
        const double q = (h - dotp(pos.Location().XYZ(), frame.w)) / (k * r);
        if (std::fabs(q) >= 1) return true;
        double lo, hi;
        range(false, lo, hi);
        std::vector<double> vs;
        for (double v : {std::asin(q), M_PI - std::asin(q)}) periodicIn(v, lo, hi, vs);
        for (double v : vs) lines.push_back({0, 1, v, true, std::fabs(R + r * std::cos(v))});
    } else if (ruled) {
        if (!ruledLines(*ruled, frame, h, lines)) return false;
    } else {
        return false;
    }
    std::vector<std::vector<P2>> pieces;
    for (const IsoLine& L : lines)
        if (!sectionAlong(L, boundaryUV, cls, s, frame, chordTol, pieces)) return false;
    for (auto& p : pieces) out.push_back(std::move(p));
    return true;
}

}  // namespace aeronc::recognition
