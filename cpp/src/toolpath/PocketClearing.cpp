#include <aeronc/toolpath/PocketClearing.h>

#include "ClearingMoves.h"
#include "PocketArea.h"
#include "Validate.h"

#include <aeronc/core/Error.h>
#include <aeronc/toolpath/FloorFillet.h>
#include <aeronc/toolpath/Levels.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace aeronc::toolpath {

namespace {

std::string mm(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%g mm", v);
    return b;
}

// Round the walls at the finishing allowance, level by level after the clearing: each loop is
// entered from the cleared side, at the point of the roughing boundary nearest its start.
void finishingMoves(MoveWriter& w, const clip::Paths& finish, const clip::Paths& rough,
                    const std::vector<double>& levels, double top, const EntrySettings& s) {
    for (const auto& path : finish) {
        Loop loop = clip::toLoop(path);
        if (s.climb) std::reverse(loop.begin(), loop.end());
        // Start in the middle of the longest edge: the straightest place to arrive at the wall.
        std::size_t longest = 0;
        for (std::size_t i = 0; i < loop.size(); ++i)
            if (clip::distance(loop[i], loop[(i + 1) % loop.size()]) >
                clip::distance(loop[longest], loop[(longest + 1) % loop.size()]))
                longest = i;
        const Point& a = loop[longest];
        const Point& b = loop[(longest + 1) % loop.size()];
        const clip::LoopPoint start{{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2}, longest, 0};
        const std::vector<Point> closed = clip::loopFrom(loop, start);
        // The cleared side: the nearest point of the roughing boundary.
        Point inside = start.at;
        double best = 1e300;
        for (const auto& r : rough) {
            const auto q = clip::nearestOnLoop(clip::toLoop(r), start.at);
            if (q.distance < best) best = q.distance, inside = q.at;
        }
        for (std::size_t i = 0; i < levels.size(); ++i) {
            if (i == 0) w.rapidOver(inside, s.clearancePlane, top + s.approach);
            w.plunge(inside[0], inside[1], levels[i]);
            for (const Point& p : closed) w.feed(p, levels[i]);
            w.feed(inside, levels[i]);
        }
    }
}

// One cutting level of the unit: the islands in the way there, and for a level at the top of
// lower islands, those islands (the level clears only around them).
struct Pass {
    double level = 0;
    double above = 0;  // where the material may start over it
    std::vector<bool> present;
    std::vector<bool> faced;  // empty: a whole level
    bool operator<(const Pass& o) const { return level > o.level; }
};

constexpr double kSame = 1e-6;  // mm: heights taken as one

std::vector<Pass> passesOf(const PocketUnit& unit, const PocketParameters& p) {
    const std::size_t n = unit.islands.size();
    if (!unit.islandTops.empty() && unit.islandTops.size() != n)
        throw inputError("islandTops needs one height (or none) per island");
    auto lower = [&](std::size_t i) { return !unit.islandTops.empty() && !std::isnan(unit.islandTops[i]); };
    for (std::size_t i = 0; i < n; ++i)
        if (lower(i)) requireFinite(unit.islandTops[i], "the top of island " + std::to_string(i + 1));
    const double aa = p.axialAllowance;
    // An island is in the way up to its top plus the floor's allowance.
    auto presentAt = [&](double z) {
        std::vector<bool> v(n, true);
        for (std::size_t i = 0; i < n; ++i)
            if (lower(i)) v[i] = unit.islandTops[i] + aa > z + kSame;
        return v;
    };
    std::vector<Pass> passes;
    const std::vector<double> regular = cuttingLevels(unit.top, unit.bottom + aa, p.stepDown);
    for (double z : regular) passes.push_back({z, 0, presentAt(z), {}});
    std::vector<double> tops;
    for (std::size_t i = 0; i < n; ++i)
        if (lower(i)) tops.push_back(unit.islandTops[i]);
    std::sort(tops.begin(), tops.end());
    tops.erase(std::unique(tops.begin(), tops.end(), [](double a, double b) { return b - a <= kSame; }), tops.end());
    for (double t : tops) {
        const double z = t + aa;
        // A floor unit faces every lower top; a clearing unit those between its top and floor
        // that no level meets already.
        if (unit.faceIslandTops) {
            if (!(t > unit.bottom + kSame)) continue;
        } else {
            if (!(z > unit.bottom + aa + kSame && z < unit.top - kSame)) continue;
            if (std::any_of(regular.begin(), regular.end(), [&](double r) { return std::fabs(r - z) <= kSame; }))
                continue;
        }
        Pass f{z, 0, presentAt(z), std::vector<bool>(n, false)};
        for (std::size_t i = 0; i < n; ++i) f.faced[i] = lower(i) && std::fabs(unit.islandTops[i] - t) <= kSame;
        passes.push_back(f);
    }
    std::stable_sort(passes.begin(), passes.end());
    // Around a lower island only, so over the rest the material starts at the last whole level.
    double lastWhole = entryTop(p, unit.top);
    for (Pass& ps : passes) {
        ps.above = lastWhole;
        // A floor unit's island top carries what the floor does.
        if (unit.faceIslandTops && !ps.faced.empty())
            ps.above = std::max(ps.above, ps.level + (unit.top - unit.bottom - aa));
        if (ps.faced.empty()) lastWhole = ps.level;
    }
    return passes;
}

struct PassPlan {
    clip::Paths centres;
    ClearingPlan plan;
};

}  // namespace

