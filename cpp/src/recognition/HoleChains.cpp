#include "HoleChains.h"

#include <aeronc/recognition/SetupFrame.h>

#include "AxisRays.h"
#include "FaceLists.h"
#include "HoleRecognition.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <gp_Cylinder.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

namespace aeronc::recognition {
namespace {

constexpr double kPi = 3.14159265358979323846;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 mul(const Vec3& a, double k) { return {a[0] * k, a[1] * k, a[2] * k}; }
Vec3 unit(const Vec3& a) { return mul(a, 1 / norm(a)); }

// Distance of point p from the line through o along unit d.
double offAxis(const Vec3& p, const Vec3& o, const Vec3& d) {
    const Vec3 r = sub(p, o);
    return norm(sub(r, mul(d, dot(r, d))));
}

struct UnionFind {
    std::vector<int> up;
    explicit UnionFind(std::size_t n) : up(n) { std::iota(up.begin(), up.end(), 0); }
    int find(int a) { return up[static_cast<std::size_t>(a)] == a ? a : up[static_cast<std::size_t>(a)] = find(up[static_cast<std::size_t>(a)]); }
    void join(int a, int b) { up[static_cast<std::size_t>(find(a))] = find(b); }
};

// Degrees of the circle a cylinder face spans, as bins in the frame (x, y) square to its axis.
void markSpan(const FaceInfo& f, const Vec3& x, const Vec3& y, std::array<bool, 360>& bins) {
    BRepAdaptor_Surface s(f.face, false);
    const gp_Ax3 pos = s.Cylinder().Position();
    const Vec3 fx{pos.XDirection().X(), pos.XDirection().Y(), pos.XDirection().Z()};
    const Vec3 fy{pos.YDirection().X(), pos.YDirection().Y(), pos.YDirection().Z()};
    double u0, u1, v0, v1;
    BRepTools::UVBounds(f.face, u0, u1, v0, v1);
    const int n = std::max(2, static_cast<int>(std::ceil((u1 - u0) * 180 / kPi * 2)));
    for (int k = 0; k <= n; ++k) {
        const double u = u0 + (u1 - u0) * k / n;
        const Vec3 r = add(mul(fx, std::cos(u)), mul(fy, std::sin(u)));
        double a = std::atan2(dot(r, y), dot(r, x)) * 180 / kPi;
        if (a < 0) a += 360;
        bins[static_cast<std::size_t>(a) % 360] = true;
    }
}

}  // namespace

std::vector<int> HoleChain::faces() const {
    std::vector<int> out;
    for (const HoleSegment& s : segments) out.insert(out.end(), s.faces.begin(), s.faces.end());
    out.insert(out.end(), steps.begin(), steps.end());
    out.insert(out.end(), cones.begin(), cones.end());
    return out;
}

std::vector<HoleChain> findHoleChains(const FaceCatalogue& faces, const Tolerances& tol) {
    const double lin = 10 * tol.linear;
    auto coaxial = [&](const FaceInfo& a, const FaceInfo& b) {
        return std::fabs(dot(a.axisDir, b.axisDir)) >= tol.parallelCos &&
               offAxis(b.axisPoint, a.axisPoint, unit(a.axisDir)) <= lin;
    };
    // 1. Segments: concave cylinders with one axis and radius that touch or overlap along
    // the axis (a hole split in halves, or cut in pieces by a slot across it).
    const int n = faces.size();
    UnionFind same(static_cast<std::size_t>(n));
    std::vector<int> cylinders;
    for (int i = 0; i < n; ++i)
        if (faces[i].kind == SurfaceKind::Cylinder && faces[i].concave) cylinders.push_back(i);
    for (std::size_t a = 0; a < cylinders.size(); ++a) {
        const FaceInfo& f = faces[cylinders[a]];
        const Vec3 d = unit(f.axisDir);
        double flo, fhi;
        faces.heightRange(cylinders[a], d, flo, fhi);
        for (std::size_t b = 0; b < a; ++b) {
            const FaceInfo& g = faces[cylinders[b]];
            if (std::fabs(g.radius - f.radius) > lin || !coaxial(f, g)) continue;
            double glo, ghi;
            faces.heightRange(cylinders[b], d, glo, ghi);
            const bool touch = std::find(f.neighbours.begin(), f.neighbours.end(), cylinders[b]) != f.neighbours.end();
            if (touch || (glo < fhi - lin && flo < ghi - lin)) same.join(cylinders[a], cylinders[b]);
        }
    }
    std::map<int, std::vector<int>> groups;
    for (int i : cylinders) groups[same.find(i)].push_back(i);
    struct Seg {
        HoleSegment s;
        Vec3 axis, point;
    };
    std::vector<Seg> segs;
    std::vector<int> segOfFace(static_cast<std::size_t>(n), -1);
    for (auto& [root, members] : groups) {
        const FaceInfo& f0 = faces[members[0]];
        const Vec3 d = unit(f0.axisDir);
        // More than half the circle: a hole; a corner fillet or a slot's end is not.
        const Vec3 a = std::fabs(d[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        const Vec3 x = unit(sub(a, mul(d, dot(a, d))));
        const Vec3 y{d[1] * x[2] - d[2] * x[1], d[2] * x[0] - d[0] * x[2], d[0] * x[1] - d[1] * x[0]};
        std::array<bool, 360> bins{};
        for (int i : members) markSpan(faces[i], x, y, bins);
        if (std::count(bins.begin(), bins.end(), true) < 185) continue;
        Seg g;
        g.axis = d;
        g.point = f0.axisPoint;
        g.s.faces = members;
        g.s.radius = f0.radius;
        for (int i : members) segOfFace[static_cast<std::size_t>(i)] = static_cast<int>(segs.size());
        segs.push_back(std::move(g));
    }
    if (segs.empty()) return {};

    // 2. Chains: segments on one axis that touch, directly or through a step or a cone.
    UnionFind chainOf(segs.size());
    auto onAxis = [&](const FaceInfo& f, const Seg& s) {
        if (f.kind == SurfaceKind::Plane)
            return std::fabs(dot(f.normal, s.axis)) >= tol.parallelCos;
        if (f.kind == SurfaceKind::Cone)
            return std::fabs(dot(unit(f.axisDir), s.axis)) >= tol.parallelCos && offAxis(f.axisPoint, s.point, s.axis) <= lin;
        return false;
    };
    for (std::size_t a = 0; a < segs.size(); ++a)
        for (int f : segs[a].s.faces)
            for (int nb : faces[f].neighbours) {
                const int b = segOfFace[static_cast<std::size_t>(nb)];
                if (b >= 0 && b != static_cast<int>(a) && coaxial(faces[segs[a].s.faces[0]], faces[nb]))
                    chainOf.join(static_cast<int>(a), b);
                if (b < 0 && onAxis(faces[nb], segs[a]))
                    for (int nn : faces[nb].neighbours) {
                        const int c = segOfFace[static_cast<std::size_t>(nn)];
                        if (c >= 0 && c != static_cast<int>(a) && coaxial(faces[segs[a].s.faces[0]], faces[nn]))
                            chainOf.join(static_cast<int>(a), c);
                    }
            }
    std::map<int, std::vector<int>> chainSegs;
    for (std::size_t a = 0; a < segs.size(); ++a) chainSegs[chainOf.find(static_cast<int>(a))].push_back(static_cast<int>(a));

    // Rays and heights along each axis direction, built once per direction.
    struct Along {
        Vec3 w;
        std::unique_ptr<AxisRays> rays;
        std::vector<FaceCatalogue::HeightRange> ranges;
    };
    std::vector<std::unique_ptr<Along>> alongs;
    auto along = [&](const Vec3& d) -> Along& {
        for (auto& a : alongs)
            if (dot(a->w, d) >= tol.parallelCos) return *a;
        auto a = std::make_unique<Along>();
        a->w = d;
        const SetupFrame frame(d);
        a->rays = std::make_unique<AxisRays>(faces, frame);
        a->ranges = faces.heightRanges(frame.u, frame.v, frame.w);
        alongs.push_back(std::move(a));
        return *alongs.back();
    };

    std::vector<HoleChain> out;
    for (auto& [root, members] : chainSegs) {
        HoleChain c;
        const Seg& s0 = segs[static_cast<std::size_t>(members[0])];
        // Heights along the first direction met of this axis, so opposite holes agree.
        Along& al = along(s0.axis);
        c.axis = al.w;
        c.point = s0.point;
        for (int m : members) {
            HoleSegment s = segs[static_cast<std::size_t>(m)].s;
            s.lo = std::numeric_limits<double>::max(), s.hi = -s.lo;
            for (int f : s.faces) {
                s.lo = std::min(s.lo, al.ranges[static_cast<std::size_t>(f)].lo);
                s.hi = std::max(s.hi, al.ranges[static_cast<std::size_t>(f)].hi);
            }
            c.segments.push_back(std::move(s));
        }
        std::sort(c.segments.begin(), c.segments.end(), [](const HoleSegment& a, const HoleSegment& b) {
            return a.lo + a.hi < b.lo + b.hi;
        });
        // Steps and cones on the axis touching the walls.
        for (const HoleSegment& s : c.segments)
            for (int f : s.faces)
                for (int nb : faces[f].neighbours) {
                    const FaceInfo& g = faces[nb];
                    if (segOfFace[static_cast<std::size_t>(nb)] >= 0) continue;
                    if (g.kind == SurfaceKind::Cone && onAxis(g, s0) && g.concave) pushUnique(c.cones, nb);
                    if (g.kind == SurfaceKind::Plane && onAxis(g, s0)) {
                        // A step or a bottom: the plane faces into the hole, so it lies between
                        // segments or at an end with its material beyond.
                        const double h = dot(g.planePoint, c.axis);
                        const bool facesUp = dot(g.normal, c.axis) > 0;
                        const HoleSegment& first = c.segments.front();
                        const HoleSegment& last = c.segments.back();
                        const bool bottom = facesUp && std::fabs(h - first.lo) <= lin;
                        const bool top = !facesUp && std::fabs(h - last.hi) <= lin;
                        bool between = false;
                        for (std::size_t k = 0; k + 1 < c.segments.size(); ++k)
                            between |= std::fabs(h - c.segments[k].hi) <= lin || std::fabs(h - c.segments[k + 1].lo) <= lin;
                        if (bottom || top || between) pushUnique(c.steps, nb);
                    }
                }
        // Open ends: a ray along the axis from inside the end segment leaves the part.
        auto axisAt = [&](double h) { return add(c.point, mul(c.axis, h - dot(c.point, c.axis))); };
        const HoleSegment& first = c.segments.front();
        const HoleSegment& last = c.segments.back();
        c.openTop = std::isinf(al.rays->firstHit(axisAt(0.5 * (last.lo + last.hi)), true));
        c.openBottom = std::isinf(al.rays->firstHit(axisAt(0.5 * (first.lo + first.hi)), false));
        // A tool as wide as a segment comes down the axis only if rays round nine tenths of its
        // radius leave the part too.
        const SetupFrame across(c.axis);
        auto overhung = [&](const HoleSegment& s, bool up) {
            const Vec3 o = axisAt(0.5 * (s.lo + s.hi));
            for (int k = 0; k < 8; ++k) {
                const double a = k * M_PI / 4, r = 0.9 * s.radius;
                const Vec3 p = add(o, add(mul(across.u, r * std::cos(a)), mul(across.v, r * std::sin(a))));
                if (!std::isinf(al.rays->firstHit(p, up))) return true;
            }
            return false;
        };
        // From an open end a tool reaches the segments in turn while none is wider than the
        // one before (a bore turned from both sides is reached half from each).
        const std::size_t m = c.segments.size();
        // Past an overhung segment the deeper ones are overhung too: the tool would come down
        // through material left in it.
        if (c.openTop) {
            bool blocked = false;
            for (std::size_t k = m; k-- > 0;) {
                if (k + 1 < m && c.segments[k].radius > c.segments[k + 1].radius + lin) break;
                c.segments[k].entries.push_back(1);
                blocked = blocked || overhung(c.segments[k], true);
                if (blocked) c.segments[k].overhung.push_back(1);
            }
        }
        if (c.openBottom) {
            bool blocked = false;
            for (std::size_t k = 0; k < m; ++k) {
                if (k > 0 && c.segments[k].radius > c.segments[k - 1].radius + lin) break;
                c.segments[k].entries.push_back(-1);
                blocked = blocked || overhung(c.segments[k], false);
                if (blocked) c.segments[k].overhung.push_back(-1);
            }
        }
        // Reached from both ends: from the end that reaches more of the hole, a countersink
        // counting, so a counterbore or a countersink and its hole are made from one side.
        int fromTop = 0, fromBottom = 0;
        for (const HoleSegment& s : c.segments)
            for (int e : s.entries) (e > 0 ? fromTop : fromBottom)++;
        for (int f : c.cones) {
            const auto& r = al.ranges[static_cast<std::size_t>(f)];
            if (r.lo >= last.hi - lin && coneRadiusAt(faces[f], c.axis, r.hi) > last.radius + lin) ++fromTop;
            if (r.hi <= first.lo + lin && coneRadiusAt(faces[f], c.axis, r.lo) > first.radius + lin) ++fromBottom;
        }
        // A segment reached from both ends is made from the one a tool as wide as it can come
        // down, else from the one that reaches more.
        for (HoleSegment& s : c.segments) {
            if (s.entries.size() != 2) continue;
            auto over = [&](int e) { return std::find(s.overhung.begin(), s.overhung.end(), e) != s.overhung.end(); };
            int pick = fromTop == fromBottom ? 0 : fromTop > fromBottom ? 1 : -1;
            if (over(1) != over(-1)) pick = over(1) ? -1 : 1;
            if (pick == 0) continue;
            s.entries = {pick};
            if (!over(pick)) s.overhung.clear();
        }
        if (std::getenv("AERONC_TRACE")) {
            std::fprintf(stderr, "hole chain axis (%.3f %.3f %.3f) at (%.3f %.3f %.3f), open %d%d:", c.axis[0],
                         c.axis[1], c.axis[2], c.point[0], c.point[1], c.point[2], c.openBottom, c.openTop);
            for (const HoleSegment& s : c.segments) {
                std::fprintf(stderr, " [r %.3f, %.3f..%.3f, %zu entries:", s.radius, s.lo, s.hi, s.entries.size());
                for (int f : s.faces) std::fprintf(stderr, " %d", f + 1);
                std::fprintf(stderr, "]");
            }
            for (int f : c.steps) std::fprintf(stderr, " step %d", f + 1);
            for (int f : c.cones) std::fprintf(stderr, " cone %d", f + 1);
            std::fprintf(stderr, "\n");
        }
        out.push_back(std::move(c));
    }
    return out;
}

}  // namespace aeronc::recognition
