#include "ClearingMoves.h"

#include "Arcs.h"

#include <aeronc/core/Error.h>

#include <cmath>

namespace aeronc::toolpath {

namespace {

// Down a closed loop path[0..end] (path[end] == path[0]) at the ramp angle until `level`, then
// on round to the loop's end at the level.
void rampMoves(MoveWriter& w, const std::vector<Point>& path, std::size_t end, double level, double tanAngle) {
    const std::vector<Point> loop(path.begin(), path.begin() + long(end) + 1);
    const double perimeter = clip::length(loop);
    const double start = w.h();
    const double run = (start - level) / tanAngle;
    if (run / perimeter > 1e5) throw inputError("a ramp would go round its loop more than 10^5 times: raise rampAngle");
    double done = 0;
    std::size_t i = 1;
    while (true) {
        const Point& a = loop[i - 1];
        const Point& b = loop[i];
        const double l = clip::distance(a, b);
        if (done + l >= run) {
            const double t = l > 0 ? (run - done) / l : 1;
            w.feed(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), level);
            break;
        }
        done += l;
        w.feed(b, start - done * tanAngle);
        i = i + 1 < loop.size() ? i + 1 : 1;
    }
    for (; i < loop.size(); ++i) w.feed(loop[i], level);
}

}  // namespace

void chainMoves(MoveWriter& w, const Chain& chain, double level, double above, const EntrySettings& s) {
    const Point& first = chain.path.front();
    const double from = std::max(level, above + s.approach);
    w.rapidOver(first, s.clearancePlane, from);
    const double tanAngle = std::tan(s.rampAngleDeg * M_PI / 180);
    switch (chain.entry.kind) {
        case Entry::Kind::Helix: {
            const Entry& e = chain.entry;
            const double a0 = std::atan2(first[1] - e.centre[1], first[0] - e.centre[0]);
            const double sign = s.climb ? -1 : 1;  // climb: clockwise, the material outside on the left
            // Round by the angle that keeps every chord within the ramp angle.
            const double down = (from - level) / (e.radius * tanAngle) * chordFactor(e.radius, s.chordTolerance);
            helixMoves(w, e.centre, e.radius, a0, sign * down, level, s.chordTolerance);
            // Flat at the level, one full turn at least, back to the start.
            const double turns = std::ceil((down + 2 * M_PI) / (2 * M_PI) - 1e-9);
            helixMoves(w, e.centre, e.radius, a0 + sign * down, sign * (turns * 2 * M_PI - down), level,
                       s.chordTolerance);
            w.feed(first, level);  // exactly where the helix began
            break;
        }
        case Entry::Kind::Ramp:
            rampMoves(w, chain.path, chain.entry.rampEnd, level, tanAngle);
            break;
        case Entry::Kind::Plunge:
            w.plunge(first[0], first[1], level);
            break;
    }
    for (std::size_t i = 1; i < chain.path.size(); ++i) w.feed(chain.path[i], level);
}

void clearingMoves(MoveWriter& w, const ClearingPlan& plan, const std::vector<double>& levels, double top,
                   const EntrySettings& s) {
    for (std::size_t i = 0; i < levels.size(); ++i)
        for (const Chain& c : plan.chains) chainMoves(w, c, levels[i], i == 0 ? top : levels[i - 1], s);
}

}  // namespace aeronc::toolpath