Toolpath pocketClearing(const PocketUnit& unit, const Cutter& cutter, const PocketParameters& p) {
    const double s = checkMilling(p, cutter, unit.top, unit.bottom);
    requireFinite(p.finishingAllowance, "finishingAllowance");
    if (p.finishingPass && (p.finishingAllowance > p.radialAllowance + 1e-12 ||
                            !(cutter.radius() + p.finishingAllowance > 0)))
        throw inputError("finishingAllowance must lie between -R and radialAllowance");
    const double R = cutter.radius(), tol = p.chordTolerance;
    const double fillet = floorFilletOffset(unit.floorFilletRadius, cutter.cornerRadius, p.radialAllowance);
    const double off = R + p.radialAllowance + fillet;
    const std::vector<Pass> passes = passesOf(unit, p);
    // Rapids clear the highest material: a floor unit's lower island tops stand over its top.
    double high = unit.top;
    for (const Pass& ps : passes) high = std::max(high, ps.above);
    if (high > unit.top) checkMilling(p, cutter, high, unit.bottom);

    ClearingOptions o;
    o.stepOver = s;
    o.reach = cutter.radius() - cutter.cornerRadius > 0.1 * R ? R - cutter.cornerRadius : R;
    o.chordTolerance = tol;
    o.helixRadius = 0.5 * R;
    o.minHelixRadius = 0.25 * R;
    o.maxEntryLink = cutter.diameter;
    o.climb = p.climb;
    // Over a lower island's top the tool's flat reaches past its edge by a quarter of its width.
    const double margin = 0.25 * std::max(R - cutter.cornerRadius, 0.1 * R);

    // The tool-centre region with the islands in the way (and the material they leave for a
    // plunge), once per set of islands.
    struct Centres {
        clip::Paths region, centres, entryArea;
    };
    std::map<std::vector<bool>, Centres> centresBySet;
    auto centresOf = [&](const std::vector<bool>& present) -> const Centres& {
        const auto found = centresBySet.find(present);
        if (found != centresBySet.end()) return found->second;
        PocketUnit inWay = unit;
        inWay.islands.clear();
        for (std::size_t i = 0; i < unit.islands.size(); ++i)
            if (present[i]) inWay.islands.push_back(unit.islands[i]);
        PocketArea area = pocketArea(inWay, 2 * off + p.clearance);
        Centres c;
        c.centres = clip::offset(area.region, -off, tol);
        // A cutter wider than a pocket open on adjacent sides (FTC-09's flanges) finds room only
        // round the corners between its open edges: those are taken open then, and only then
        // (beyond a corner there may be material, and the simulation judges what this cuts).
        if (!(clip::area(c.centres) > 0) && unit.openEdges.size() >= 2) {
            area = pocketArea(inWay, 2 * off + p.clearance, true);
            c.centres = clip::offset(area.region, -off, tol);
        }
        c.region = area.region;
        if (!(clip::area(c.centres) > 0))
            throw inputError("the cutter (D " + mm(cutter.diameter) + ", radial allowance " + mm(p.radialAllowance) +
                             ") does not fit in the pocket");
        // Beyond an open edge a plunge meets no material.
        if (!unit.openEdges.empty())
            c.entryArea = clip::subtract(c.centres, clip::offset(area.material, R + 2 * tol, tol));
        return centresBySet.emplace(present, std::move(c)).first->second;
    };
    std::map<std::pair<std::vector<bool>, std::vector<bool>>, PassPlan> plans;
    auto planOf = [&](const Pass& ps) -> const PassPlan& {
        const auto key = std::make_pair(ps.present, ps.faced);
        const auto found = plans.find(key);
        if (found != plans.end()) return found->second;
        const Centres& whole = centresOf(ps.present);
        PassPlan pp;
        pp.centres = whole.centres;
        clip::Paths entryArea = whole.entryArea;
        if (!ps.faced.empty()) {
            // Round the lower islands only: the centres within the margin of them.
            clip::Paths faced;
            for (std::size_t i = 0; i < unit.islands.size(); ++i)
                if (ps.faced[i]) {
                    clip::Path f = clip::toPath(unit.islands[i]);
                    if (!ClipperLib::Orientation(f)) ClipperLib::ReversePath(f);
                    faced.push_back(f);
                }
            const clip::Paths near = clip::offset(faced, margin, tol);
            pp.centres = clip::intersect(whole.centres, near);
            if (!entryArea.empty()) entryArea = clip::intersect(entryArea, near);
            if (!(clip::area(pp.centres) > 0))
                throw inputError("the cutter (D " + mm(cutter.diameter) + ") cannot reach the top of a lower island at " +
                                 mm(ps.level));
        }
        pp.plan = planClearing(pp.centres, pp.centres, entryArea, o);
        return plans.emplace(key, std::move(pp)).first->second;
    };

    const Heights hs = heightsOf(p, high);
    EntrySettings es;
    es.clearancePlane = hs.clearance;
    es.approach = std::min(p.clearance, 1.0);
    es.rampAngleDeg = p.rampAngleDeg;
    es.chordTolerance = tol;
    es.climb = p.climb;

    Toolpath tp;
    MoveWriter w(tp);
    const ClearingPlan& first = planOf(passes.front()).plan;
    w.rapid(first.chains.front().path.front()[0], first.chains.front().path.front()[1], hs.safe);
    for (const Pass& ps : passes) clearingMoves(w, planOf(ps).plan, {ps.level}, ps.above, es);
    if (p.finishingPass) {
        // Round the walls of each run of whole levels with the same islands in the way.
        const double finishFillet = floorFilletOffset(unit.floorFilletRadius, cutter.cornerRadius, p.finishingAllowance);
        for (std::size_t i = 0; i < passes.size();) {
            if (!passes[i].faced.empty()) {
                ++i;
                continue;
            }
            std::vector<double> levels;
            std::size_t j = i;
            for (; j < passes.size() && (!passes[j].faced.empty() || passes[j].present == passes[i].present); ++j)
                if (passes[j].faced.empty()) levels.push_back(passes[j].level);
            const Centres& whole = centresOf(passes[i].present);
            const clip::Paths finish = clip::offset(whole.region, -(R + p.finishingAllowance + finishFillet), tol);
            finishingMoves(w, finish, whole.centres, levels, entryTop(p, unit.top), es);
            i = j;
        }
    }
    w.retract(hs.safe);
    return tp;
}

}  // namespace aeronc::toolpath
