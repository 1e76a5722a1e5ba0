#pragma once
#include <aeronc/core/Vec3.h>

#include <cmath>

namespace aeronc::recognition {

struct P2 {
    double x = 0, y = 0;
};

// Right-handed frame with w along the setup direction: (u, v) span the slicing plane
// and h = p . w is the height along the tool axis.
struct SetupFrame {
    Vec3 u, v, w;
    // ref: a direction square to d to align u with (the part's principal axis), so the
    // blank box in this frame fits a rotated part; ignored when not square to d.
    explicit SetupFrame(const Vec3& d, const Vec3* ref = nullptr) {
        const double n = norm(d);
        w = {d[0] / n, d[1] / n, d[2] / n};
        // Seed with the world axis least aligned with w, so the frame is exact for ±X/Y/Z.
        Vec3 a{1, 0, 0};
        if (std::fabs(w[0]) > std::fabs(w[1]) && std::fabs(w[0]) > std::fabs(w[2])) a = {0, 1, 0};
        if (std::fabs(w[0]) <= std::fabs(w[1]) && std::fabs(w[0]) <= std::fabs(w[2])) a = {1, 0, 0};
        else if (std::fabs(w[1]) <= std::fabs(w[2])) a = {0, 1, 0};
        else a = {0, 0, 1};
        if (ref && std::fabs(dot(*ref, w)) < 1e-2 * norm(*ref)) a = *ref;
        const double k = dot(a, w);
        u = {a[0] - k * w[0], a[1] - k * w[1], a[2] - k * w[2]};
        const double un = norm(u);
        u = {u[0] / un, u[1] / un, u[2] / un};
        v = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]};
    }
    P2 project(const Vec3& p) const { return {dot(p, u), dot(p, v)}; }
    double height(const Vec3& p) const { return dot(p, w); }
    Vec3 world(const P2& p, double h) const {
        return {p.x * u[0] + p.y * v[0] + h * w[0], p.x * u[1] + p.y * v[1] + h * w[1],
                p.x * u[2] + p.y * v[2] + h * w[2]};
    }
};

}  // namespace aeronc::recognition
