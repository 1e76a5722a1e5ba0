#include "PocketRegion.h"

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>

namespace aeronc::toolselect {
using namespace ClipperLib;

namespace {
Path toPath(const std::vector<std::array<double, 2>>& pts, const std::string& pocket, const char* what) {
    Path p;
    p.reserve(pts.size());
    for (const auto& q : pts) {
        if (!std::isfinite(q[0]) || !std::isfinite(q[1]))
            throw inputError("pocket '" + pocket + "': " + what + " has a non-finite coordinate");
        p.push_back({static_cast<cInt>(std::llround(q[0] * kScale)),
                     static_cast<cInt>(std::llround(q[1] * kScale))});
    }
    return p;
}
}  // namespace

double areaOf(const Paths& ps) {
    double a = 0;
    for (const Path& p : ps) a += Area(p);  // signed: holes come out negative
    return a / (kScale * kScale);
}

PocketRegion makeRegion(const PocketGeometry& pocket) {
    if (pocket.outer.size() < 3)
        throw inputError("pocket '" + pocket.name + "': the contour needs at least 3 points");
    Clipper c;
    // Union with itself (pftNonZero) normalises orientation and self-touching contours.
    c.AddPath(toPath(pocket.outer, pocket.name, "the contour"), ptSubject, true);
    for (const auto& isl : pocket.islands)
        if (isl.size() >= 3) c.AddPath(toPath(isl, pocket.name, "an island"), ptClip, true);
    PocketRegion r;
    c.Execute(ctDifference, r.paths, pftNonZero, pftNonZero);
    r.area = areaOf(r.paths);
    if (!(r.area > 0)) throw inputError("pocket '" + pocket.name + "' has no area");
    return r;
}

Paths offsetRegion(const Paths& ps, double delta, double arcTolerance) {
    ClipperOffset off(2.0, arcTolerance * kScale);
    off.AddPaths(ps, jtRound, etClosedPolygon);
    Paths out;
    off.Execute(out, delta * kScale);
    return out;
}

namespace {

// Offsetting by r (Clipper, round joins): a stretch of the boundary that turns towards the
// offset (a convex fillet or arc under erosion, a concave one under dilation) and curves
// more tightly than r sends Clipper's corner spikes through one another, about n² crossings
// for n vertices, and that is where such an offset spends its time. The stretch is cut into
// short sub-runs, and each sub-run v_i..v_j is replaced by the apex X where the lines of the
// edges entering and leaving it meet. For an erosion the result P⁺ contains P (a convex
// sub-run lies in its triangle v_i X v_j), and its boundary is P's except for the dropped
// chains v_i..v_j: a disc inside P⁺ lies inside P unless it crosses a dropped chain, so
//     P ⊖ D_r = (P⁺ ⊖ D_r) \ ⋃ (chain ⊕ D_r)
// exactly (the triangles being thinner than r). A dilation is the erosion of the
// complement: the triangles are cut out of P, giving P⁻, and
//     P ⊕ D_r = (P⁻ ⊕ D_r) ∪ ⋃ (chain ⊕ D_r).
// Where the stretch curves more tightly than r (the slow case) no chain comes within r of
// the boundary of P± offset, and there is nothing to add or subtract; otherwise only the
// chains that do are swept, each on its own, so their spikes never meet.
constexpr double kThinRadius = 1.25;  // vertices with circumradius <= this · r may be thinned,
constexpr double kCollapse = 1.0;     // in stretches whose mean radius is <= this · r
constexpr double kMaxTurn = 30 * M_PI / 180;  // turning of one sub-run
constexpr std::size_t kMaxRun = 8;            // vertices of one sub-run

struct Seg {
    IntPoint a, b;
    double x0, y0, x1, y1;  // box
};

Seg segOf(const IntPoint& a, const IntPoint& b) {
    return {a, b, double(std::min(a.X, b.X)), double(std::min(a.Y, b.Y)), double(std::max(a.X, b.X)),
            double(std::max(a.Y, b.Y))};
}

double orient(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
    return double(b.X - a.X) * double(c.Y - a.Y) - double(b.Y - a.Y) * double(c.X - a.X);
}

bool segmentsCross(const IntPoint& a, const IntPoint& b, const IntPoint& c, const IntPoint& d) {
    const double d1 = orient(a, b, c), d2 = orient(a, b, d), d3 = orient(c, d, a), d4 = orient(c, d, b);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    auto onSeg = [](const IntPoint& p, const IntPoint& q, const IntPoint& x) {
        return std::min(p.X, q.X) <= x.X && x.X <= std::max(p.X, q.X) && std::min(p.Y, q.Y) <= x.Y &&
               x.Y <= std::max(p.Y, q.Y);
    };
    return (d1 == 0 && onSeg(a, b, c)) || (d2 == 0 && onSeg(a, b, d)) || (d3 == 0 && onSeg(c, d, a)) ||
           (d4 == 0 && onSeg(c, d, b));
}

double pointSegDist2(const IntPoint& p, const IntPoint& a, const IntPoint& b) {
    const double dx = double(b.X - a.X), dy = double(b.Y - a.Y), l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? (double(p.X - a.X) * dx + double(p.Y - a.Y) * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    const double ex = double(a.X) + t * dx - double(p.X), ey = double(a.Y) + t * dy - double(p.Y);
    return ex * ex + ey * ey;
}

double segDist2(const IntPoint& a, const IntPoint& b, const IntPoint& c, const IntPoint& d) {
    if (segmentsCross(a, b, c, d)) return 0;
    return std::min(std::min(pointSegDist2(a, c, d), pointSegDist2(b, c, d)),
                    std::min(pointSegDist2(c, a, b), pointSegDist2(d, a, b)));
}

// Does segment s meet the triangle (p, q, r) (counter-clockwise or not)?
bool meetsTriangle(const Seg& s, const IntPoint& p, const IntPoint& q, const IntPoint& r) {
    auto inside = [&](const IntPoint& x) {
        const double a = orient(p, q, x), b = orient(q, r, x), c = orient(r, p, x);
        return (a >= 0 && b >= 0 && c >= 0) || (a <= 0 && b <= 0 && c <= 0);
    };
    return inside(s.a) || inside(s.b) || segmentsCross(s.a, s.b, p, q) || segmentsCross(s.a, s.b, q, r) ||
           segmentsCross(s.a, s.b, r, p);
}

struct Thinned {
    Paths outer;   // P± (apexes for the thinned sub-runs)
    Paths chains;  // the dropped chains v_i..v_j, as open paths
};

// `sign` +1 thins left turns (the spiking vertices of an erosion), -1 right turns (those of a
// dilation).
Thinned thinSpikingRuns(const Paths& ps, double delta, double sign) {
    Thinned t;
    std::vector<Seg> edges;  // every edge of P, to keep a triangle from covering another part of it
    for (const Path& p : ps)
        for (std::size_t i = 0; i < p.size(); ++i) edges.push_back(segOf(p[i], p[(i + 1) % p.size()]));
    std::size_t pathStart = 0;  // index of the path's first edge in `edges`
    for (const Path& p : ps) {
        const std::size_t n = p.size(), first = pathStart;
        pathStart += n;
        std::vector<double> turn(n);
        std::vector<char> thin(n, 0);
        bool any = false, all = true;
        for (std::size_t j = 0; n >= 4 && j < n; ++j) {
            const IntPoint& a = p[(j + n - 1) % n];
            const IntPoint& b = p[j];
            const IntPoint& c = p[(j + 1) % n];
            const double ax = double(b.X - a.X), ay = double(b.Y - a.Y), bx = double(c.X - b.X), by = double(c.Y - b.Y);
            const double cr = sign * (ax * by - ay * bx);
            turn[j] = std::atan2(cr, ax * bx + ay * by);
            // Circumradius |a||b||a+b| / (2 (a × b)) at most kThinRadius · delta.
            const double chord = std::hypot(ax + bx, ay + by);
            thin[j] = cr > 0 && std::hypot(ax, ay) * std::hypot(bx, by) * chord <= 2 * cr * kThinRadius * delta;
            any = any || thin[j];
            all = all && thin[j];
        }
        std::size_t start = 0;
        if (any && !all)
            while (thin[start]) ++start;
        // A stretch is thinned only when, on the whole, it curves more tightly than r (its
        // length over its turning): then its erosion collapses and nothing needs subtracting.
        // A wider stretch erodes without crossings anyway.
        for (std::size_t k = 0; any && k < n;) {
            const std::size_t i = (start + k) % n;
            if (!thin[i]) {
                ++k;
                continue;
            }
            std::size_t m = 1;
            double length = 0, turning = turn[i];
            while (k + m < n && thin[(i + m) % n]) {
                const IntPoint& a = p[(i + m - 1) % n];
                const IntPoint& b = p[(i + m) % n];
                length += std::hypot(double(b.X - a.X), double(b.Y - a.Y));
                turning += turn[(i + m) % n];
                ++m;
            }
            if (m < 3 || length > turning * kCollapse * delta)
                for (std::size_t q = 0; q < m; ++q) thin[(i + q) % n] = 0;
            k += m;
        }
        if (std::find(thin.begin(), thin.end(), 1) == thin.end()) {
            t.outer.push_back(p);
            continue;
        }
        Path out;
        Paths chains;
        for (std::size_t k = 0; k < n;) {
            const std::size_t i = (start + k) % n;
            std::size_t m = 1;
            double sum = turn[i];
            if (thin[i])
                while (k + m < n && m < kMaxRun && thin[(i + m) % n] && sum + turn[(i + m) % n] <= kMaxTurn)
                    sum += turn[(i + m) % n], ++m;
            if (m < 2) {
                out.push_back(p[i]);
                ++k;
                continue;
            }
            const std::size_t j = (i + m - 1) % n;
            // Apex: line through (v_{i-1}, v_i) meets line through (v_j, v_{j+1}).
            const IntPoint& a0 = p[(i + n - 1) % n];
            const IntPoint& a1 = p[i];
            const IntPoint& b0 = p[j];
            const IntPoint& b1 = p[(j + 1) % n];
            const double ux = double(a1.X - a0.X), uy = double(a1.Y - a0.Y);
            const double vx = double(b1.X - b0.X), vy = double(b1.Y - b0.Y);
            const double den = ux * vy - uy * vx;
            bool ok = sign * den > 0;
            IntPoint x;
            if (ok) {
                const double s = (double(b0.X - a1.X) * vy - double(b0.Y - a1.Y) * vx) / den;
                ok = s >= 0 && std::isfinite(s);
                x = IntPoint(static_cast<cInt>(std::llround(a1.X + s * ux)),
                             static_cast<cInt>(std::llround(a1.Y + s * uy)));
            }
            if (ok) {
                // The triangle v_i X v_j must cover nothing of P but the chain it replaces.
                const double bx0 = double(std::min({a1.X, b0.X, x.X})), by0 = double(std::min({a1.Y, b0.Y, x.Y}));
                const double bx1 = double(std::max({a1.X, b0.X, x.X})), by1 = double(std::max({a1.Y, b0.Y, x.Y}));
                for (std::size_t e = 0; ok && e < edges.size(); ++e) {
                    if (e >= first && e < first + n) {
                        const std::size_t local = e - first;  // edge local → local+1
                        // Edges i-1 .. j (the two tangents and the chain) belong to the triangle.
                        if ((local + n - ((i + n - 1) % n)) % n <= m) continue;
                    }
                    const Seg& s = edges[e];
                    if (s.x1 < bx0 || s.x0 > bx1 || s.y1 < by0 || s.y0 > by1) continue;
                    ok = !meetsTriangle(s, a1, x, b0);
                }
            }
            if (!ok) {
                out.push_back(p[i]);
                ++k;
                continue;
            }
            out.push_back(x);
            Path chain;
            for (std::size_t q = 0; q < m; ++q) chain.push_back(p[(i + q) % n]);
            chains.push_back(std::move(chain));
            k += m;
        }
        if (out.size() < 3) {
            t.outer.push_back(p);
            continue;
        }
        t.outer.push_back(std::move(out));
        for (Path& c : chains) t.chains.push_back(std::move(c));
    }
    return t;
}

}  // namespace

Paths offsetRegionFast(const Paths& ps, double delta, double arcTolerance) {
    const double d = std::fabs(delta) * kScale;
    Thinned t = thinSpikingRuns(ps, d, delta < 0 ? 1.0 : -1.0);
    if (t.chains.empty()) return offsetRegion(ps, delta, arcTolerance);
    Paths base = offsetRegion(t.outer, delta, arcTolerance);
    if (base.empty() && delta < 0) return base;

    // The chains that come within r of the boundary of the offset P± (plus a unit for
    // rounding); the others' sweeps lie wholly outside it (erosion) or inside it (dilation).
    std::vector<Seg> edges;
    for (const Path& p : base)
        for (std::size_t i = 0; i < p.size(); ++i) edges.push_back(segOf(p[i], p[(i + 1) % p.size()]));
    const double reach = d + 1, reach2 = reach * reach;
    Paths cut;
    for (const Path& c : t.chains) {
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        for (const IntPoint& q : c)
            x0 = std::min(x0, double(q.X)), y0 = std::min(y0, double(q.Y)), x1 = std::max(x1, double(q.X)),
            y1 = std::max(y1, double(q.Y));
        x0 -= reach, y0 -= reach, x1 += reach, y1 += reach;
        bool near = false;
        for (std::size_t e = 0; !near && e < edges.size(); ++e) {
            const Seg& s = edges[e];
            if (s.x1 < x0 || s.x0 > x1 || s.y1 < y0 || s.y0 > y1) continue;
            for (std::size_t q = 0; !near && q + 1 < c.size(); ++q) near = segDist2(c[q], c[q + 1], s.a, s.b) < reach2;
        }
        if (!near) continue;
        // Flat ends: the end points lie on P±'s boundary, which already sweeps their discs.
        ClipperOffset off(2.0, arcTolerance * kScale);
        off.AddPath(c, jtRound, etOpenButt);
        Paths sweep;
        off.Execute(sweep, d);
        cut.insert(cut.end(), sweep.begin(), sweep.end());
    }
    if (cut.empty()) return base;
    Clipper clip;
    clip.AddPaths(base, ptSubject, true);
    clip.AddPaths(cut, ptClip, true);
    Paths out;
    clip.Execute(delta < 0 ? ctDifference : ctUnion, out, pftNonZero, pftNonZero);
    return out;
}

double arcToleranceFor(double radius) { return std::max(radius * 2e-3, 2e-4); }

Opening openRegion(const PocketRegion& region, double radius) {
    if (!(radius > 0) || !std::isfinite(radius))
        throw inputError("tool radius " + std::to_string(radius) + " mm must be positive");
    const double tol = arcToleranceFor(radius);
    Opening o;
    Paths eroded = offsetRegionFast(region.paths, -radius, tol);
    // (An empty erosion leaves the whole region.)
    // The round joins leave runs of near-collinear points; dropping them halves the
    // dilation's cost and moves the boundary by less than the arc tolerance.
    CleanPolygons(eroded, o.eroded, tol * kScale);
    // Clipper's arcs are inscribed chords and would lose (2/3)·tol·arc length; a radius
    // giving the polygon the circle's area cancels that to first order. Along the walls
    // the extra is clipped off below.
    const double step = 2 * std::acos(1 - tol / radius);
    const double equalArea = radius * std::sqrt(step / std::sin(step));
    // What the opening leaves of the region is kept: the narrow-passage analysis looks
    // only there.
    Clipper c;
    c.AddPaths(region.paths, ptSubject, true);
    c.AddPaths(offsetRegion(o.eroded, equalArea, tol), ptClip, true);
    PolyTree left;
    c.Execute(ctDifference, left, pftNonZero, pftNonZero);
    double unreached = 0;
    std::vector<const PolyNode*> todo(left.Childs.begin(), left.Childs.end());
    while (!todo.empty()) {
        const PolyNode* n = todo.back();
        todo.pop_back();
        for (const PolyNode* ch : n->Childs) todo.push_back(ch);
        if (n->IsHole()) continue;
        Opening::Piece piece;
        piece.outer = n->Contour;
        double a = std::fabs(Area(n->Contour));
        for (const PolyNode* h : n->Childs) piece.holes.push_back(h->Contour), a -= std::fabs(Area(h->Contour));
        piece.area = a / (kScale * kScale);
        unreached += piece.area;
        o.unreached.push_back(std::move(piece));
    }
    o.machinableArea = o.eroded.empty() ? 0 : std::max(0.0, region.area - unreached);
    return o;
}

}  // namespace aeronc::toolselect
