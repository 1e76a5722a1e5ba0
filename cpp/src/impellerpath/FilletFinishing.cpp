// Fillet finishing along the root of each wall (see Strategies.h).
#include "Strategies.h"

#include <algorithm>
#include <cmath>

namespace aeronc::impellerpath {

void finishFillet(const Channel& ch, bool b, const CutterShape& cut, double filletRadius, const PathOptions& opt,
                  const Links& links, CheckResult& res, std::vector<Move>& out) {
    Checker check{ch, cut, opt, res};
    const Wall& w = ch.wall(b);
    const double R = cut.tipRadius, target = std::max(R, filletRadius);
    const double tilt = 10 * kPi / 180;
    std::vector<Move> pass;
    const auto rs = stations(w.rMin + target + 1, w.rMax - target - 1, opt.stations);
    for (size_t i = 0; i < rs.size(); ++i) {
        const double r = rs[b ? rs.size() - 1 - i : i];  // climb milling either side: A outwards, B inwards
        const double z0 = ch.hubZ(r) + target;
        Vec3 x = ch.frame().at(r, ch.wallTheta(b, r, z0, ch.guessTheta(b, r)), z0), nW, nH;
        ch.wallDistance(b, x, nW);
        x += target * nW;
        bool converged = false;
        for (int it = 0; it < 30 && !converged; ++it) {
            const double ew = target - ch.wallDistance(b, x, nW), eh = target - ch.hubDistance(x, nH);
            const double c = nW.dot(nH);
            if (1 - c * c < 1e-6) break;  // wall and hub parallel: no corner here
            x += (ew - c * eh) / (1 - c * c) * nW + (eh - c * ew) / (1 - c * c) * nH;
            converged = std::abs(ew) < 1e-7 && std::abs(eh) < 1e-7;
        }
        if (!converged) continue;
        const Vec3 centre = x - (target - R) * (nW + nH).normalized();
        Vec3 ruling, normal;
        ch.wallFrame(b, centre, ruling, normal);
        check.add(pass, centre, (std::cos(tilt) * ruling + std::sin(tilt) * normal).normalized(), links, out);
    }
    links.append(out, pass, check);
}

}  // namespace aeronc::impellerpath
