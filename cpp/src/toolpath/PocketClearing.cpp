#include <aeronc/toolpath/PocketClearing.h>

#include "ClearingMoves.h"
#include "PocketArea.h"
#include "Validate.h"

#include <aeronc/core/Error.h>
#include <aeronc/toolpath/FloorFillet.h>
#include <aeronc/toolpath/Levels.h>

#include <algorithm>
#include <cstdio>

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
    const PocketArea area = pocketArea(unit, 2 * off + p.clearance);
    const clip::Paths centres = clip::offset(area.region, -off, tol);
    if (!(clip::area(centres) > 0))
        throw inputError("the cutter (D " + mm(cutter.diameter) + ", radial allowance " + mm(p.radialAllowance) +
                         ") does not fit in the pocket");
    // Beyond an open edge a plunge meets no material.
    clip::Paths entryArea;
    if (!unit.openEdges.empty()) entryArea = clip::subtract(centres, clip::offset(area.material, R + 2 * tol, tol));

    ClearingOptions o;
    o.stepOver = s;
    o.reach = cutter.radius() - cutter.cornerRadius > 0.1 * R ? R - cutter.cornerRadius : R;
    o.chordTolerance = tol;
    o.helixRadius = 0.5 * R;
    o.minHelixRadius = 0.25 * R;
    o.maxEntryLink = cutter.diameter;
    o.climb = p.climb;
    const ClearingPlan plan = planClearing(centres, centres, entryArea, o);

    const std::vector<double> levels = cuttingLevels(unit.top, unit.bottom + p.axialAllowance, p.stepDown);
    const Heights hs = heightsOf(p, unit.top);
    EntrySettings es;
    es.clearancePlane = hs.clearance;
    es.approach = std::min(p.clearance, 1.0);
    es.rampAngleDeg = p.rampAngleDeg;
    es.chordTolerance = tol;
    es.climb = p.climb;

    Toolpath tp;
    MoveWriter w(tp);
    w.rapid(plan.chains.front().path.front()[0], plan.chains.front().path.front()[1], hs.safe);
    clearingMoves(w, plan, levels, unit.top, es);
    if (p.finishingPass) {
        const double finishFillet = floorFilletOffset(unit.floorFilletRadius, cutter.cornerRadius, p.finishingAllowance);
        const clip::Paths finish = clip::offset(area.region, -(R + p.finishingAllowance + finishFillet), tol);
        finishingMoves(w, finish, centres, levels, unit.top, es);
    }
    w.retract(hs.safe);
    return tp;
}

}  // namespace aeronc::toolpath
