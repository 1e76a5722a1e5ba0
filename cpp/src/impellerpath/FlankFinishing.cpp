// Flank finishing of the blade walls (see Strategies.h).
#include "Strategies.h"

#include <BRepTools.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>

#include <algorithm>
#include <cmath>

namespace aeronc::impellerpath {

void finishWall(const Channel& ch, bool b, const CutterShape& cut, const PathOptions& opt, const Links& links,
                CheckResult& res, std::vector<Move>& out) {
    Checker check{ch, cut, opt, res};
    const Wall& w = ch.wall(b);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(w.face, u0, u1, v0, v1);
    // The ruling parameter: the one whose iso-lines run up the wall.
    Vec3 ruling, normal;
    double pu, pv;
    ch.wallFrame(b, w.samples[w.samples.size() / 2], ruling, normal, &pu, &pv);
    gp_Pnt q;
    gp_Vec du, dv;
    w.surface->D1(pu, pv, q, du, dv);
    const bool alongV = std::abs(dv.Normalized().Dot(gp_Vec(ch.frame().z().x(), ch.frame().z().y(), ch.frame().z().z()))) >
                        std::abs(du.Normalized().Dot(gp_Vec(ch.frame().z().x(), ch.frame().z().y(), ch.frame().z().z())));
    const double a0 = alongV ? u0 : v0, a1 = alongV ? u1 : v1;
    const double sina = std::sin(cut.taperDeg * kPi / 180), cosa = std::cos(cut.taperDeg * kPi / 180);
    std::vector<Move> pass;
    const int n = opt.stations;
    for (int i = 0; i < n; ++i) {
        const double a = lerp(a0, a1, 0.06 + 0.88 * i / (n - 1));
        gp_Pnt2d foot;
        BRepTopAdaptor_FClass2d cls(w.face, 1e-7);
        bool found = false;
        // Lowest point of this ruling on the face.
        const double b0 = alongV ? v0 : u0, b1 = alongV ? v1 : u1;
        double lowest = 1e300;
        for (int k = 0; k <= 200; ++k) {
            const double t = lerp(b0, b1, k / 200.0);
            const gp_Pnt2d uv = alongV ? gp_Pnt2d(a, t) : gp_Pnt2d(t, a);
            if (cls.Perform(uv) != TopAbs_IN) continue;
            const gp_Pnt p = w.surface->Value(uv.X(), uv.Y());
            const double z = ch.frame().axial(Vec3(p.X(), p.Y(), p.Z()));
            if (z < lowest) lowest = z, foot = uv, found = true;
        }
        if (!found) continue;
        const gp_Pnt p = w.surface->Value(foot.X(), foot.Y());
        const Vec3 P(p.X(), p.Y(), p.Z());
        ch.wallFrame(b, P, ruling, normal);
        // The cone's generator on the wall side then runs along the ruling: flank contact.
        const Vec3 axis = (cosa * ruling + sina * normal).normalized();
        const double r = ch.frame().radius(P);
        // Keep the ball at the wall's foot, clear of the hub by its radius.
        const Vec3 c = P + cut.tipRadius * normal;
        double hub;
        if (!ch.hubBelow(r, hub)) continue;  // the wall's foot on a nose or a rim, not in the channel
        if (ch.frame().axial(c) - hub < cut.tipRadius - 1e-6) continue;
        check.add(pass, c, axis, links, out);
    }
    links.append(out, pass, check);
}

}  // namespace aeronc::impellerpath
