#include <aeronc/toolpath/RestCorners.h>

#include "ClearingMoves.h"
#include "PocketArea.h"
#include "Validate.h"

#include <aeronc/core/Error.h>
#include <aeronc/toolpath/FloorFillet.h>
#include <aeronc/toolpath/Levels.h>

#include <algorithm>
#include <cmath>

namespace aeronc::toolpath {

Toolpath restCorners(const PocketUnit& unit, const Cutter& previous, const Cutter& cutter, const PocketParameters& p,
                     std::optional<double> previousAllowance) {
    const double s = checkMilling(p, cutter, unit.top, unit.bottom);
    checkCutter(previous, "the previous cutter");
    const double R = cutter.radius(), R0 = previous.radius(), a = p.radialAllowance, tol = p.chordTolerance;
    const double a0 = previousAllowance.value_or(a);
    if (!std::isfinite(a0) || a0 < 0) throw inputError("the previous unit's radial allowance must be a length >= 0");
    if (!(R < R0)) throw inputError("rest machining needs a cutter smaller than the previous one");
    // The same extension as the previous cutter's clearing had.
    const PocketArea area = pocketArea(unit, 2 * (R0 + a) + p.clearance);
    const double fillet = floorFilletOffset(unit.floorFilletRadius, cutter.cornerRadius, a);
    // Floor fillets meet in a mitre round a convex corner: both erosions keep off both walls there (Clip.h).
    auto erode = [&](const clip::Paths& region, double by, double chord) {
        return unit.floorFilletRadius > 0 ? clip::offsetMitred(region, -by, chord) : clip::offset(region, -by, chord);
    };
    const clip::Paths centres = erode(area.region, R + a + fillet, tol);
    if (!(clip::area(centres) > 0)) throw inputError("the rest-machining cutter does not fit in the pocket");
    // Where the rest lies needs no toolpath's precision: the cutter's centres stay in `centres`
    // whatever it is, and it sweeps R beyond the rest. Coarser arcs there make the offsets of
    // large cutters several times faster.
    const double coarse = 10 * tol;
    const clip::Paths reached = clip::offset(centres, R, coarse);
    // What the previous cutter cleared: its centres kept R0 + its own allowance (and its fillet
    // offset) off the walls, and it swept R0 round them. The coarse arcs of the erosion cut up to
    // `coarse` into the corners' circles, so the sweep is taken `coarse` narrower: the region is
    // never larger than what was cut.
    const double filletBefore = floorFilletOffset(unit.floorFilletRadius, previous.cornerRadius, a0);
    const clip::Paths reachedBefore =
        clip::offset(erode(area.region, R0 + a0 + filletBefore, coarse), R0 - coarse, coarse);
    // What is left, without the slivers that only rounding makes.
    const clip::Paths rest =
        clip::offset(clip::offset(clip::subtract(reached, reachedBefore), -2 * coarse, coarse), 2 * coarse, coarse);
    Toolpath tp;
    if (rest.empty()) return tp;

    // The centres from which the cutter touches the rest. Entries come down only where the
    // whole cutter stands in what the previous cutter cleared (its region eroded by R, and by
    // `coarse` for the arcs): the slivers dropped from the rest above are material too.
    const clip::Paths touching = clip::intersect(clip::offset(rest, R, coarse), centres);
    const clip::Paths cleared = clip::intersect(centres, clip::offset(reachedBefore, -(R + coarse), coarse));
    ClearingOptions o;
    o.stepOver = s;
    o.reach = R - cutter.cornerRadius > 0.1 * R ? R - cutter.cornerRadius : R;
    o.chordTolerance = tol;
    o.helixRadius = 0.5 * R;
    o.minHelixRadius = 0.25 * R;
    o.maxEntryLink = 2 * cutter.diameter;
    o.climb = p.climb;
    const ClearingPlan plan = planClearing(touching, centres, cleared, o);
    if (plan.chains.empty()) return tp;

    const std::vector<double> levels = cuttingLevels(unit.top, unit.bottom + p.axialAllowance, p.stepDown);
    const Heights hs = heightsOf(p, unit.top);
    EntrySettings es;
    es.clearancePlane = hs.clearance;
    es.approach = std::min(p.clearance, 1.0);
    es.rampAngleDeg = p.rampAngleDeg;
    es.chordTolerance = tol;
    es.climb = p.climb;
    MoveWriter w(tp);
    w.rapid(plan.chains.front().path.front()[0], plan.chains.front().path.front()[1], hs.safe);
    clearingMoves(w, plan, levels, unit.top, es);
    w.retract(hs.safe);
    return tp;
}

}  // namespace aeronc::toolpath
