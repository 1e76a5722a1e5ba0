#pragma once
// Independent geometry for checking toolpaths: plain point and segment distances and a raster
// of the swept cutter, written without Clipper so that the checks do not share the
// implementation's mistakes.
#include <aeronc/toolpath/Toolpath.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

namespace aeronc::toolpath::test {

inline double dist(const Point& a, const Point& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]));
}

inline double pointSegment(const Point& p, const Point& a, const Point& b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
    const double ex = a[0] + t * dx - p[0], ey = a[1] + t * dy - p[1];
    return std::sqrt(ex * ex + ey * ey);
}

// The distance between segments ab and cd, or `beyond` when their boxes are farther apart.
inline double segmentSegment(const Point& a, const Point& b, const Point& c, const Point& d,
                             double beyond = std::numeric_limits<double>::infinity()) {
    const double gap = std::max({std::min(c[0], d[0]) - std::max(a[0], b[0]), std::min(a[0], b[0]) - std::max(c[0], d[0]),
                                 std::min(c[1], d[1]) - std::max(a[1], b[1]), std::min(a[1], b[1]) - std::max(c[1], d[1])});
    if (gap > beyond) return beyond;
    auto cr = [](const Point& o, const Point& p, const Point& q) {
        return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
    };
    const double d1 = cr(a, b, c), d2 = cr(a, b, d), d3 = cr(c, d, a), d4 = cr(c, d, b);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0;
    return std::min({pointSegment(a, c, d), pointSegment(b, c, d), pointSegment(c, a, b), pointSegment(d, a, b)});
}

// Edges in a uniform grid, to find whether a segment comes within `limit` of any of them.
class EdgeGrid {
public:
    EdgeGrid(const std::vector<std::pair<Point, Point>>& edges, double cell) : edges_(edges), cell_(cell) {
        for (std::size_t e = 0; e < edges.size(); ++e) {
            const auto& [a, b] = edges[e];
            for (long i = key(std::min(a[0], b[0])); i <= key(std::max(a[0], b[0])); ++i)
                for (long j = key(std::min(a[1], b[1])); j <= key(std::max(a[1], b[1])); ++j) cells_[{i, j}].push_back(e);
        }
        seen_.assign(edges.size(), 0);
    }
    // The distance from segment ab to the nearest edge, or `limit` when none is nearer.
    double nearest(const Point& a, const Point& b, double limit) {
        ++stamp_;
        double d = limit;
        for (long i = key(std::min(a[0], b[0]) - limit); i <= key(std::max(a[0], b[0]) + limit); ++i)
            for (long j = key(std::min(a[1], b[1]) - limit); j <= key(std::max(a[1], b[1]) + limit); ++j) {
                const auto it = cells_.find({i, j});
                if (it == cells_.end()) continue;
                for (std::size_t e : it->second) {
                    if (seen_[e] == stamp_) continue;
                    seen_[e] = stamp_;
                    d = std::min(d, segmentSegment(a, b, edges_[e].first, edges_[e].second, d));
                }
            }
        return d;
    }

private:
    long key(double x) const { return long(std::floor(x / cell_)); }
    std::vector<std::pair<Point, Point>> edges_;
    double cell_;
    std::map<std::pair<long, long>, std::vector<std::size_t>> cells_;
    std::vector<unsigned> seen_;
    unsigned stamp_ = 0;
};

// Even-odd point in polygon.
inline bool inside(const Loop& l, const Point& p) {
    bool in = false;
    for (std::size_t i = 0, j = l.size() - 1; i < l.size(); j = i++)
        if ((l[i][1] > p[1]) != (l[j][1] > p[1]) &&
            p[0] < (l[j][0] - l[i][0]) * (p[1] - l[i][1]) / (l[j][1] - l[i][1]) + l[i][0])
            in = !in;
    return in;
}

inline double loopDistance(const Loop& l, const Point& p) {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < l.size(); ++i) d = std::min(d, pointSegment(p, l[i], l[(i + 1) % l.size()]));
    return d;
}

inline double loopSegmentDistance(const Loop& l, const Point& a, const Point& b) {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < l.size(); ++i) d = std::min(d, segmentSegment(a, b, l[i], l[(i + 1) % l.size()], d));
    return d;
}

inline Loop rectangle(double u0, double v0, double u1, double v1) { return {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}}; }

// A rectangle with its corners rounded to radius r, as a polygon fine enough for the checks.
inline Loop roundedRectangle(double u0, double v0, double u1, double v1, double r, int perQuarter = 32) {
    if (r <= 0) return rectangle(u0, v0, u1, v1);
    Loop l;
    const Point centres[4] = {{u1 - r, v0 + r}, {u1 - r, v1 - r}, {u0 + r, v1 - r}, {u0 + r, v0 + r}};
    for (int c = 0; c < 4; ++c)
        for (int i = 0; i <= perQuarter; ++i) {
            const double a = (c - 1) * M_PI / 2 + i * (M_PI / 2) / perQuarter;
            l.push_back({centres[c][0] + r * std::cos(a), centres[c][1] + r * std::sin(a)});
        }
    return l;
}

inline Loop circle(const Point& c, double r, int n = 96) {
    Loop l;
    for (int i = 0; i < n; ++i) l.push_back({c[0] + r * std::cos(2 * M_PI * i / n), c[1] + r * std::sin(2 * M_PI * i / n)});
    return l;
}

