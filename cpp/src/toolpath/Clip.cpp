#include "Clip.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace aeronc::toolpath::clip {
using namespace ClipperLib;

IntPoint toInt(const Point& p) {
    return {static_cast<cInt>(std::llround(p[0] * kScale)), static_cast<cInt>(std::llround(p[1] * kScale))};
}
Point toPoint(const IntPoint& p) { return {double(p.X) / kScale, double(p.Y) / kScale}; }

Path toPath(const Loop& loop) {
    Path p;
    p.reserve(loop.size());
    for (const Point& q : loop) p.push_back(toInt(q));
    return p;
}

Loop toLoop(const Path& path) {
    Loop l;
    l.reserve(path.size());
    for (const IntPoint& q : path) l.push_back(toPoint(q));
    return l;
}

double arcTolerance(double chordTolerance) { return std::max(chordTolerance / 2.25 * kScale, 1.0); }

Paths offset(const Paths& region, double delta, double chordTolerance) {
    ClipperOffset off(2.0, arcTolerance(chordTolerance));
    off.AddPaths(region, jtRound, etClosedPolygon);
    Paths out;
    off.Execute(out, delta * kScale);
    return out;
}

Paths offsetMitred(const Paths& region, double delta, double chordTolerance) {
    ClipperOffset off(kMitreLimit, arcTolerance(chordTolerance));
    off.AddPaths(region, jtMiter, etClosedPolygon);
    Paths out;
    off.Execute(out, delta * kScale);
    return out;
}

namespace {
Paths boolean(ClipType type, const Paths& a, const Paths& b) {
    Clipper c;
    c.AddPaths(a, ptSubject, true);
    c.AddPaths(b, ptClip, true);
    Paths out;
    c.Execute(type, out, pftNonZero, pftNonZero);
    return out;
}

void collect(const PolyNode& node, std::vector<Piece>& out) {
    for (const PolyNode* child : node.Childs) {
        // Children of the tree's root and of holes are outers.
        Piece p{child->Contour, {}};
        for (const PolyNode* hole : child->Childs) {
            p.holes.push_back(hole->Contour);
            collect(*hole, out);
        }
        out.push_back(std::move(p));
    }
}
}  // namespace

Paths unite(const Paths& a, const Paths& b) { return boolean(ctUnion, a, b); }
Paths intersect(const Paths& a, const Paths& b) { return boolean(ctIntersection, a, b); }
Paths subtract(const Paths& a, const Paths& b) { return boolean(ctDifference, a, b); }

double area(const Paths& region) {
    double a = 0;
    for (const Path& p : region) a += Area(p);
    return a / (kScale * kScale);
}

std::vector<Piece> pieces(const Paths& region) {
    Clipper c;
    c.AddPaths(region, ptSubject, true);
    PolyTree tree;
    c.Execute(ctUnion, tree, pftNonZero, pftNonZero);
    std::vector<Piece> out;
    collect(tree, out);
    return out;
}

std::vector<Piece> offsetPieces(const Paths& region, double delta, double chordTolerance) {
    ClipperOffset off(2.0, arcTolerance(chordTolerance));
    off.AddPaths(region, jtRound, etClosedPolygon);
    PolyTree tree;
    off.Execute(tree, delta * kScale);
    std::vector<Piece> out;
    collect(tree, out);
    return out;
}

Paths pathsOf(const Piece& piece) {
    Paths ps{piece.outer};
    ps.insert(ps.end(), piece.holes.begin(), piece.holes.end());
    return ps;
}

bool contains(const Paths& region, const Point& p) {
    // Nonzero winding over all paths (outers +1, holes -1); the boundary counts as inside.
    const IntPoint q = toInt(p);
    int winding = 0;
    for (const Path& path : region) {
        const int in = PointInPolygon(q, path);
        if (in == -1) return true;
        if (in == 1) winding += Orientation(path) ? 1 : -1;
    }
    return winding > 0;
}

