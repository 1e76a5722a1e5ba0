#include "ElementMeasures.h"

#include "FaceClaims.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <cmath>
#include <limits>
#include <map>

namespace aeronc::recognition {
using namespace ClipperLib;

double RegionWidths::minWidth(const Region& r) {
    std::string key;
    auto add = [&](const Path& p) {
        for (const IntPoint& q : p) {
            const cInt d[2] = {q.X - p[0].X, q.Y - p[0].Y};
            key.append(reinterpret_cast<const char*>(d), sizeof d);
        }
        const cInt o[2] = {p[0].X - r.outer[0].X, p[0].Y - r.outer[0].Y};
        key.append(reinterpret_cast<const char*>(o), sizeof o);
        key.push_back('|');
    };
    add(r.outer);
    for (const Path& h : r.holes) add(h);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = widths_.find(key);
        if (it != widths_.end()) return it->second;
    }
    // Measured on the shape moved to the origin, so that every copy of it gives the same
    // figure whichever thread measures it first. Outside the lock: two threads may both
    // measure one shape.
    Region at0 = r;
    const IntPoint o = r.outer[0];
    auto shift = [&](Path& p) {
        for (IntPoint& q : p) q.X -= o.X, q.Y -= o.Y;
    };
    shift(at0.outer);
    for (Path& h : at0.holes) shift(h);
    at0.updateBox();
    const double w = at0.minWidth();
    std::lock_guard<std::mutex> lock(mutex_);
    widths_.emplace(std::move(key), w);
    return w;
}

void measureWidths(std::vector<ElementDraft>& made, const std::vector<bool>& claimed, RegionWidths& widths,
                   int threads) {
    std::vector<std::size_t> todo;
    for (std::size_t k = 0; k < made.size(); ++k) {
        const ElementDraft& d = made[k];
        if (d.el.minWidth >= 0 || d.dropped) continue;
        if (takenEarlier(d.el, claimed)) {
            made[k].el.minWidth = 0;  // claimFaces drops it: never shown
            continue;
        }
        todo.push_back(k);
    }
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t i; (i = next++) < todo.size();) made[todo[i]].el.minWidth = widths.minWidth(made[todo[i]].region);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min<int>(threads, static_cast<int>(todo.size())); ++t) pool.emplace_back(work);
    work();
    for (std::thread& t : pool) t.join();
}

void measureCorners(const VoidRegion& c, const FaceCatalogue& faces, const std::vector<FaceInSetup>& fs,
                    DomainElement& e) {
    double r = std::numeric_limits<double>::infinity();
    std::map<double, std::vector<int>> corners;  // FaceN of the concave corners, by radius
    auto visit = [&](const SectionLoop& L, bool voidLeft) {
        const std::size_t n = L.pts.size();
        for (std::size_t i = 0; i < n; ++i) {
            const int f = L.faces[i];
            if (f < 0) continue;
            const FaceInfo& fi = faces[f];
            if (fi.kind == SurfaceKind::Cylinder && fs[static_cast<std::size_t>(f)].att == Attitude::Vertical &&
                fi.concave) {
                r = std::min(r, fi.radius);
                auto& v = corners[std::round(fi.radius * 1e6) / 1e6];
                if (std::find(v.begin(), v.end(), f + 1) == v.end()) v.push_back(f + 1);
            }
            const int g = L.faces[(i + 1) % n];
            if (g == f || g < 0 || fi.kind != SurfaceKind::Plane || faces[g].kind != SurfaceKind::Plane) continue;
            const P2& a = L.pts[i];
            const P2& b = L.pts[(i + 1) % n];
            const P2& q = L.pts[(i + 2) % n];
            const double ux = b.x - a.x, uy = b.y - a.y, vx = q.x - b.x, vy = q.y - b.y;
            const double cr = ux * vy - uy * vx;
            const double sn = cr / (std::hypot(ux, uy) * std::hypot(vx, vy) + 1e-300);
            // A turn towards the void side is a corner the tool cannot reach.
            if ((voidLeft ? sn : -sn) > std::sin(0.05)) r = 0;
        }
    };
    for (std::size_t k = 0; k < c.contourLoops.size(); ++k) visit(*c.contourLoops[k], c.contourVoidLeft[k]);
    for (const SectionLoop* L : c.islandLoops) visit(*L, false);
    e.minCornerRadius = std::isfinite(r) ? r : -1;
    for (auto& kv : corners) {
        AttachedFeature a;
        a.kind = "corner_fillet";
        a.radius = kv.first;
        a.faces = kv.second;
        e.attached.push_back(a);
    }
}

}  // namespace aeronc::recognition
