// Channel roughing in layers between adjacent blades (see Strategies.h).
#include "Strategies.h"

#include <algorithm>
#include <cmath>

namespace aeronc::impellerpath {

void roughChannel(const Channel& ch, const CutterShape& cut, const PathOptions& opt, const Links& links,
                  CheckResult& res, std::vector<Move>& out) {
    Checker check{ch, cut, opt, res, opt.roughAllowance};
    const double R = cut.tipRadius, keep = R + opt.roughAllowance;
    const double r0 = ch.rMin() + keep, r1 = ch.rMax() - keep;
    const auto rs = stations(r0, r1, opt.stations);
    // The lowest centre at each station: `keep` from the hub along its normal (the hub slopes,
    // so that is more than `keep` along the axis).
    std::vector<double> floor;
    for (double r : rs) {
        const double theta = 0.5 * (ch.guessTheta(false, r) + ch.guessTheta(true, r));
        const Vec3 onHub = ch.frame().at(r, theta, ch.hubZ(r));
        floor.push_back(ch.hubZ(r) + keep / std::max(0.3, ch.hubNormal(onHub).dot(ch.frame().z())));
    }
    // Layers from the shroud down, by depth below it.
    double deepest = 0;
    for (size_t i = 0; i < rs.size(); ++i) deepest = std::max(deepest, ch.shroudZ(rs[i]) - floor[i]);
    const int layers = std::max(1, static_cast<int>(std::ceil(deepest / opt.stepDown)));
    for (int k = 1; k <= layers; ++k) {
        // Lanes across the channel at this layer: as many as the narrowest station needs.
        std::vector<double> zs, ta, tb;
        double gA = ch.guessTheta(false, rs.front()), gB = ch.guessTheta(true, rs.front());
        int lanes = 1;
        for (size_t i = 0; i < rs.size(); ++i) {
            const double r = rs[i];
            const double z = std::max(ch.shroudZ(r) - std::min(k * opt.stepDown, deepest), floor[i]);
            gA = ch.wallTheta(false, r, z, gA);
            gB = ch.wallTheta(true, r, z, gB);
            zs.push_back(z), ta.push_back(gA), tb.push_back(gB);
            const double width = r * (gB - gA) - 2 * keep;
            lanes = std::max(lanes, 1 + static_cast<int>(std::ceil(std::max(width, 0.0) / (opt.stepOver * 2 * R))));
        }
        for (int l = 0; l < lanes; ++l) {
            const double u = lanes == 1 ? 0.5 : static_cast<double>(l) / (lanes - 1);
            std::vector<Move> pass;
            for (size_t i = 0; i < rs.size(); ++i) {
                const size_t j = l % 2 ? rs.size() - 1 - i : i;  // zig-zag
                const double r = rs[j];
                // Clear of both walls by the ball and the allowance, normal to each wall (a
                // wrapped wall meets the arc at a slant, so the arc needs more than that).
                const double lo = ta[j] + arcMargin(ch, false, r, ta[j], zs[j], keep) / r;
                const double hi = tb[j] - arcMargin(ch, true, r, tb[j], zs[j], keep) / r;
                if (hi < lo) continue;  // the channel is narrower than the ball here
                const double theta = lerp(lo, hi, u);
                const Vec3 c = ch.frame().at(r, theta, zs[j]);
                check.add(pass, c, blendedAxis(ch, r, zs[j], ta[j], tb[j], (theta - ta[j]) / (tb[j] - ta[j])), links, out);
            }
            links.append(out, pass, check);
        }
    }
}

}  // namespace aeronc::impellerpath
