#include "Region.h"

#include <algorithm>
#include <cmath>

namespace aeronc::recognition {
using namespace ClipperLib;

namespace {
struct Shape {
    int outers = 0, holes = 0;
    bool operator==(const Shape& o) const { return outers == o.outers && holes == o.holes; }
};
Shape shapeOf(const Paths& ps) {
    Shape s;
    for (const Path& p : ps) (Orientation(p) ? s.outers : s.holes)++;
    return s;
}
// Round joins: the erosion is then the true distance from the boundary. Arcs to within
// 4e-3 of `scale` (the erosion's radius, or the total one when eroding an erosion further).
Paths erode(const Paths& ps, double r, double scale = 0) {
    ClipperOffset off(2.0, std::clamp(std::max(r, scale) * 4e-3, 0.002, 0.1) * kClipperScale);
    off.AddPaths(ps, jtRound, etClosedPolygon);
    Paths out;
    off.Execute(out, -r * kClipperScale);
    return out;
}
}  // namespace

void Region::updateBox() {
    if (outer.empty()) return;
    lo = hi = toP2(outer[0]);
    for (const IntPoint& ip : outer) {
        const P2 p = toP2(ip);
        lo.x = std::min(lo.x, p.x), lo.y = std::min(lo.y, p.y);
        hi.x = std::max(hi.x, p.x), hi.y = std::max(hi.y, p.y);
    }
}

double Region::area() const {
    double a = std::fabs(Area(outer));
    for (const Path& h : holes) a -= std::fabs(Area(h));
    return a / (kClipperScale * kClipperScale);
}

bool Region::contains(const P2& p) const {
    if (p.x < lo.x || p.x > hi.x || p.y < lo.y || p.y > hi.y) return false;
    const IntPoint ip = toInt(p);
    if (PointInPolygon(ip, outer) == 0) return false;
    for (const Path& h : holes)
        if (PointInPolygon(ip, h) == 1) return false;
    return true;
}

Paths Region::paths() const {
    Paths ps{outer};
    ps.insert(ps.end(), holes.begin(), holes.end());
    return ps;
}

// Tessellated arcs carry many short edges whose offsets all intersect; thinning them
// first keeps the erosions fast without moving the boundary by more than 5 µm.
static Paths thinned(const Paths& ps) {
    Paths out;
    CleanPolygons(ps, out, 0.005 * kClipperScale);
    return out;
}

double Region::minWidth() const {
    const Paths ps = thinned(paths());
    const Shape ref{1, static_cast<int>(holes.size())};
    // No disc wider than the box's narrow side fits; 11 halvings resolve it to ~1e-3 of that.
    // Each erosion starts from the last one that kept the shape (eroding by r then by s is
    // eroding by r + s): its convex stretches tighter than r are gone, whose offsets would
    // otherwise cross each other all at once.
    double good = 0, bad = 0.5 * std::min(hi.x - lo.x, hi.y - lo.y) + 1e-3;
    Paths base = ps;
    for (int it = 0; it < 11; ++it) {
        const double r = 0.5 * (good + bad);
        Paths e = erode(base, r - good, r);
        if (!e.empty() && shapeOf(e) == ref) good = r, base = thinned(e);
        else bad = r;
    }
    return 2 * good;
}

P2 Region::interiorPoint() const {
    // The centroid serves when it is inside (holes, most pockets).
    {
        double a = 0, cx = 0, cy = 0;
        for (std::size_t i = 0; i < outer.size(); ++i) {
            const P2 p = toP2(outer[i]), q = toP2(outer[(i + 1) % outer.size()]);
            const double c = p.x * q.y - q.x * p.y;
            a += c, cx += (p.x + q.x) * c, cy += (p.y + q.y) * c;
        }
        if (std::fabs(a) > 0) {
            const P2 c{cx / (3 * a), cy / (3 * a)};
            if (contains(c)) return c;
        }
    }
    const Paths ps = thinned(paths());
    // Erode as far as possible while something remains; any vertex of that is deep inside.
    double good = 0, bad = 0.5 * std::max(hi.x - lo.x, hi.y - lo.y) + 1e-3;
    Paths best = ps;
    for (int it = 0; it < 10; ++it) {
        const double r = 0.5 * (good + bad);
        Paths e = erode(ps, r);
        if (!e.empty()) good = r, best = std::move(e);
        else bad = r;
    }
    for (const Path& p : best)
        if (Orientation(p) && !p.empty()) {
            // Centre of the eroded outer's box nudged to a vertex if it falls outside.
            P2 c{0, 0};
            for (const IntPoint& q : p) c.x += q.X, c.y += q.Y;
            const IntPoint m{static_cast<cInt>(c.x / p.size()), static_cast<cInt>(c.y / p.size())};
            if (PointInPolygon(m, p) == 1 && contains(toP2(m))) return toP2(m);
            return toP2(p[0]);
        }
    return toP2(outer[0]);
}

std::vector<P2> Region::boundaryProbes(double inset, std::size_t maxCount) const {
    const Paths ps = thinned(paths());
    Paths e;
    // Narrow regions vanish under the full inset: halve it until something is left.
    for (double r = inset; r > 1e-4 && e.empty(); r *= 0.5) e = erode(ps, r);
    std::vector<P2> out;
    std::size_t total = 0;
    for (const Path& p : e) total += p.size();
    if (total == 0) return out;
    const std::size_t step = std::max<std::size_t>(1, total / std::max<std::size_t>(1, maxCount));
    std::size_t k = 0;
    for (const Path& p : e)
        for (const IntPoint& q : p)
            if (k++ % step == 0) out.push_back(toP2(q));
    return out;
}

}  // namespace aeronc::recognition
