#include "PocketArea.h"

#include "Validate.h"

#include <aeronc/core/Error.h>

#include <cmath>

namespace aeronc::toolpath {

namespace {
constexpr double kOnContour = 0.1;  // mm: how far an open edge may stray from the contour
}

PocketArea pocketArea(const PocketUnit& unit, double extension, bool openCorners) {
    const Loop contour = checkedLoop(unit.contour, "the contour");
    clip::Paths outer{clip::toPath(contour)};
    if (!ClipperLib::Orientation(outer[0])) ClipperLib::ReversePath(outer[0]);
    clip::Paths islands;
    for (std::size_t i = 0; i < unit.islands.size(); ++i)
        islands.push_back(clip::toPath(checkedLoop(unit.islands[i], "island " + std::to_string(i + 1))));

    PocketArea a;
    a.material = clip::subtract(outer, islands);
    if (!(clip::area(a.material) > 0)) throw inputError("the islands cover the whole pocket");

    clip::Paths extensions;
    for (std::size_t i = 0; i < unit.openEdges.size(); ++i) {
        const std::string what = "open edge " + std::to_string(i + 1);
        const Point& p = unit.openEdges[i].a;
        const Point& q = unit.openEdges[i].b;
        for (double c : {p[0], p[1], q[0], q[1]}) requireFinite(c, what + "'s coordinate");
        const double len = clip::distance(p, q);
        if (!(len > 1e-6)) throw inputError(what + " has no length");
        const Point mid{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2};
        if (clip::nearestOnLoop(contour, mid).distance > kOnContour)
            throw inputError(what + " does not lie on the contour");
        // Outward: the side of the edge away from the contour's inside.
        Point n{-(q[1] - p[1]) / len, (q[0] - p[0]) / len};
        const double probe = std::min(kOnContour * 2, len / 4);
        if (clip::contains(outer, {mid[0] + n[0] * probe, mid[1] + n[1] * probe})) n = {-n[0], -n[1]};
        // openCorners: where two open edges meet at a convex corner (a pocket open on two sides
        // of the blank), the rectangle runs on past that end, or the two rectangles would leave
        // the corner's quadrant out and a tool wider than the pocket could not pass round it.
        const Point t{(q[0] - p[0]) / len, (q[1] - p[1]) / len};
        auto beyond = [&](const Point& end, double sign) {
            if (!openCorners) return 0.0;
            for (std::size_t j = 0; j < unit.openEdges.size(); ++j) {
                if (j == i) continue;
                const auto& other = unit.openEdges[j];
                if (clip::distance(other.a, end) > kOnContour && clip::distance(other.b, end) > kOnContour) continue;
                const Point past{end[0] + sign * t[0] * probe, end[1] + sign * t[1] * probe};
                return clip::contains(outer, past) ? 0.0 : extension;
            }
            return 0.0;
        };
        const double before = beyond(p, -1), after = beyond(q, 1);
        const Point a{p[0] - t[0] * before, p[1] - t[1] * before}, b{q[0] + t[0] * after, q[1] + t[1] * after};
        // Starting a little inside, the rectangle overlaps the contour however it was rounded.
        const double in = kOnContour;
        Loop rect{{a[0] - n[0] * in, a[1] - n[1] * in},
                  {b[0] - n[0] * in, b[1] - n[1] * in},
                  {b[0] + n[0] * extension, b[1] + n[1] * extension},
                  {a[0] + n[0] * extension, a[1] + n[1] * extension}};
        clip::Path r = clip::toPath(rect);
        if (!ClipperLib::Orientation(r)) ClipperLib::ReversePath(r);
        extensions.push_back(r);
    }
    a.region = extensions.empty() ? a.material : clip::subtract(clip::unite(outer, extensions), islands);
    return a;
}

}  // namespace aeronc::toolpath
