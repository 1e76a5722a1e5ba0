#include <aeronc/toolpath/HelicalHole.h>

#include "Arcs.h"
#include "HoleChecks.h"
#include "Validate.h"

#include <aeronc/core/Error.h>
#include <aeronc/toolpath/FloorFillet.h>

#include <algorithm>
#include <cmath>

namespace aeronc::toolpath {

namespace {

// The rings of a hole wider than twice its cutter: levels at most stepDown apart; at each, a helix
// down round a circle inside the cutter's radius (so the axis is cut), a turn there, then circles
// at most a step-over apart out to the roughing radius at that height. Returns the end angle, at
// the floor on the outer circle.
template <class RoughAt>
double ringLevels(MoveWriter& w, const Heights& hs, const Hole& h, double R, double start, double floor,
                  const RoughAt& roughAt, const HelicalHoleParameters& p, double a, double sign) {
    const double tol = p.chordTolerance;
    const double inner = 0.5 * R;
    const double step = std::min(p.stepOver.value_or(R), 1.5 * R);
    const double tanAngle = std::tan(p.rampAngleDeg * M_PI / 180);
    const double pitch = std::min(p.stepDown, 2 * M_PI * inner * tanAngle / chordFactor(inner, tol));
    const std::size_t levels = static_cast<std::size_t>(std::ceil((start - floor) / p.stepDown - 1e-9));
    if ((start - floor) / pitch > 1e5) throw inputError("a hole's rings would take more than 10^5 helix turns");
    const Point first = onCircle(h.centre, inner, a);
    if (!w.started()) w.rapid(first[0], first[1], hs.safe);
    w.rapidOver(first, hs.clearance, start);
    for (std::size_t j = 1; j <= levels; ++j) {
        const double level = j == levels ? floor : start - (start - floor) * double(j) / double(levels);
        a = helixMoves(w, h.centre, inner, a, sign * 2 * M_PI * (w.h() - level) / pitch, level, tol);
        a = helixMoves(w, h.centre, inner, a, sign * 2 * M_PI, level, tol);  // the ramp's foot
        const double outer = roughAt(level - floor);
        const std::size_t rings = static_cast<std::size_t>(std::ceil((outer - inner) / step - 1e-9));
        for (std::size_t k = 1; k <= rings; ++k) {
            const double r = inner + (outer - inner) * double(k) / double(rings);
            w.feed(onCircle(h.centre, r, a), level);
            a = helixMoves(w, h.centre, r, a, sign * 2 * M_PI, level, tol);
        }
        if (j < levels) w.feed(onCircle(h.centre, inner, a), level);  // back in, over what the rings cleared
    }
    return a;
}

}  // namespace

Toolpath helicalHole(const std::vector<Hole>& holes, const Cutter& cutter, const HelicalHoleParameters& p) {
    checkHoles(holes);
    double top = holes.front().top;
    for (const Hole& h : holes) top = std::max(top, h.top);
    for (const Hole& h : holes) checkMilling(p, cutter, h.top, h.bottom);
    requireFinite(p.finishingAllowance, "finishingAllowance");
    requireFinite(p.breakThrough, "breakThrough");
    if (p.finishingAllowance > p.radialAllowance + 1e-12)
        throw inputError("finishingAllowance must be at most radialAllowance");
    if (p.breakThrough < 0) throw inputError("breakThrough must be at least 0");
    const double R = cutter.radius(), tol = p.chordTolerance;
    const Heights hs = heightsOf(p, top);
    const double approach = std::min(p.clearance, 1.0);
    const double tanAngle = std::tan(p.rampAngleDeg * M_PI / 180);
    const double sign = p.climb ? -1 : 1;  // climb: clockwise, the wall on the left

    Toolpath tp;
    MoveWriter w(tp);
    for (std::size_t i = 0; i < holes.size(); ++i) {
        const Hole& h = holes[i];
        const std::string what = "hole " + std::to_string(i + 1);
        const double rough = h.diameter / 2 - R - p.radialAllowance;
        const double finish = h.diameter / 2 - R - p.finishingAllowance;
        if (!(rough > tol))
            throw inputError(what + " (diameter " + std::to_string(h.diameter) +
                             " mm) is not larger than the cutter and its allowance: drill it instead");
        const double floor = h.through ? h.bottom - p.breakThrough - cutter.cornerRadius : h.bottom + p.axialAllowance;
        if (!(floor < h.top)) throw inputError(what + ": the axial allowance leaves nothing to cut");
        // A blind hole's floor fillet holds the cutter off the wall near the floor, as on a
        // pocket's walls (FloorFillet.h): the radius at a height above the floor.
        const double rf = h.through ? 0.0 : h.floorFilletRadius;
        requireFinite(rf, what + "'s floor fillet radius");
        auto roughAt = [&](double above) {
            return rough - wallFilletOffset(rf, cutter.cornerRadius, p.radialAllowance, std::max(0.0, above));
        };
        const double roughFloor = roughAt(0);
        const double finishFloor = finish - floorFilletOffset(rf, cutter.cornerRadius, p.finishingAllowance);
        if (!(roughFloor > tol) || !(finishFloor > tol))
            throw inputError(what + ": its floor fillet (radius " + std::to_string(rf) +
                             " mm) leaves the cutter no room to go round at the floor");
        const double start = entryTop(p, h.top) + approach;
        const double a0 = M_PI;  // start on the -u side
        double a = a0;
        if (rough > R) {
            // A cutter under half the hole would leave a core round the axis (a slug that drops
            // at the break-through of a through hole): level by level, a helix near the axis,
            // then rings out to the wall.
            a = ringLevels(w, hs, h, R, start, floor, roughAt, p, a0, sign);
        } else {
            // Pitch: at most the step-down, and no steeper than the ramp angle on the helix.
            const double pitch = std::min(p.stepDown, 2 * M_PI * rough * tanAngle / chordFactor(rough, tol));
            const double turns = (start - floor) / pitch;
            if (turns > 1e5) throw inputError(what + ": the helix would take more than 10^5 turns");
            const Point first = onCircle(h.centre, rough, a0);
            if (!w.started()) w.rapid(first[0], first[1], hs.safe);
            w.rapidOver(first, hs.clearance, start);
            // Down at the full radius to where the fillet begins to bind, then drawn in by it.
            const double band = std::min(start - floor, std::max(0.0, rf - cutter.cornerRadius - p.radialAllowance));
            a = helixMoves(w, h.centre, rough, a0, sign * 2 * M_PI * (start - floor - band) / pitch, floor + band, tol);
            if (band > 0) {
                const double angle = sign * 2 * M_PI * band / pitch;
                const std::size_t n = arcSegments(rough, std::fabs(angle), tol);
                const double h0 = w.h();
                for (std::size_t k = 1; k <= n; ++k) {
                    const double t = double(k) / n;
                    const double hk = k == n ? floor : h0 + (floor - h0) * t;
                    w.feed(onCircle(h.centre, roughAt(hk - floor), a + angle * t), hk);
                }
                a += angle;
            }
            a = helixMoves(w, h.centre, roughFloor, a, sign * 2 * M_PI, floor, tol);  // the flat turn at the bottom
        }
        // Straight out to the finishing radius, once round, and in to the centre, off the wall.
        const Point out = onCircle(h.centre, finishFloor, a);
        w.feed(out, floor);
        a = helixMoves(w, h.centre, finishFloor, a, sign * 2 * M_PI, floor, tol);
        w.feed(h.centre, floor);
        w.retract(hs.clearance);
    }
    w.retract(hs.safe);
    return tp;
}

}  // namespace aeronc::toolpath
