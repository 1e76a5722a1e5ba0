#include "EdgeChamfers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace aeronc::recognition {

EdgeCuts findEdgeChamfers(const FaceCatalogue& faces, const Tolerances& tol, const std::vector<Vec3>& axes) {
    EdgeCuts out;
    out.chamfers.assign(static_cast<std::size_t>(faces.size()), false);
    out.stepWalls = out.chamfers;
    out.boxSides = out.chamfers;
    // Three axes, one of each ± pair.
    std::vector<Vec3> frame;
    for (const Vec3& a : axes) {
        bool seen = false;
        for (const Vec3& b : frame) seen |= std::fabs(dot(a, b)) >= tol.parallelCos;
        if (!seen) frame.push_back(a);
    }
    if (frame.size() != 3) return out;
    // The part's box along them, from points on every face's boundary.
    std::array<double, 3> lo, hi;
    lo.fill(std::numeric_limits<double>::max()), hi.fill(-std::numeric_limits<double>::max());
    for (int i = 0; i < faces.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            hi[static_cast<std::size_t>(k)] = std::max(hi[static_cast<std::size_t>(k)], faces.boundaryTop(i, frame[static_cast<std::size_t>(k)]));
            const Vec3 neg{-frame[static_cast<std::size_t>(k)][0], -frame[static_cast<std::size_t>(k)][1], -frame[static_cast<std::size_t>(k)][2]};
            lo[static_cast<std::size_t>(k)] = std::min(lo[static_cast<std::size_t>(k)], -faces.boundaryTop(i, neg));
        }
    const double lin = std::max(10 * tol.linear, 1e-6 * (hi[0] - lo[0] + hi[1] - lo[1] + hi[2] - lo[2]));
    for (int i = 0; i < faces.size(); ++i) {
        const FaceInfo& f = faces[i];
        if (f.kind != SurfaceKind::Plane) continue;
        for (int k = 0; k < 3; ++k) {
            const Vec3& a = frame[static_cast<std::size_t>(k)];
            const double c = dot(f.normal, a), h = dot(f.planePoint, a);
            if (c >= tol.parallelCos) out.boxSides[static_cast<std::size_t>(i)] = std::fabs(h - hi[static_cast<std::size_t>(k)]) <= lin;
            if (c <= -tol.parallelCos) out.boxSides[static_cast<std::size_t>(i)] = std::fabs(h - lo[static_cast<std::size_t>(k)]) <= lin;
        }
        // Square to one axis, slanted to the other two.
        int along = -1, slanted = 0;
        for (int k = 0; k < 3; ++k) {
            const double c = std::fabs(dot(f.normal, frame[static_cast<std::size_t>(k)]));
            if (c <= tol.squareSin) along = k;
            else if (c < tol.parallelCos) ++slanted;
        }
        if (along < 0 || slanted != 2) continue;
        // It reaches both box sides its normal points to: it cuts that edge of the box off.
        bool both = true;
        for (int k = 0; k < 3; ++k) {
            if (k == along) continue;
            const Vec3& a = frame[static_cast<std::size_t>(k)];
            const bool up = dot(f.normal, a) > 0;
            const Vec3 d = up ? a : Vec3{-a[0], -a[1], -a[2]};
            const double reach = faces.boundaryTop(i, d);
            const double side = up ? hi[static_cast<std::size_t>(k)] : -lo[static_cast<std::size_t>(k)];
            both = both && std::fabs(reach - side) <= lin;
        }
        // A plane square to the edge that the face rises from on its void side is a floor
        // under it: the wall of a blind step cut across the edge, not a chamfer.
        if (!both) continue;
        bool floor = false;
        for (int n : f.neighbours) {
            const FaceInfo& g = faces[n];
            if (g.kind == SurfaceKind::Plane &&
                std::fabs(dot(g.normal, frame[static_cast<std::size_t>(along)])) >= tol.parallelCos)
                floor = floor || faces.boundaryTop(i, g.normal) > dot(g.normal, g.planePoint) + lin;
        }
        (floor ? out.stepWalls : out.chamfers)[static_cast<std::size_t>(i)] = true;
    }
    return out;
}

}  // namespace aeronc::recognition
