#include "AxisRays.h"

#include <ElSLib.hxx>
#include <gp_Lin.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aeronc::recognition {

AxisRays::AxisRays(const FaceCatalogue& faces, const SetupFrame& frame)
    : faces_(faces), frame_(frame), lo_(faces.size()), hi_(faces.size()), h0_(faces.size()), h1_(faces.size()) {
    P2 all0{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    P2 all1{-all0.x, -all0.y};
    for (int i = 0; i < faces.size(); ++i) {
        const FaceInfo& f = faces[i];
        P2 a{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()}, b{-a.x, -a.y};
        double h0 = std::numeric_limits<double>::max(), h1 = -h0;
        for (int c = 0; c < 8; ++c) {
            const Vec3 corner{(c & 1) ? f.boxMax[0] : f.boxMin[0], (c & 2) ? f.boxMax[1] : f.boxMin[1],
                              (c & 4) ? f.boxMax[2] : f.boxMin[2]};
            const P2 q = frame.project(corner);
            a.x = std::min(a.x, q.x), a.y = std::min(a.y, q.y), b.x = std::max(b.x, q.x), b.y = std::max(b.y, q.y);
            h0 = std::min(h0, frame.height(corner)), h1 = std::max(h1, frame.height(corner));
        }
        h0_[static_cast<std::size_t>(i)] = h0 - 1e-6 * (1 + std::fabs(h0));
        h1_[static_cast<std::size_t>(i)] = h1 + 1e-6 * (1 + std::fabs(h1));
        const double m = 1e-6 + 1e-9 * (std::fabs(a.x) + std::fabs(a.y));
        lo_[static_cast<std::size_t>(i)] = {a.x - m, a.y - m};
        hi_[static_cast<std::size_t>(i)] = {b.x + m, b.y + m};
        all0.x = std::min(all0.x, a.x), all0.y = std::min(all0.y, a.y);
        all1.x = std::max(all1.x, b.x), all1.y = std::max(all1.y, b.y);
    }
    // About one face per cell on average.
    const double area = std::max((all1.x - all0.x) * (all1.y - all0.y), 1e-12);
    cell_ = std::max(std::sqrt(area / std::max(1, faces.size())), 1e-6);
    for (int i = 0; i < faces.size(); ++i) {
        // A ray along the axis never crosses a cylinder about a parallel axis.
        const FaceInfo& f = faces[i];
        if (f.kind == SurfaceKind::Cylinder && std::fabs(dot(f.axisDir, frame.w)) >= 1 - 1e-12) continue;
        if (f.ruled && std::fabs(dot(f.ruled->extrusion, frame.w)) >= 1 - 1e-12) continue;  // nor an extrusion along it
        const P2& a = lo_[static_cast<std::size_t>(i)];
        const P2& b = hi_[static_cast<std::size_t>(i)];
        const long long x0 = static_cast<long long>(std::floor(a.x / cell_)), x1 = static_cast<long long>(std::floor(b.x / cell_));
        const long long y0 = static_cast<long long>(std::floor(a.y / cell_)), y1 = static_cast<long long>(std::floor(b.y / cell_));
        for (long long x = x0; x <= x1; ++x)
            for (long long y = y0; y <= y1; ++y) grid_[key(x, y)].push_back(i);
    }
}

double AxisRays::firstHit(const Vec3& p, bool up) { return cast(p, up, false); }

bool AxisRays::anyHit(const Vec3& p, bool up) { return !std::isinf(cast(p, up, true)); }

double AxisRays::cast(const Vec3& p, bool up, bool any) {
    const P2 q = frame_.project(p);
    const auto it = grid_.find(key(static_cast<long long>(std::floor(q.x / cell_)), static_cast<long long>(std::floor(q.y / cell_))));
    double best = std::numeric_limits<double>::infinity();
    if (it == grid_.end()) return best;
    const Vec3& w = frame_.w;
    const gp_Lin ray(gp_Pnt(p[0], p[1], p[2]), up ? gp_Dir(w[0], w[1], w[2]) : gp_Dir(-w[0], -w[1], -w[2]));
    // Planes first: they are cheap, and for `any` one hit ends the search.
    for (int pass = 0; pass < 2; ++pass)
    for (int i : it->second) {
        const P2& a = lo_[static_cast<std::size_t>(i)];
        const P2& b = hi_[static_cast<std::size_t>(i)];
        if (q.x < a.x || q.x > b.x || q.y < a.y || q.y > b.y) continue;
        const FaceInfo& f = faces_[i];
        if ((f.kind == SurfaceKind::Plane) != (pass == 0)) continue;
        // Wholly behind the ray's start, or beyond the nearest hit so far.
        const double h = frame_.height(p);
        if (up ? (h1_[static_cast<std::size_t>(i)] < h || h0_[static_cast<std::size_t>(i)] - h > best)
               : (h0_[static_cast<std::size_t>(i)] > h || h - h1_[static_cast<std::size_t>(i)] > best))
            continue;
        if (any && !std::isinf(best)) return best;
        if (f.kind == SurfaceKind::Plane) {
            // Planes: meet the plane, then ask the face's own classifier.
            const double c = dot(f.normal, up ? w : Vec3{-w[0], -w[1], -w[2]});
            if (std::fabs(c) < 1e-12) continue;
            const Vec3& o = f.planePoint;
            const double t = dot(f.normal, Vec3{o[0] - p[0], o[1] - p[1], o[2] - p[2]}) / c;
            if (t < 0 || t >= best) continue;
            const gp_Pnt x(p[0] + t * ray.Direction().X(), p[1] + t * ray.Direction().Y(), p[2] + t * ray.Direction().Z());
            double u, v;
            ElSLib::Parameters(f.plane, x, u, v);
            if (faces_.classifyUV(i, u, v) != TopAbs_OUT) best = t;
            continue;
        }
        IntCurvesFace_Intersector& x = faces_.intersector(i);
        x.Perform(ray, 0, best);
        for (int k = 1; k <= x.NbPnt(); ++k)
            if (x.State(k) != TopAbs_OUT) best = std::min(best, x.WParameter(k));
    }
    return best;
}

bool AxisRays::reachable(int i) {
    const Vec3 p = faces_.interiorPoint(i);
    const Vec3& w = frame_.w;
    const double eps = 1e-4;  // start just off the face so it does not see itself
    return std::isinf(firstHit({p[0] + eps * w[0], p[1] + eps * w[1], p[2] + eps * w[2]}, true));
}

}  // namespace aeronc::recognition
