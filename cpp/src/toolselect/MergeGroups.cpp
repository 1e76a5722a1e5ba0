#include <aeronc/core/Error.h>
#include <aeronc/toolselect/Selection.h>

#include <algorithm>

namespace aeronc::toolselect {

namespace {
double groupTime(const std::vector<MachiningUnit>& units, const CuttingData& d) {
    double s = 0;
    for (const MachiningUnit& u : units) s += unitTime(u.area, u.depth, d);
    return s;
}
double deepest(const std::vector<MachiningUnit>& units) {
    double h = 0;
    for (const MachiningUnit& u : units) h = std::max(h, u.depth);
    return h;
}
}  // namespace

std::vector<ToolGroup> mergeGroups(std::vector<ToolGroup> groups, const std::vector<Tool>& tools,
                                   double muThreshold, const CuttingDataOf& cuttingDataOf,
                                   MergeReport* report) {
    for (const ToolGroup& g : groups)
        if (g.tool >= tools.size())
            throw inputError("tool group refers to tool " + std::to_string(g.tool) + " of a list of " +
                             std::to_string(tools.size()));
    auto timeOf = [&](const ToolGroup& g) { return groupTime(g.units, cuttingDataOf(g.tool)); };
    auto total = [&] {
        double s = 0;
        for (const ToolGroup& g : groups) s += timeOf(g);
        return s;
    };
    MergeReport rep;
    rep.toolChangesBefore = std::max(0, static_cast<int>(groups.size()) - 1);
    rep.timeBefore = total();

    // Greedy: the best pair first, since each merge changes the times of later pairs.
    for (;;) {
        double bestMu = muThreshold;
        std::size_t bi = 0, bj = 0;
        bool found = false;
        for (std::size_t i = 0; i < groups.size(); ++i)
            for (std::size_t j = i + 1; j < groups.size(); ++j) {
                const Tool& ti = tools[groups[i].tool];
                const Tool& tj = tools[groups[j].tool];
                // The smaller tool keeps the units; ties go to the lower tool index.
                const bool iSmaller = ti.diameter < tj.diameter ||
                                      (ti.diameter == tj.diameter && groups[i].tool <= groups[j].tool);
                const std::size_t k = iSmaller ? i : j, other = iSmaller ? j : i;
                if (tools[groups[k].tool].usableLength() < deepest(groups[other].units)) continue;
                const CuttingData dk = cuttingDataOf(groups[k].tool);
                const double tk = groupTime(groups[i].units, dk) + groupTime(groups[j].units, dk);
                const double mu = tk > 0 ? (timeOf(groups[i]) + timeOf(groups[j])) / tk : 1.0;
                if (mu > bestMu) bestMu = mu, bi = k, bj = other, found = true;
            }
        if (!found) break;
        rep.merges.push_back({groups[bi].tool, groups[bj].tool, bestMu});
        auto& kept = groups[bi].units;
        kept.insert(kept.end(), groups[bj].units.begin(), groups[bj].units.end());
        groups.erase(groups.begin() + static_cast<std::ptrdiff_t>(bj));
    }
    rep.toolChangesAfter = std::max(0, static_cast<int>(groups.size()) - 1);
    rep.timeAfter = total();
    if (report) *report = rep;
    return groups;
}

}  // namespace aeronc::toolselect
