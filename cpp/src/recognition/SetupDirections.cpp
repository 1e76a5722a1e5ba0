#include "SetupDirections.h"

#include <aeronc/core/Error.h>
#include <aeronc/recognition/SetupFrame.h>

#include "AxisRays.h"
#include "FaceInSetup.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>

namespace aeronc::recognition {

std::string directionName(const Vec3& d) {
    const char* axes[3] = {"X", "Y", "Z"};
    for (int k = 0; k < 3; ++k) {
        if (std::fabs(std::fabs(d[k]) - 1) < 1e-9) return std::string(d[k] > 0 ? "+" : "-") + axes[k];
    }
    std::ostringstream s;
    s.precision(4);
    s << "(" << d[0] << ", " << d[1] << ", " << d[2] << ")";
    return s.str();
}

std::vector<Vec3> principalAxes(const FaceCatalogue& faces, const Tolerances& tol) {
    // Planar area per normal direction (up to sign), largest first.
    struct Group {
        Vec3 n;  // the normal of its largest face
        double area, largest;
    };
    std::vector<Group> groups;
    for (int i = 0; i < faces.size(); ++i) {
        if (faces[i].kind != SurfaceKind::Plane) continue;
        const Vec3& n = faces[i].normal;
        const double a = faces.area(i);
        bool found = false;
        for (Group& g : groups)
            if (std::fabs(dot(g.n, n)) >= tol.parallelCos) {
                g.area += a, found = true;
                if (a > g.largest) g.largest = a, g.n = n;
                break;
            }
        if (!found) groups.push_back({n, a, a});
    }
    if (groups.empty()) return {};
    std::stable_sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) { return a.area > b.area; });
    auto cross = [](const Vec3& a, const Vec3& b) {
        return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    // The frame of two square normal directions that holds the most planar area: the box a
    // machinist would clamp, even when a slanted face is the largest (a wide chamfer or
    // ramp on a small block).
    const std::size_t firsts = std::min<std::size_t>(groups.size(), 6);
    int bestA = 0, bestB = -1;
    double bestArea = -1;
    for (std::size_t a = 0; a < firsts; ++a) {
        bool any = false;
        for (std::size_t b = 0; b < groups.size(); ++b) {
            if (b == a || std::fabs(dot(groups[a].n, groups[b].n)) > tol.squareSin) continue;
            any = true;
            const Vec3 n3 = cross(groups[a].n, groups[b].n);
            double area = groups[a].area + groups[b].area;
            for (const Group& g : groups)
                if (std::fabs(dot(g.n, n3)) >= tol.parallelCos) area += g.area;
            if (area > bestArea * (1 + 1e-9)) bestArea = area, bestA = static_cast<int>(a), bestB = static_cast<int>(b);
        }
        if (!any && groups[a].area > bestArea * (1 + 1e-9)) bestArea = groups[a].area, bestA = static_cast<int>(a), bestB = -1;
    }
    const Vec3 n1 = groups[static_cast<std::size_t>(bestA)].n;
    std::vector<Vec3> out{n1, {-n1[0], -n1[1], -n1[2]}};
    if (bestB < 0) return out;
    const Vec3 n2 = groups[static_cast<std::size_t>(bestB)].n;
    const Vec3 n3 = cross(n1, n2);
    for (const Vec3& n : {n2, n3}) out.push_back(n), out.push_back({-n[0], -n[1], -n[2]});
    return out;
}

Vec3 checkedDirection(const FaceCatalogue& faces, const Tolerances& tol, const Vec3& dir, std::size_t k) {
    const double n = norm(dir);
    if (!(n > 1e-12) || !std::isfinite(n))
        throw inputError("setup direction " + std::to_string(k + 1) + " is not a valid vector");
    const Vec3 d{dir[0] / n, dir[1] / n, dir[2] / n};
    for (int i = 0; i < faces.size(); ++i)
        if (faces[i].kind == SurfaceKind::Plane && std::fabs(dot(faces[i].normal, d)) >= tol.parallelCos) return d;
    throw inputError("the part has no planar face normal to the setup direction " + directionName(d) +
                     "; pick a direction along a face normal");
}

SetupDirectionSearch::SetupDirectionSearch(const FaceCatalogue& faces, const Tolerances& tol)
    : faces_(faces), tol_(tol), consumed_(static_cast<std::size_t>(faces.size()), false) {}

namespace {
constexpr double kPrincipalShare = 0.2;  // of the best direction's score
}  // namespace

