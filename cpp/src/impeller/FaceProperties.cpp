#include "FaceProperties.h"

#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <math.hxx>
#include <math_Vector.hxx>

#include <algorithm>
#include <cmath>
#include <vector>

namespace aeronc::impeller {

namespace {

struct Rectangle {
    double u0, u1, v0, v1;
};

// Whether the face is its surface's parameter rectangle: one wire whose every edge runs along
// a side of the face's parameter bounds.
bool rectangleDomain(const TopoDS_Face& f, Rectangle& r) {
    int wires = 0;
    for (TopExp_Explorer w(f, TopAbs_WIRE); w.More(); w.Next()) ++wires;
    if (wires != 1) return false;
    BRepTools::UVBounds(f, r.u0, r.u1, r.v0, r.v1);
    const double tol = 1e-9 * (1 + std::max(r.u1 - r.u0, r.v1 - r.v0));
    for (TopExp_Explorer e(f, TopAbs_EDGE); e.More(); e.Next()) {
        double a, b;
        const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), f, a, b);
        if (c.IsNull()) return false;
        bool u0 = true, u1 = true, v0 = true, v1 = true;
        for (int k = 0; k <= 8; ++k) {
            const gp_Pnt2d p = c->Value(a + (b - a) * k / 8.0);
            u0 = u0 && std::abs(p.X() - r.u0) < tol, u1 = u1 && std::abs(p.X() - r.u1) < tol;
            v0 = v0 && std::abs(p.Y() - r.v0) < tol, v1 = v1 && std::abs(p.Y() - r.v1) < tol;
        }
        if (!(u0 || u1 || v0 || v1)) return false;
    }
    return true;
}

// The knots inside (a, b), with a and b, each interval cut into `split` equal pieces.
std::vector<double> breaks(const TColStd_Array1OfReal& knots, double a, double b, int split) {
    std::vector<double> k{a};
    for (int i = knots.Lower(); i <= knots.Upper(); ++i)
        if (knots(i) > a + 1e-12 * (b - a) && knots(i) < b - 1e-12 * (b - a)) k.push_back(knots(i));
    k.push_back(b);
    std::vector<double> out{a};
    for (size_t i = 0; i + 1 < k.size(); ++i)
        for (int s = 1; s <= split; ++s) out.push_back(k[i] + (k[i + 1] - k[i]) * s / split);
    return out;
}

// Tensor Gauss-Legendre with n points a direction on every (split) knot span: the surface is
// polynomial (rational) on a span, so the area element is smooth there.
AreaAndCentroid integrate(const Handle(Geom_BSplineSurface)& bs, const Rectangle& r, int nu, int nv, int split) {
    const auto ub = breaks(bs->UKnots(), r.u0, r.u1, split), vb = breaks(bs->VKnots(), r.v0, r.v1, split);
    GeomAdaptor_Surface s(bs);  // evaluates through its per-span polynomial cache
    math_Vector pu(1, nu), wu(1, nu), pv(1, nv), wv(1, nv);
    math::GaussPoints(nu, pu), math::GaussWeights(nu, wu), math::GaussPoints(nv, pv), math::GaussWeights(nv, wv);
    double area = 0;
    gp_XYZ moment(0, 0, 0);
    for (size_t i = 0; i + 1 < ub.size(); ++i)
        for (size_t j = 0; j + 1 < vb.size(); ++j) {
            const double hu = 0.5 * (ub[i + 1] - ub[i]), mu = 0.5 * (ub[i + 1] + ub[i]);
            const double hv = 0.5 * (vb[j + 1] - vb[j]), mv = 0.5 * (vb[j + 1] + vb[j]);
            for (int a = 1; a <= nu; ++a)
                for (int b = 1; b <= nv; ++b) {
                    gp_Pnt p;
                    gp_Vec du, dv;
                    s.D1(mu + hu * pu(a), mv + hv * pv(b), p, du, dv);
                    const double w = wu(a) * wv(b) * hu * hv * du.Crossed(dv).Magnitude();
                    area += w;
                    moment += w * p.XYZ();
                }
        }
    return {area, gp_Pnt(area > 0 ? moment / area : moment)};
}

}  // namespace

bool isParameterRectangle(const TopoDS_Face& face) {
    Rectangle r;
    return rectangleDomain(face, r);
}

AreaAndCentroid areaAndCentroid(const TopoDS_Face& face) {
    const Handle(Geom_BSplineSurface) s = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face));
    Rectangle r;
    if (!s.IsNull() && rectangleDomain(face, r)) {
        // Two orders that agree to 1e-7 mean the quadrature has converged; else finer spans.
        const int max = math::GaussPointsMax();
        const int nu = std::min(s->UDegree() + 3, max), nv = std::min(s->VDegree() + 3, max);
        for (int split = 1; split <= 8; split *= 2) {
            const AreaAndCentroid fine = integrate(s, r, nu, nv, split);
            const AreaAndCentroid coarse = integrate(s, r, nu - 1, nv - 1, split);
            if (fine.area > 0 && std::abs(fine.area - coarse.area) <= 1e-7 * fine.area) return fine;
        }
    }
    GProp_GProps g;
    BRepGProp::SurfaceProperties(face, g);
    return {g.Mass(), g.CentreOfMass()};
}

}  // namespace aeronc::impeller
