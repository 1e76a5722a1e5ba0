// Hub finishing between the root fillets (see Strategies.h).
#include "Strategies.h"

#include <algorithm>
#include <cmath>

namespace aeronc::impellerpath {

void finishHub(const Channel& ch, const CutterShape& cut, double filletRadius, const PathOptions& opt,
               const Links& links, CheckResult& res, std::vector<Move>& out) {
    Checker check{ch, cut, opt, res};
    const double R = cut.tipRadius, keep = R + filletRadius;
    const auto rs = stations(ch.rMin() + keep, ch.rMax() - keep, opt.stations);
    // Lanes across the hub between the fillets, the step at most finishStep at the narrowest.
    std::vector<double> ta, tb, zh;
    double gA = ch.guessTheta(false, rs.front()), gB = ch.guessTheta(true, rs.front());
    double widest = 0;
    for (double r : rs) {
        const double z = ch.hubZ(r) + R;
        gA = ch.wallTheta(false, r, z, gA), gB = ch.wallTheta(true, r, z, gB);
        ta.push_back(gA), tb.push_back(gB), zh.push_back(z);
        widest = std::max(widest, r * (gB - gA) - 2 * keep);
    }
    const int lanes = std::max(2, 1 + static_cast<int>(std::ceil(widest / opt.finishStep)));
    for (int l = 0; l < lanes; ++l) {
        const double u = static_cast<double>(l) / (lanes - 1);
        std::vector<Move> pass;
        for (size_t i = 0; i < rs.size(); ++i) {
            const size_t j = l % 2 ? rs.size() - 1 - i : i;
            const double r = rs[j];
            const double lo = ta[j] + arcMargin(ch, false, r, ta[j], zh[j], keep) / r;
            const double hi = tb[j] - arcMargin(ch, true, r, tb[j], zh[j], keep) / r;
            if (hi < lo) continue;
            const double theta = lerp(lo, hi, u);
            const Vec3 onHub = ch.frame().at(r, theta, ch.hubZ(r));
            const Vec3 n = ch.hubNormal(onHub);
            check.add(pass, onHub + R * n, blendedAxis(ch, r, zh[j], ta[j], tb[j], (theta - ta[j]) / (tb[j] - ta[j])), links, out);
        }
        links.append(out, pass, check);
    }
}

}  // namespace aeronc::impellerpath
