#include "HoleRecognition.h"

#include "FaceLists.h"

#include <cmath>

namespace aeronc::recognition {

double coneRadiusAt(const FaceInfo& c, const Vec3& w, double height) {
    const double sgn = dot(c.axisDir, w) > 0 ? 1 : -1;
    return std::fabs(c.radius + std::tan(c.semiAngle) * sgn * (height - dot(c.axisPoint, w)));
}

bool onDrillPoint(const SetupView& view, int f, double h) {
    const FaceCatalogue& faces = view.faces;
    const double tol = 10 * view.tol.linear;
    // A sphere is a ball end when it caps the hole: it meets only walls of this hole and
    // other pieces of the cap. A pocket's ball corner (corner radius equal to the floor
    // fillet's) also meets the floor fillets, and the pocket goes on below it.
    auto capsTheHole = [&](int sphere) {
        const FaceInfo& w = faces[f];
        for (int m : faces[sphere].neighbours) {
            const FaceInfo& g = faces[m];
            if (m == f || g.kind == SurfaceKind::Sphere) continue;
            if (g.kind != SurfaceKind::Cylinder || !g.concave || std::fabs(g.radius - w.radius) > tol ||
                std::fabs(dot(g.axisDir, w.axisDir)) < view.tol.parallelCos)
                return false;
            const Vec3 d{g.axisPoint[0] - w.axisPoint[0], g.axisPoint[1] - w.axisPoint[1],
                         g.axisPoint[2] - w.axisPoint[2]};
            const double along = dot(d, w.axisDir) / norm(w.axisDir);
            if (std::sqrt(std::max(0.0, dot(d, d) - along * along)) > tol) return false;
        }
        return true;
    };
    for (int n : faces[f].neighbours) {
        const FaceInfo& c = faces[n];
        const FaceInSetup& cs = view.fs[static_cast<std::size_t>(n)];
        if (cs.hi > h + tol) continue;
        if (c.kind == SurfaceKind::Sphere && capsTheHole(n)) return true;
        if (c.kind == SurfaceKind::Cone && coneRadiusAt(c, view.axis, cs.lo) < faces[f].radius - 10 * view.tol.linear)
            return true;
    }
    return false;
}

namespace {

// One circular contour of concave vertical cylinders, no islands, not open.
void recogniseHole(ElementDraft& in, const SetupView& view) {
    const FaceCatalogue& faces = view.faces;
    const SetupFrame& frame = view.frame;
    DomainElement& e = in.el;
    if (!e.islandFaces.empty() || e.contourFaces.empty() || e.type == ElementType::OpenPocket) return;
    const FaceInfo& f0 = faces[e.contourFaces[0] - 1];
    const double tol = 10 * view.tol.linear;
    for (int f : e.contourFaces) {
        const FaceInfo& fi = faces[f - 1];
        if (fi.kind != SurfaceKind::Cylinder || !fi.concave ||
            view.fs[static_cast<std::size_t>(f - 1)].att != Attitude::Vertical)
            return;
        if (std::fabs(fi.radius - f0.radius) > tol) return;
        const Vec3 dp{fi.axisPoint[0] - f0.axisPoint[0], fi.axisPoint[1] - f0.axisPoint[1],
                      fi.axisPoint[2] - f0.axisPoint[2]};
        const double along = dot(dp, frame.w);
        const Vec3 perp{dp[0] - along * frame.w[0], dp[1] - along * frame.w[1], dp[2] - along * frame.w[2]};
        if (norm(perp) > tol) return;
    }
    HoleInfo hi;
    hi.diameter = 2 * f0.radius;
    hi.through = e.type == ElementType::Opening;
    hi.axis = frame.w;
    const P2 c = frame.project(f0.axisPoint);
    hi.location = frame.world(c, e.top);
    hi.depth = e.depth;
    // Countersink: a concave cone on the axis above the wall; drill point: below it.
    for (int f : e.contourFaces)
        for (int n : faces[f - 1].neighbours) {
            const FaceInfo& cf = faces[n];
            const FaceInSetup& cs = view.fs[static_cast<std::size_t>(n)];
            if (cf.kind != SurfaceKind::Cone || std::fabs(dot(cf.axisDir, frame.w)) < view.tol.parallelCos) continue;
            if (cs.lo >= e.top - tol) {
                const double sgn = dot(cf.axisDir, frame.w) > 0 ? 1 : -1;
                const double href = dot(cf.axisPoint, frame.w);
                const double rTop = cf.radius + std::tan(cf.semiAngle) * sgn * (cs.hi - href);
                hi.countersinkDiameter = 2 * std::fabs(rTop);
                hi.countersinkAngle = 2 * cf.semiAngle * 180 / M_PI;
                pushUnique(e.chamferFaces, n + 1);
                AttachedFeature a;
                a.kind = "countersink";
                a.faces = {n + 1};
                a.size = hi.countersinkDiameter;
                e.attached.push_back(a);
            } else if (cs.hi <= e.level + tol && coneRadiusAt(cf, view.axis, cs.lo) < f0.radius - tol) {
                pushUnique(e.floorFaces, n + 1);  // drill point is the hole's bottom
            }
        }
    e.type = ElementType::Hole;
    e.hole = hi;
    e.minWidth = hi.diameter;  // a round region: no erosion needed
}

}  // namespace

void recogniseHoles(std::vector<ElementDraft>& made, const SetupView& view) {
    for (ElementDraft& in : made)
        if (!in.el.hole) recogniseHole(in, view);
}

void recogniseCounterbores(std::vector<ElementDraft>& made, const SetupView& view) {
    // Counterbore: the wider hole above a hole, on the same axis.
    const double tol = 10 * view.tol.linear;
    const SetupFrame& frame = view.frame;
    for (ElementDraft& in : made) {
        DomainElement& e = in.el;
        if (!e.hole || e.parent < 0 || in.dropped) continue;
        DomainElement& p = made[static_cast<std::size_t>(e.parent)].el;
        if (!p.hole || p.hole->diameter <= e.hole->diameter) continue;
        const Vec3 dl{p.hole->location[0] - e.hole->location[0], p.hole->location[1] - e.hole->location[1],
                      p.hole->location[2] - e.hole->location[2]};
        const double along = dot(dl, frame.w);
        const Vec3 perp{dl[0] - along * frame.w[0], dl[1] - along * frame.w[1], dl[2] - along * frame.w[2]};
        if (norm(perp) > tol) continue;
        e.hole->counterboreDiameter = p.hole->diameter;
        e.hole->counterboreDepth = p.depth;
    }
}

}  // namespace aeronc::recognition