std::optional<Vec3> SetupDirectionSearch::next(const std::vector<bool>& claimed) {
    std::vector<Vec3> cands;
    for (int i = 0; i < faces_.size(); ++i) {
        const FaceInfo& f = faces_[i];
        if (claimed[static_cast<std::size_t>(i)] || consumed_[static_cast<std::size_t>(i)]) continue;
        if (f.kind == SurfaceKind::Plane) cands.push_back(f.normal);
        if (f.kind == SurfaceKind::Cylinder && f.concave) {
            cands.push_back(f.axisDir);
            cands.push_back({-f.axisDir[0], -f.axisDir[1], -f.axisDir[2]});
        }
    }
    // Unique directions.
    std::vector<Vec3> dirs;
    for (const Vec3& c : cands) {
        bool seen = false;
        for (const Vec3& d : dirs) seen |= dot(d, c) >= tol_.parallelCos;
        for (const Vec3& d : tried_) seen |= dot(d, c) >= tol_.parallelCos;
        if (!seen) dirs.push_back(c);
    }
    // The part's principal axes first, as a machinist clamps it: a slanted face (an edge
    // chamfer, a step a few degrees off) calls for a tilted setup only when it holds far more
    // to machine than any principal axis.
    if (axes_.empty()) axes_ = principalAxes(faces_, tol_);
    auto principal = [&](const Vec3& d) {
        for (const Vec3& a : axes_)
            if (dot(a, d) >= tol_.parallelCos) return true;
        return false;
    };
    double bestScore = 0, bestPrincipalScore = 0;
    Vec3 best{0, 0, 0}, bestPrincipal{0, 0, 0};
    const auto ts = std::chrono::steady_clock::now();
    for (const Vec3& d : dirs) {
        const double s = score(d, claimed, false);
        // Ties resolve by the score only up to rounding, then by the first found.
        if (s > bestScore * (1 + 1e-9) + 1e-9) bestScore = s, best = d;
        if (principal(d) && s > bestPrincipalScore * (1 + 1e-9) + 1e-9) bestPrincipalScore = s, bestPrincipal = d;
    }
    if (bestPrincipalScore >= kPrincipalShare * bestScore && bestPrincipalScore > 0)
        bestScore = bestPrincipalScore, best = bestPrincipal;
    if (std::getenv("AERONC_TRACE"))
        std::fprintf(stderr, "scored %zu directions: %.3f s\n", dirs.size(),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count());
    if (bestScore <= 0) return std::nullopt;
    tried_.push_back(best);
    score(best, claimed, true);
    return best;
}

std::vector<Vec3> SetupDirectionSearch::untriedPrincipalAxes() {
    std::vector<Vec3> out;
    for (const Vec3& d : principalAxes(faces_, tol_)) {
        bool seen = false;
        for (const Vec3& t : tried_) seen |= dot(d, t) >= tol_.parallelCos;
        if (seen) continue;
        tried_.push_back(d);
        out.push_back(d);
    }
    return out;
}

void SetupDirectionSearch::setAside(const std::vector<bool>& faces) {
    for (std::size_t i = 0; i < faces.size() && i < consumed_.size(); ++i)
        if (faces[i]) consumed_[i] = true;
}

bool SetupDirectionSearch::markTried(const Vec3& d) {
    for (const Vec3& t : tried_)
        if (dot(d, t) >= tol_.parallelCos) return false;
    tried_.push_back(d);
    return true;
}

// Unclaimed floor area seen from d plus half the unclaimed concave cylinder area along d.
double SetupDirectionSearch::score(const Vec3& d, const std::vector<bool>& claimed, bool consume) {
    const SetupFrame frame(d);
    std::unique_ptr<AxisRays> rays;  // built on the first floor that needs it
    double s = 0;
    for (int i = 0; i < faces_.size(); ++i) {
        if (claimed[static_cast<std::size_t>(i)] || consumed_[static_cast<std::size_t>(i)]) continue;
        const double before = s;
        const FaceInfo& f = faces_[i];
        if (f.kind == SurfaceKind::Plane && dot(f.normal, frame.w) >= tol_.parallelCos) {
            // A floor: a neighbour rises above it, and the tool reaches it.
            const double h = dot(f.planePoint, frame.w);
            bool rising = false;
            for (int n : f.neighbours) rising = rising || faces_.boundaryTop(n, frame.w) > h + 10 * tol_.linear;
            if (rising && !rays) rays = std::make_unique<AxisRays>(faces_, frame);
            if (rising && rays->reachable(i)) s += faces_.area(i);
        } else if (f.kind == SurfaceKind::Cylinder && f.concave && std::fabs(dot(f.axisDir, frame.w)) >= tol_.parallelCos) {
            s += 0.5 * faces_.area(i);
        }
        if (consume && s > before) consumed_[static_cast<std::size_t>(i)] = true;
    }
    return s;
}

namespace {
void renumberSetup(DomainTree& tree, int e, int setup) {
    DomainElement& el = tree.elements[static_cast<std::size_t>(e)];
    el.setup = setup;
    for (int c : el.children) renumberSetup(tree, c, setup);
}
}  // namespace

void dropEmptySetups(DomainTree& tree) {
    std::vector<SetupDirection> keep;
    for (SetupDirection& s : tree.setups)
        if (!s.elements.empty()) {
            for (int e : s.elements) renumberSetup(tree, e, static_cast<int>(keep.size()));
            s.id = static_cast<int>(keep.size());
            keep.push_back(std::move(s));
        }
    tree.setups = std::move(keep);
}

}  // namespace aeronc::recognition
