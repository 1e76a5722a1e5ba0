#include "Validate.h"

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace aeronc::toolpath {

namespace {
constexpr double kMaxCoordinate = 1e6;  // mm; keeps Clipper's integers in their fast range
// mm: points closer than this to the last one kept are dropped. Sections of tessellated faces
// carry zigzags of a tenth of a micron that fold back on themselves; no cutter sees them.
constexpr double kSamePoint = 1e-3;

std::string fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

double cross(const Point& a, const Point& b, const Point& c) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

bool onSegment(const Point& p, const Point& a, const Point& b) {
    return std::min(a[0], b[0]) <= p[0] && p[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= p[1] &&
           p[1] <= std::max(a[1], b[1]);
}

// Do the closed segments ab and cd share a point? `eps` is the area below which three points
// count as collinear.
bool meet(const Point& a, const Point& b, const Point& c, const Point& d, double eps) {
    auto sgn = [eps](double x) { return x > eps ? 1 : x < -eps ? -1 : 0; };
    const int d1 = sgn(cross(a, b, c)), d2 = sgn(cross(a, b, d)), d3 = sgn(cross(c, d, a)), d4 = sgn(cross(c, d, b));
    if (d1 * d2 < 0 && d3 * d4 < 0) return true;
    return (d1 == 0 && onSegment(c, a, b)) || (d2 == 0 && onSegment(d, a, b)) || (d3 == 0 && onSegment(a, c, d)) ||
           (d4 == 0 && onSegment(b, c, d));
}
}  // namespace

void requireFinite(double value, const std::string& what) {
    if (!std::isfinite(value)) throw inputError(what + " is not a finite number");
}

Loop checkedLoop(const Loop& loop, const std::string& what) {
    Loop l;
    l.reserve(loop.size());
    for (const Point& p : loop) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1])) throw inputError(what + " has a non-finite coordinate");
        if (std::abs(p[0]) > kMaxCoordinate || std::abs(p[1]) > kMaxCoordinate)
            throw inputError(what + " lies beyond 10^6 mm of the origin");
        if (l.empty() || std::hypot(p[0] - l.back()[0], p[1] - l.back()[1]) > kSamePoint) l.push_back(p);
    }
    while (l.size() > 1 && std::hypot(l.front()[0] - l.back()[0], l.front()[1] - l.back()[1]) <= kSamePoint)
        l.pop_back();
    if (l.size() < 3) throw inputError(what + " needs at least 3 distinct points");
    double extent = 0;
    for (const Point& p : l) extent = std::max({extent, std::abs(p[0] - l[0][0]), std::abs(p[1] - l[0][1])});
    // Crossing or touching edges, by a sweep over the edges sorted by their lowest u.
    const std::size_t n = l.size();
    const double eps = 1e-12 * std::max(1.0, extent * extent);
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    auto lo = [&](std::size_t i) { return std::min(l[i][0], l[(i + 1) % n][0]); };
    auto hi = [&](std::size_t i) { return std::max(l[i][0], l[(i + 1) % n][0]); };
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return lo(i) < lo(j); });
    for (std::size_t x = 0; x < n; ++x) {
        const std::size_t i = order[x];
        const Point &a0 = l[i], &a1 = l[(i + 1) % n];
        for (std::size_t y = x + 1; y < n && lo(order[y]) <= hi(i); ++y) {
            const std::size_t j = order[y];
            const Point &b0 = l[j], &b1 = l[(j + 1) % n];
            if (std::max(a0[1], a1[1]) < std::min(b0[1], b1[1]) || std::max(b0[1], b1[1]) < std::min(a0[1], a1[1]))
                continue;
            const bool adjacent = (i + 1) % n == j || (j + 1) % n == i;
            bool bad;
            if (adjacent) {
                // Neighbours share a vertex; they are at fault only when one folds back onto the other.
                const Point& shared = (i + 1) % n == j ? a1 : b1;
                const Point& p = (i + 1) % n == j ? a0 : b0;
                const Point& q = (i + 1) % n == j ? b1 : a1;
                const double c = cross(p, shared, q);
                const double dot = (shared[0] - p[0]) * (q[0] - shared[0]) + (shared[1] - p[1]) * (q[1] - shared[1]);
                bad = std::abs(c) <= eps && dot < 0 && n > 3;
            } else {
                bad = meet(a0, a1, b0, b1, eps);
            }
            if (bad)
                throw inputError(what + " crosses or touches itself near (" + fmt(a0[0]) + ", " + fmt(a0[1]) + ")");
        }
    }
    double a = 0;
    for (std::size_t i = 0; i < n; ++i) a += l[i][0] * l[(i + 1) % n][1] - l[(i + 1) % n][0] * l[i][1];
    if (!(std::abs(a) / 2 > 1e-9 * std::max(1.0, extent * extent))) throw inputError(what + " has no area");
    return l;
}