// Feed and plunge segments at exactly height h (the moves that cut there).
inline std::vector<std::pair<Point, Point>> cutsAt(const Toolpath& t, double h) {
    std::vector<std::pair<Point, Point>> out;
    for (std::size_t i = 1; i < t.moves.size(); ++i) {
        const Move& a = t.moves[i - 1];
        const Move& b = t.moves[i];
        if (b.kind == Move::Kind::Rapid || b.kind == Move::Kind::Drill) continue;
        if (std::abs(a.h - h) < 1e-9 && std::abs(b.h - h) < 1e-9) out.push_back({{a.u, a.v}, {b.u, b.v}});
        else if (std::abs(b.h - h) < 1e-9) out.push_back({{b.u, b.v}, {b.u, b.v}});  // arriving at the level
    }
    return out;
}

inline double length(const std::vector<std::pair<Point, Point>>& segments) {
    double l = 0;
    for (const auto& [a, b] : segments) l += dist(a, b);
    return l;
}

// A square-pixel raster over a box.
struct Raster {
    double u0, v0, px;
    int nu, nv;
    Raster(double u0_, double v0_, double u1, double v1, double px_)
        : u0(u0_), v0(v0_), px(px_), nu(int(std::ceil((u1 - u0_) / px_))), nv(int(std::ceil((v1 - v0_) / px_))) {}
    Point centre(int i, int j) const { return {u0 + (i + 0.5) * px, v0 + (j + 0.5) * px}; }
    std::size_t size() const { return std::size_t(nu) * std::size_t(nv); }
    std::size_t at(int i, int j) const { return std::size_t(j) * std::size_t(nu) + std::size_t(i); }
};

// Exact squared Euclidean distance transform (Felzenszwalb-Huttenlocher), in pixels², to the
// pixels set in `mask`.
inline std::vector<double> distanceTransform(const Raster& r, const std::vector<char>& mask) {
    const double inf = 1e20;
    std::vector<double> f(r.size());
    for (std::size_t k = 0; k < f.size(); ++k) f[k] = mask[k] ? 0 : inf;
    auto pass = [](std::vector<double>& f) {
        const int n = int(f.size());
        std::vector<double> d(f.size()), z(f.size() + 1);
        std::vector<int> v(f.size());
        auto meet = [&](int q, int p) { return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p)); };
        int k = 0;
        v[0] = 0, z[0] = -1e300, z[1] = 1e300;
        for (int q = 1; q < n; ++q) {
            double s = meet(q, v[k]);
            while (s <= z[k]) s = meet(q, v[--k]);
            ++k, v[k] = q, z[k] = s, z[k + 1] = 1e300;
        }
        k = 0;
        for (int q = 0; q < n; ++q) {
            while (z[k + 1] < q) ++k;
            d[q] = double(q - v[k]) * (q - v[k]) + f[v[k]];
        }
        f = d;
    };
    std::vector<double> line;
    for (int j = 0; j < r.nv; ++j) {
        line.assign(f.begin() + long(r.at(0, j)), f.begin() + long(r.at(0, j)) + r.nu);
        pass(line);
        std::copy(line.begin(), line.end(), f.begin() + long(r.at(0, j)));
    }
    line.resize(std::size_t(r.nv));
    for (int i = 0; i < r.nu; ++i) {
        for (int j = 0; j < r.nv; ++j) line[std::size_t(j)] = f[r.at(i, j)];
        pass(line);
        for (int j = 0; j < r.nv; ++j) f[r.at(i, j)] = line[std::size_t(j)];
    }
    return f;
}

// Pixels whose centre lies within `radius` of one of the segments (the cutter's swept disc).
inline std::vector<char> swept(const Raster& r, const std::vector<std::pair<Point, Point>>& segs, double radius) {
    std::vector<char> m(r.size(), 0);
    for (const auto& [a, b] : segs) {
        const int i0 = std::max(0, int(std::floor((std::min(a[0], b[0]) - radius - r.u0) / r.px)));
        const int i1 = std::min(r.nu - 1, int(std::ceil((std::max(a[0], b[0]) + radius - r.u0) / r.px)));
        const int j0 = std::max(0, int(std::floor((std::min(a[1], b[1]) - radius - r.v0) / r.px)));
        const int j1 = std::min(r.nv - 1, int(std::ceil((std::max(a[1], b[1]) + radius - r.v0) / r.px)));
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i)
                if (!m[r.at(i, j)] && pointSegment(r.centre(i, j), a, b) <= radius) m[r.at(i, j)] = 1;
    }
    return m;
}

// The pocket's opening by `radius` at allowance `allowance`: the pixels within `radius` of a
// pixel centre where the cutter fits (inside the contour, outside the islands, at least
// radius + allowance from every wall).
inline std::vector<char> opening(const Raster& r, const Loop& contour, const std::vector<Loop>& islands, double radius,
                                 double allowance) {
    std::vector<char> centres(r.size(), 0);
    for (int j = 0; j < r.nv; ++j)
        for (int i = 0; i < r.nu; ++i) {
            const Point p = r.centre(i, j);
            if (!inside(contour, p) || loopDistance(contour, p) < radius + allowance) continue;
            bool ok = true;
            for (const Loop& isl : islands) ok = ok && !inside(isl, p) && loopDistance(isl, p) >= radius + allowance;
            centres[r.at(i, j)] = ok;
        }
    const auto d2 = distanceTransform(r, centres);
    std::vector<char> m(r.size());
    const double lim = (radius / r.px) * (radius / r.px);
    for (std::size_t k = 0; k < m.size(); ++k) m[k] = d2[k] <= lim;
    return m;
}

}  // namespace aeronc::toolpath::test
