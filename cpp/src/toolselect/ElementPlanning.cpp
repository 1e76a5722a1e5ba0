#include <aeronc/toolselect/ElementPlanning.h>

#include <aeronc/core/Error.h>
#include <aeronc/core/SpindleSpeed.h>
#include <aeronc/recognition/SetupFrame.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace aeronc::toolselect {

using recognition::DomainElement;
using recognition::DomainTree;
using recognition::ElementType;

namespace {
constexpr double kDrillTol = 0.01;  // mm: a drill of the hole's diameter within this

std::string fmt(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

void appendError(std::string& to, const std::string& what) {
    if (!to.empty()) to += "\n";
    to += what;
}

// The tools a filter keeps, and where each came from in the full list.
struct Subset {
    std::vector<Tool> tools;
    std::vector<int> index;
};
Subset subset(const std::vector<Tool>& tools, const std::function<bool(const Tool&)>& keep) {
    Subset s;
    for (std::size_t i = 0; i < tools.size(); ++i)
        if (!keep || keep(tools[i])) s.tools.push_back(tools[i]), s.index.push_back(static_cast<int>(i));
    return s;
}
int indexOf(const Subset& s, const Tool* t) { return t ? s.index[static_cast<std::size_t>(t - s.tools.data())] : -1; }

}  // namespace

bool isMilled(ElementType type) {
    return type == ElementType::ClosedPocket || type == ElementType::OpenPocket || type == ElementType::Opening;
}

PocketGeometry pocketGeometry(const DomainElement& e, const Vec3& setupDirection) {
    if (!(norm(setupDirection) > 0))
        throw inputError("element " + std::to_string(e.id) + ": its setup direction is the zero vector");
    const recognition::SetupFrame frame(setupDirection);
    auto flat = [&](const recognition::Polyline& loop) {
        std::vector<std::array<double, 2>> out;
        out.reserve(loop.size());
        for (const Vec3& p : loop) {
            const recognition::P2 q = frame.project(p);
            out.push_back({q.x, q.y});
        }
        return out;
    };
    PocketGeometry g;
    g.outer = flat(e.contour);
    for (const recognition::Polyline& isl : e.islands) g.islands.push_back(flat(isl));
    g.depth = e.depth;
    g.minCornerRadius = e.minCornerRadius;  // < 0: no concave corner limits the tool
    g.floorFilletRadius = std::max(0.0, e.floorFilletRadius);
    g.open = e.type == ElementType::OpenPocket;
    g.name = "element " + std::to_string(e.id);
    return g;
}

CuttingData roughingCuttingData(const Tool& tool, double vc, double fz, double ap, double aeRatio, double delta,
                                double maxSpindleRpm) {
    CuttingData d;
    double n = spindleSpeed(vc, tool.diameter);  // r/min
    if (maxSpindleRpm > 0) n = std::min(n, maxSpindleRpm);
    d.ae = aeRatio * tool.diameter;
    d.feedPerMinute = fz * tool.flutes * n;
    d.ap = ap;
    d.delta = delta;
    return d;
}

ToolPlan planTools(const DomainTree& tree, const std::vector<Tool>& tools, const PlanSettings& settings) {
    ToolPlan plan;
    plan.tools = tools;
    const Subset finishers = subset(tools, settings.mayFinish);
    const Subset roughers = subset(tools, settings.mayRough);
    const Subset drills = subset(tools, settings.mayDrill);

    auto directionOf = [&](const DomainElement& e) -> Vec3 {
        for (const auto& s : tree.setups)
            if (s.id == e.setup) return s.direction;
        throw inputError("element " + std::to_string(e.id) + ": unknown setup " + std::to_string(e.setup));
    };

    for (const DomainElement& e : tree.elements) {
        if (isMilled(e.type)) {
            ElementChoice c;
            c.element = e.id;
            c.type = e.type;
            c.depth = e.depth;
            PocketGeometry g;
            try {
                g = pocketGeometry(e, directionOf(e));
            } catch (const Error& err) {
                c.error = err.what();
                plan.elements.push_back(c);
                continue;
            }
            try {
                c.finishingTool = indexOf(finishers, finishingTool(g, finishers.tools));
            } catch (const Error& err) {
                appendError(c.error, err.what());
            }
            try {
                c.roughingTool = indexOf(roughers, roughingTool(g, roughers.tools, settings.etaMin, &c.ratio));
            } catch (const Error& err) {
                appendError(c.error, err.what());
                // Deeper than every end mill reaches: the tool for as deep as the longest reaches.
                double longest = 0;
                for (const Tool& t : roughers.tools)
                    if (t.isEndMill()) longest = std::max(longest, t.usableLength());
                if (longest > 0 && longest < g.depth - 1e-6) {
                    PocketGeometry reached = g;
                    reached.depth = longest;
                    try {
                        c.partialRoughingTool = indexOf(roughers, roughingTool(reached, roughers.tools, settings.etaMin));
                        c.partialDepth = longest;
                    } catch (const Error&) {
                        // no tool for the region at all: listed as it is
                    }
                }
            }
            plan.elements.push_back(c);
        } else if (e.type == ElementType::Hole) {
            HoleChoice h;
            h.element = e.id;
            h.depth = e.hole ? e.hole->depth : e.depth;
            if (!e.hole || !(e.hole->diameter > 0)) {
                h.error = "hole element " + std::to_string(e.id) + ": no diameter was recognised";
                plan.holes.push_back(h);
                continue;
            }
            h.diameter = e.hole->diameter;
            const Tool* shortOne = nullptr;
            for (std::size_t i = 0; i < drills.tools.size() && h.drill < 0; ++i) {
                const Tool& t = drills.tools[i];
                if (t.type != "drill" || std::fabs(t.diameter - h.diameter) > kDrillTol) continue;
                if (t.usableLength() + 1e-6 < h.depth) {
                    if (!shortOne) shortOne = &t;
                    continue;
                }
                h.drill = drills.index[i];
            }
            if (h.drill < 0) {
                std::ostringstream m;
                m << "hole element " << e.id << ": ";
                if (shortOne)
                    m << "drill " << shortOne->id << " has the diameter " << fmt(h.diameter) << " mm but reaches only "
                      << fmt(shortOne->usableLength()) << " mm of the " << fmt(h.depth) << " mm depth";
                else
                    m << "no drill of diameter " << fmt(h.diameter) << " mm (+/- " << kDrillTol << " mm) among the "
                      << drills.tools.size() << " usable tools; it needs one reaching " << fmt(h.depth) << " mm";
                h.error = m.str();
            }
            plan.holes.push_back(h);
        }
    }

    // Group by roughing tool, largest tool first (the tool list order).
    std::map<int, std::size_t> groupOf;  // tool index -> group
    std::vector<ToolGroup> groups;
    for (const ElementChoice& c : plan.elements) {
        if (c.roughingTool < 0) continue;
        auto it = groupOf.find(c.roughingTool);
        if (it == groupOf.end()) {
            it = groupOf.emplace(c.roughingTool, groups.size()).first;
            groups.push_back({static_cast<std::size_t>(c.roughingTool), {}});
            plan.groupsBefore.push_back({c.roughingTool, {}});
        }
        groups[it->second].units.push_back({c.ratio.area, c.depth});
        plan.groupsBefore[it->second].elements.push_back(c.element);
    }
    if (!groups.empty() && !settings.roughingData)
        throw inputError("tool planning: no roughing cutting data to time the tool groups with");
    const auto merged = mergeGroups(groups, tools, settings.muMerge, settings.roughingData, &plan.merge);

    // Replay the merges on the element lists.
    std::map<int, std::vector<int>> members;
    for (const GroupElements& g : plan.groupsBefore) members[g.tool] = g.elements;
    for (const MergeReport::Step& s : plan.merge.merges) {
        auto& kept = members[static_cast<int>(s.keptTool)];
        auto& dropped = members[static_cast<int>(s.droppedTool)];
        kept.insert(kept.end(), dropped.begin(), dropped.end());
        members.erase(static_cast<int>(s.droppedTool));
    }
    for (const ToolGroup& g : merged) {
        GroupElements ge{static_cast<int>(g.tool), members[static_cast<int>(g.tool)]};
        std::sort(ge.elements.begin(), ge.elements.end());
        plan.groupsAfter.push_back(ge);
    }
    return plan;
}

}  // namespace aeronc::toolselect
