#include "Arcs.h"

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>

namespace aeronc::toolpath {

std::size_t arcSegments(double radius, double angle, double chordTolerance) {
    const double a = std::abs(angle);
    if (radius <= chordTolerance) return std::max<std::size_t>(1, std::size_t(std::ceil(a / (M_PI / 2))));
    const double step = 2 * std::acos(1 - chordTolerance / radius);
    const double n = std::ceil(a / step - 1e-9);
    if (n > 1e6) throw inputError("an arc needs more than 10^6 segments: raise the chord tolerance or the ramp angle");
    return std::max<std::size_t>(1, std::size_t(n));
}

double chordFactor(double radius, double chordTolerance) {
    if (radius <= chordTolerance) return M_PI / 2 / std::sqrt(2.0);
    const double step = 2 * std::acos(1 - chordTolerance / radius);
    return step / (2 * std::sin(step / 2));
}

Point onCircle(const Point& c, double r, double a) { return {c[0] + r * std::cos(a), c[1] + r * std::sin(a)}; }

double helixMoves(MoveWriter& w, const Point& centre, double radius, double a0, double angle, double hEnd,
                  double chordTolerance) {
    const std::size_t n = arcSegments(radius, angle, chordTolerance);
    const double h0 = w.h();
    for (std::size_t i = 1; i <= n; ++i) {
        const double t = double(i) / n;
        const Point p = onCircle(centre, radius, a0 + angle * t);
        w.feed(p[0], p[1], i == n ? hEnd : h0 + (hEnd - h0) * t);
    }
    return a0 + angle;
}

}  // namespace aeronc::toolpath