double distance(const Point& a, const Point& b) {
    const double du = b[0] - a[0], dv = b[1] - a[1];
    return std::sqrt(du * du + dv * dv);  // not hypot: no overflow to guard against at 10^6 mm, and much faster
}

Point nearestOnSegment(const Point& p, const Point& a, const Point& b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
    return {a[0] + t * dx, a[1] + t * dy};
}

double segmentDistance(const Point& p, const Point& a, const Point& b) { return distance(p, nearestOnSegment(p, a, b)); }

double boundaryDistance(const Paths& region, const Point& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const Path& path : region)
        for (std::size_t i = 0, n = path.size(); i < n; ++i)
            best = std::min(best, segmentDistance(p, toPoint(path[i]), toPoint(path[(i + 1) % n])));
    return best;
}

namespace {
double orient(const IntPoint& a, const IntPoint& b, const IntPoint& c) {
    return double(b.X - a.X) * double(c.Y - a.Y) - double(b.Y - a.Y) * double(c.X - a.X);
}
}  // namespace

bool segmentInside(const Paths& region, const Point& a, const Point& b) {
    const IntPoint p = toInt(a), q = toInt(b);
    const cInt x0 = std::min(p.X, q.X), x1 = std::max(p.X, q.X), y0 = std::min(p.Y, q.Y), y1 = std::max(p.Y, q.Y);
    for (const Path& path : region)
        for (std::size_t i = 0, n = path.size(); i < n; ++i) {
            const IntPoint& c = path[i];
            const IntPoint& d = path[(i + 1) % n];
            if (std::max(c.X, d.X) < x0 || std::min(c.X, d.X) > x1 || std::max(c.Y, d.Y) < y0 ||
                std::min(c.Y, d.Y) > y1)
                continue;
            // A proper crossing leaves the region; touching the boundary does not.
            const double o1 = orient(p, q, c), o2 = orient(p, q, d), o3 = orient(c, d, p), o4 = orient(c, d, q);
            if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
                return false;
        }
    const Point mid{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2};
    return contains(region, a) && contains(region, b) && contains(region, mid);
}

LoopPoint nearestOnLoop(const Loop& loop, const Point& p) {
    LoopPoint best{loop.front(), 0, std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
        const Point q = nearestOnSegment(p, loop[i], loop[(i + 1) % n]);
        const double d = distance(p, q);
        if (d < best.distance) best = {q, i, d};
    }
    return best;
}

std::vector<Point> loopFrom(const Loop& loop, const LoopPoint& at) {
    const std::size_t n = loop.size();
    std::vector<Point> out;
    out.reserve(n + 2);
    out.push_back(at.at);
    for (std::size_t k = 1; k <= n; ++k) {
        const Point& q = loop[(at.edge + k) % n];
        if (distance(q, out.back()) > 1e-9) out.push_back(q);
    }
    if (distance(at.at, out.back()) > 1e-9) out.push_back(at.at);
    else out.back() = at.at;
    return out;
}

double length(const std::vector<Point>& polyline) {
    double l = 0;
    for (std::size_t i = 1; i < polyline.size(); ++i) l += distance(polyline[i - 1], polyline[i]);
    return l;
}

double signedArea(const Loop& loop) {
    double a = 0;
    for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
        const Point& p = loop[i];
        const Point& q = loop[(i + 1) % n];
        a += p[0] * q[1] - q[0] * p[1];
    }
    return a / 2;
}

Point centroid(const Loop& loop) {
    double a = 0, cx = 0, cy = 0;
    const Point& o = loop.front();  // relative to a vertex, for precision far from the origin
    for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
        const double px = loop[i][0] - o[0], py = loop[i][1] - o[1];
        const double qx = loop[(i + 1) % n][0] - o[0], qy = loop[(i + 1) % n][1] - o[1];
        const double w = px * qy - qx * py;
        a += w, cx += (px + qx) * w, cy += (py + qy) * w;
    }
    if (std::abs(a) < 1e-12) return o;
    return {o[0] + cx / (3 * a), o[1] + cy / (3 * a)};
}

}  // namespace aeronc::toolpath::clip