void checkCutter(const Cutter& c, const std::string& what) {
    requireFinite(c.diameter, what + "'s diameter");
    requireFinite(c.cornerRadius, what + "'s corner radius");
    if (!(c.diameter > 0)) throw inputError(what + "'s diameter must be positive");
    if (c.cornerRadius < 0 || c.cornerRadius > c.radius() + 1e-9)
        throw inputError(what + "'s corner radius must lie between 0 and half the diameter");
}

double checkMilling(const CutParameters& p, const Cutter& cutter, double top, double bottom) {
    checkCutter(cutter);
    requireFinite(top, "top");
    requireFinite(bottom, "bottom");
    requireFinite(p.clearance, "clearance");
    requireFinite(p.stepDown, "stepDown");
    requireFinite(p.radialAllowance, "radialAllowance");
    requireFinite(p.axialAllowance, "axialAllowance");
    requireFinite(p.rampAngleDeg, "rampAngle");
    requireFinite(p.chordTolerance, "chordTolerance");
    if (p.safeHeight) requireFinite(*p.safeHeight, "safeHeight");
    if (p.stockTop) requireFinite(*p.stockTop, "stockTop");
    if (!(bottom < top)) throw inputError("bottom (" + fmt(bottom) + ") must lie below top (" + fmt(top) + ")");
    if (!(p.clearance > 0)) throw inputError("clearance must be positive");
    if (!(p.stepDown > 0)) throw inputError("stepDown must be positive");
    if (p.axialAllowance < 0 || !(bottom + p.axialAllowance < top))
        throw inputError("axialAllowance must be at least 0 and leave some depth to cut");
    if (!(cutter.radius() + p.radialAllowance > 0)) throw inputError("radialAllowance is more negative than the cutter radius");
    if (!(p.rampAngleDeg > 0 && p.rampAngleDeg <= 90)) throw inputError("rampAngle must lie in (0, 90] degrees");
    if (!(p.chordTolerance >= 1e-4 && p.chordTolerance <= cutter.radius() / 4))
        throw inputError("chordTolerance must lie between 0.0001 mm and a quarter of the cutter radius");
    const double s = p.stepOver ? *p.stepOver : cutter.radius();
    requireFinite(s, "stepOver");
    if (!(s > 0) || s > cutter.diameter + 1e-9)
        throw inputError("stepOver (" + fmt(s) + " mm) must be positive and at most the cutter diameter (" +
                         fmt(cutter.diameter) + " mm)");
    const double above = entryTop(p, top);
    if (p.safeHeight && *p.safeHeight < above + p.clearance - 1e-9)
        throw inputError("safeHeight (" + fmt(*p.safeHeight) + ") lies below " + (above > top ? "stockTop" : "top") +
                         " + clearance (" + fmt(above + p.clearance) + ")");
    return s;
}

double entryTop(const CutParameters& p, double top) { return p.stockTop ? std::max(top, *p.stockTop) : top; }

Heights heightsOf(const CutParameters& p, double top) {
    const double c = entryTop(p, top) + p.clearance;
    return {c, p.safeHeight ? *p.safeHeight : c};
}

}  // namespace aeronc::toolpath
