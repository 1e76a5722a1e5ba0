// A unit's geometry in its setup's frame (see UnitOutline.h).
#include "UnitOutline.h"

#include "ElementTools.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace aeronc::chain::detail {

namespace {

double signedArea(const Loop& l) {
    double a = 0;
    for (std::size_t i = 0; i < l.size(); ++i) {
        const Point2& p = l[i];
        const Point2& q = l[(i + 1) % l.size()];
        a += p[0] * q[1] - q[0] * p[1];
    }
    return 0.5 * a;
}

Point2 centroid(const Loop& l) {
    const double a = signedArea(l);
    if (std::fabs(a) < 1e-9) {
        Point2 m{0, 0};
        for (const Point2& p : l) m[0] += p[0], m[1] += p[1];
        if (!l.empty()) m[0] /= static_cast<double>(l.size()), m[1] /= static_cast<double>(l.size());
        return m;
    }
    double cx = 0, cy = 0;
    for (std::size_t i = 0; i < l.size(); ++i) {
        const Point2& p = l[i];
        const Point2& q = l[(i + 1) % l.size()];
        const double c = p[0] * q[1] - q[0] * p[1];
        cx += (p[0] + q[0]) * c;
        cy += (p[1] + q[1]) * c;
    }
    return {cx / (6 * a), cy / (6 * a)};
}

}  // namespace

void outlineUnit(MachiningUnit& u, const recognition::DomainElement& e, const recognition::SetupFrame& frame,
                 double ceiling, double top, double bottom) {
    using recognition::ElementType;
    auto flat = [&](const recognition::Polyline& loop, bool ccw) {
        Loop out;
        out.reserve(loop.size());
        for (const Vec3& p : loop) {
            const recognition::P2 q = frame.project(p);
            out.push_back({q.x, q.y});
        }
        if (out.size() > 1 && std::hypot(out.front()[0] - out.back()[0], out.front()[1] - out.back()[1]) < 1e-9)
            out.pop_back();
        if ((signedArea(out) > 0) != ccw) std::reverse(out.begin(), out.end());
        return out;
    };
    u.contour = flat(e.contour, true);
    for (const auto& isl : e.islands) u.islands.push_back(flat(isl, false));
    // Island tops inside this element's own cavity (above its floor, below its top and the
    // parent's floor): a parent's island reaching down into a child is the parent's to face.
    const bool floorless = e.type == ElementType::Opening || e.type == ElementType::Hole;
    if (u.operation == Operation::Pocket && e.islandTops.size() == e.islands.size() && !floorless) {
        ceiling -= kTol;
        std::vector<double> tops(e.islands.size(), std::numeric_limits<double>::quiet_NaN());
        bool lower = false;
        for (std::size_t i = 0; i < tops.size(); ++i)
            if (e.islandTops[i] < ceiling && e.islandTops[i] > e.level + kTol) tops[i] = e.islandTops[i], lower = true;
        if (lower) u.islandTops = std::move(tops);
    }
    for (const auto& [a, b] : e.openEdges) {
        const recognition::P2 p = frame.project(a), q = frame.project(b);
        u.openEdges.push_back({Point2{p.x, p.y}, Point2{q.x, q.y}});
    }
    u.at = centroid(u.contour);
    if (e.hole) {
        const recognition::P2 c = frame.project(e.hole->location);
        u.at = {c.x, c.y};
        u.holes.push_back({c.x, c.y, e.hole->diameter, top, bottom, e.hole->through,
                           e.hole->through ? 0.0 : std::max(0.0, e.floorFilletRadius)});
    }
}

}  // namespace aeronc::chain::detail
