#include <aeronc/chain/StockTops.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace aeronc::chain {

namespace {

// The steps that clear an element's whole region down to their bottom (plus the axial allowance).
bool clears(StepCode s) { return s == StepCode::Rough || s == StepCode::Web || s == StepCode::HoleMill; }

// The steps that take the allowance off an element's walls.
bool finishesWalls(StepCode s) {
    return s == StepCode::SemiWall || s == StepCode::SemiFlange || s == StepCode::FinishWall ||
           s == StepCode::FinishFlange;
}

double pointSegment(const Point2& p, const Point2& a, const Point2& b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

// Whether a point of `points` (each with its reach) comes within `gap` of a loop's edges.
bool within(const std::vector<std::pair<Point2, double>>& points, const std::vector<const Loop*>& loops, double gap) {
    for (const Loop* l : loops)
        for (std::size_t i = 0; i < l->size(); ++i)
            for (const auto& [p, reach] : points)
                if (pointSegment(p, (*l)[i], (*l)[(i + 1) % l->size()]) < reach + gap) return true;
    return false;
}

// Where a unit's cutter may go: its loops' corners (the cutter reaches the unit's walls), or its
// holes' centres with the hole's radius.
std::vector<std::pair<Point2, double>> footprint(const MachiningUnit& u) {
    std::vector<std::pair<Point2, double>> out;
    for (const HoleTarget& h : u.holes) out.push_back({{h.u, h.v}, 0.5 * h.diameter});
    if (!u.holes.empty()) return out;
    for (const Point2& p : u.contour) out.push_back({p, 0.0});
    for (const Loop& l : u.islands)
        for (const Point2& p : l) out.push_back({p, 0.0});
    return out;
}

}  // namespace

void setStockTops(MachiningChain& chain) {
    // Per element, the enabled clearing units in order: (order, the height they leave). A
    // roughing short of its element's floor is not counted on: the gate may leave it out alone.
    std::map<int, std::vector<std::pair<int, double>>> cleared;
    for (const MachiningUnit& u : chain.units)
        if (u.enabled && clears(u.step) && !u.shortOfFloor)
            cleared[u.element].push_back({u.order, u.bottom + u.axialAllowance});

    // What stands over an ancestor's region before unit `order` runs: its top, or the lowest
    // height its clearing units that ran before left.
    auto standing = [&](const ChainElement& a, int order) {
        double h = a.top;
        const auto it = cleared.find(a.id);
        if (it != cleared.end())
            for (const auto& [o, left] : it->second)
                if (o < order) h = std::min(h, left);
        return h;
    };

    // An ancestor's walls keep the radial allowance its roughing left until its wall steps take
    // it off. A unit reaching within that of the walls (a slot along the wall of the pocket it
    // opens from) meets it on the way down and in its rapids: the material stands there to the
    // ancestor's top. Two non-crossing segments are nearest at an end of one of them: corners of each
    // against the edges of the other.
    std::map<int, const MachiningUnit*> roughing;
    for (const MachiningUnit& u : chain.units)
        if (u.enabled && u.step == StepCode::Rough && !u.shortOfFloor) roughing[u.element] = &u;
    auto wallAllowance = [&](const ChainElement& a, int order) {
        const auto it = roughing.find(a.id);
        if (it == roughing.end()) return 0.0;
        double left = it->second->radialAllowance;
        for (const MachiningUnit& w : chain.units)
            if (w.enabled && w.element == a.id && finishesWalls(w.step) && w.order < order)
                left = std::min(left, w.radialAllowance);
        return left;
    };
    constexpr double kMargin = 0.05;  // mm
    auto besideWalls = [&](const MachiningUnit& u, const ChainElement& a) {
        const auto it = roughing.find(a.id);
        if (it == roughing.end() || it->second->setup != u.setup || it->second->order > u.order) return false;
        const double left = wallAllowance(a, u.order);
        if (!(left > 1e-9)) return false;
        std::vector<const Loop*> walls{&it->second->contour};
        for (const Loop& l : it->second->islands) walls.push_back(&l);
        if (within(footprint(u), walls, left + kMargin)) return true;
        if (!u.holes.empty() || u.contour.empty()) return false;
        std::vector<std::pair<Point2, double>> corners;
        for (const Loop* l : walls)
            for (const Point2& p : *l) corners.push_back({p, 0.0});
        std::vector<const Loop*> mine{&u.contour};
        for (const Loop& l : u.islands) mine.push_back(&l);
        return within(corners, mine, left + kMargin);
    };

    std::map<int, double> blankTops;
    for (const ChainSetup& s : chain.setups)
        if (s.blankTop) blankTops[s.id] = *s.blankTop;
    for (MachiningUnit& u : chain.units) {
        double top = u.top;
        const ChainElement* e = chain.element(u.element);
        if (e) {
            top = std::max(top, e->top);
            const ChainElement* root = e;
            int guard = 0;  // a parent loop in a damaged chain must not hang
            for (const ChainElement* a = chain.element(e->parent); a && guard < 64; a = chain.element(a->parent), ++guard)
                top = std::max({top, standing(*a, u.order), besideWalls(u, *a) ? a->top : top}), root = a;
            // Over a root below the blank's top (a pocket in a face another setup or nothing
            // here lowers) anything of the blank may still stand: come down at feed from there.
            const auto b = blankTops.find(e->setup);
            if (b != blankTops.end() && root->top < b->second - 1e-6) top = std::max(top, b->second);
        }
        u.stockTop.reset();
        if (top > u.top + 1e-9) u.stockTop = top;
    }
}

}  // namespace aeronc::chain
