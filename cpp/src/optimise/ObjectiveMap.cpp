#include <aeronc/optimise/ObjectiveMap.h>

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>

namespace aeronc::optimise {

namespace {

std::vector<double> logSpaced(double lo, double hi, int count) {
    std::vector<double> v(count);
    const double a = std::log(lo), b = std::log(hi);
    for (int i = 0; i < count; ++i) v[i] = std::exp(a + (b - a) * i / (count - 1));
    return v;
}

// Corners in order around the polygon (stepless): sorted by angle about their mean in log space.
std::vector<RegionPoint> ordered(std::vector<RegionPoint> pts) {
    if (pts.size() < 3) return pts;
    double cx = 0, cy = 0;
    for (const auto& p : pts) cx += std::log(p.n), cy += std::log(p.fz);
    cx /= pts.size(), cy /= pts.size();
    std::sort(pts.begin(), pts.end(), [&](const RegionPoint& a, const RegionPoint& b) {
        return std::atan2(std::log(a.fz) - cy, std::log(a.n) - cx) < std::atan2(std::log(b.fz) - cy, std::log(b.n) - cx);
    });
    // Corners where three limits meet appear more than once.
    std::vector<RegionPoint> out;
    for (const auto& p : pts)
        if (out.empty() || std::abs(std::log(p.n / out.back().n)) > 1e-9 || std::abs(std::log(p.fz / out.back().fz)) > 1e-9)
            out.push_back(p);
    return out;
}

}  // namespace

nlohmann::json objectiveMap(const Problem& p, const Solution& s, MapBox box) {
    validate(p);
    if (box.nCount < 2 || box.fzCount < 2 || box.nCount > 1000 || box.fzCount > 1000)
        throw inputError("the map needs 2 to 1000 points each way");
    if (!(box.spread > 1)) throw inputError("the map's spread must be more than 1");
    const Optimum& best = s.combined;
    const double nMin = std::max(p.machine.minSpindle, 1e-6), nMax = p.machine.maxSpindle;
    if (box.nLow <= 0) box.nLow = std::max(nMin, best.n / box.spread);
    if (box.nHigh <= 0) box.nHigh = std::min(nMax, best.n * box.spread);
    if (box.fzLow <= 0) box.fzLow = std::max(p.feedPerTooth.min, best.fz / box.spread);
    if (box.fzHigh <= 0) box.fzHigh = std::min(p.feedPerTooth.max, best.fz * box.spread);
    if (!(box.nLow < box.nHigh) || !(box.fzLow < box.fzHigh))
        throw inputError("the map's box is empty: n and f_z need low < high");

    const Region region = Region::of(p);
    const Posynomial f = combinedObjective(p, s.time.objective, s.cost.objective);
    const auto ns = logSpaced(box.nLow, box.nHigh, box.nCount), fzs = logSpaced(box.fzLow, box.fzHigh, box.fzCount);
    nlohmann::json values = nlohmann::json::array(), feasible = nlohmann::json::array();
    for (double fz : fzs) {
        nlohmann::json row = nlohmann::json::array(), ok = nlohmann::json::array();
        for (double n : ns) {
            row.push_back(f(n, fz));
            // Continuous in n: a gearbox's steps are drawn on top of the region.
            bool in = true;
            for (const auto& c : region.constraints()) in = in && c.utilisation(n, fz) <= 1 + kFeasibilityTolerance;
            ok.push_back(in);
        }
        values.push_back(row);
        feasible.push_back(ok);
    }
    nlohmann::json limits = nlohmann::json::array();
    for (const auto& c : region.constraints())
        limits.push_back({{"name", c.name},
                          {"symbol", c.symbol},
                          {"unit", c.unit},
                          {"coefficient", c.coefficient},
                          {"n_exp", c.nExp},
                          {"fz_exp", c.fzExp},
                          {"limit", c.limit},
                          {"upper", c.upper}});
    nlohmann::json corners = nlohmann::json::array();
    if (!region.stepped())
        for (const auto& c : ordered(region.corners())) corners.push_back({c.n, c.fz});
    return {{"n_rpm", ns},
            {"f_z_mm", fzs},
            {"objective", values},
            {"feasible", feasible},
            {"region", corners},
            {"spindle_steps_rpm", p.machine.spindleSteps},
            {"limits", limits},
            {"optimum", {{"n_rpm", best.n}, {"f_z_mm", best.fz}, {"objective", best.objective}}}};
}

}  // namespace aeronc::optimise
