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

double arcToleranceFor(double radius) { return std::max(radius * 2e-3, 2e-4); }

Opening openRegion(const PocketRegion& region, double radius) {
    if (!(radius > 0) || !std::isfinite(radius))
        throw inputError("tool radius " + std::to_string(radius) + " mm must be positive");
    const double tol = arcToleranceFor(radius);
    Opening o;
    Paths eroded = offsetRegion(region.paths, -radius, tol);
    if (eroded.empty()) return o;
    // The round joins leave runs of near-collinear points; dropping them halves the
    // dilation's cost and moves the boundary by less than the arc tolerance.
    CleanPolygons(eroded, o.eroded, tol * kScale);
    // Clipper's arcs are inscribed chords and would lose (2/3)·tol·arc length; a radius
    // giving the polygon the circle's area cancels that to first order. Along the walls
    // the extra is clipped off below.
    const double step = 2 * std::acos(1 - tol / radius);
    const double equalArea = radius * std::sqrt(step / std::sin(step));
    const Paths opened = offsetRegion(o.eroded, equalArea, tol);
    Clipper c;
    c.AddPaths(opened, ptSubject, true);
    c.AddPaths(region.paths, ptClip, true);
    Paths clipped;
    c.Execute(ctIntersection, clipped, pftNonZero, pftNonZero);
    o.machinableArea = areaOf(clipped);
    return o;
}

}  // namespace aeronc::toolselect
