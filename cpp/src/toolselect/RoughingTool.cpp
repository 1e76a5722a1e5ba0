#include "PocketRegion.h"

#include <aeronc/core/Error.h>
#include <aeronc/toolselect/Selection.h>

#include <algorithm>
#include <numeric>
#include <sstream>

namespace aeronc::toolselect {

const Tool* roughingTool(const PocketGeometry& pocket, const std::vector<Tool>& tools,
                         double etaThreshold, MachinableRatio* ratio) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < tools.size(); ++i) {
        tools[i].validate();
        if (tools[i].isEndMill() && tools[i].usableLength() >= pocket.depth - 1e-6) order.push_back(i);
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return tools[a].diameter > tools[b].diameter; });

    // The region is built once. An opening by a larger disc lies inside the opening by a
    // smaller one, so eta only grows down the list and a bisection finds the first tool
    // meeting the threshold in log2(n) evaluations instead of n.
    const PocketRegion region = makeRegion(pocket);
    auto etaOf = [&](std::size_t k) { return openRegion(region, tools[order[k]].radius()).machinableArea / region.area; };
    std::size_t lo = 0, hi = order.size();  // answer in [lo, hi]; hi: none
    double bestEta = -1;
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        const double eta = etaOf(mid);
        if (eta >= etaThreshold) hi = mid;
        else lo = mid + 1, bestEta = std::max(bestEta, eta);
    }
    if (hi < order.size()) {
        const Tool& t = tools[order[hi]];
        if (ratio) *ratio = machinableRatio(pocket, t.radius());
        return &t;
    }
    const double bestDiameter = order.empty() ? 0 : tools[order.back()].diameter;

    std::ostringstream m;
    m << "pocket '" << pocket.name << "': no roughing tool reaches eta >= " << etaThreshold;
    if (order.empty())
        m << "; none of the " << tools.size() << " tools is an end mill reaching the depth " << pocket.depth
          << " mm";
    else
        m << " with reach >= " << pocket.depth << " mm; the smallest, diameter " << bestDiameter
          << " mm, reaches eta " << bestEta << ", so a smaller tool is needed";
    throw inputError(m.str());
}

}  // namespace aeronc::toolselect
