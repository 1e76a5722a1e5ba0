#include "PocketRegion.h"

#include <aeronc/core/Error.h>
#include <aeronc/toolselect/Selection.h>

#include <algorithm>
#include <numeric>
#include <optional>
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

    // The region is built once, and each diameter's opening at most once: tools of one
    // diameter share their eta. An opening by a larger disc lies inside the opening by a
    // smaller one, so eta only grows down the list. The largest diameter is tried first
    // (a roughing tool usually is one of the larger ones), then a bisection finds the first
    // diameter meeting the threshold in log2(n) more evaluations.
    const PocketRegion region = makeRegion(pocket);
    std::vector<std::size_t> firstOfGroup;  // index into order of each diameter's first tool
    for (std::size_t k = 0; k < order.size(); ++k)
        if (k == 0 || tools[order[k]].diameter != tools[order[k - 1]].diameter) firstOfGroup.push_back(k);
    std::vector<std::optional<Opening>> openings(firstOfGroup.size());
    auto opening = [&](std::size_t g) -> const Opening& {
        if (!openings[g]) openings[g] = openRegion(region, tools[order[firstOfGroup[g]]].radius());
        return *openings[g];
    };
    auto etaOf = [&](std::size_t g) { return opening(g).machinableArea / region.area; };
    const std::size_t groups = firstOfGroup.size();
    std::size_t lo = 0, hi = groups;  // answer in [lo, hi]; hi: none
    if (groups > 0) {
        if (etaOf(0) >= etaThreshold) hi = 0;
        else lo = 1;
    }
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (etaOf(mid) >= etaThreshold) hi = mid;
        else lo = mid + 1;
    }
    if (hi < groups) {
        const Tool& t = tools[order[firstOfGroup[hi]]];
        if (ratio) *ratio = machinableRatio(region, opening(hi), t.radius());
        return &t;
    }
    // None qualifies: the smallest diameter's eta is the best one.
    const double bestEta = groups > 0 ? etaOf(groups - 1) : -1;
    const double bestDiameter = order.empty() ? 0 : tools[order.back()].diameter;

    std::ostringstream m;
    m << "pocket '" << pocket.name << "': no roughing tool reaches eta >= " << etaThreshold;
    if (order.empty()) {
        // What it would need, beside what the crib has: the longest end mill's reach.
        double longest = 0;
        for (const Tool& t : tools)
            if (t.isEndMill()) longest = std::max(longest, t.usableLength());
        m << "; none of the " << tools.size() << " tools is an end mill reaching the depth " << pocket.depth
          << " mm (the longest reaches " << longest << " mm): it needs an end mill reaching " << pocket.depth
          << " mm";
    }
    else
        m << " with reach >= " << pocket.depth << " mm; the smallest, diameter " << bestDiameter
          << " mm, reaches eta " << bestEta << ", so a smaller tool is needed";
    throw inputError(m.str());
}

}  // namespace aeronc::toolselect
