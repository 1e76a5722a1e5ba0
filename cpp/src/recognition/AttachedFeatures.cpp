#include "AttachedFeatures.h"

#include "FaceLists.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace aeronc::recognition {

void attachElementFeatures(std::vector<ElementDraft>& made, const SetupView& view, const std::vector<bool>& boxSides) {
    const FaceCatalogue& faces = view.faces;
    const std::vector<FaceInSetup>& fs = view.fs;
    const double tol = 10 * view.tol.linear;
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (ElementDraft& in : made) {
        DomainElement& e = in.el;
        std::set<int> inLoops(e.contourFaces.begin(), e.contourFaces.end());
        for (auto& isl : e.islandFaces) inLoops.insert(isl.begin(), isl.end());
        // Floor fillets: curved faces between the floor and the walls.
        double ff = kInf;
        std::vector<int> fillets;
        for (int f : e.floorFaces)
            for (int n : faces[f - 1].neighbours) {
                const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                const SurfaceKind k = faces[n].kind;
                if (s.att != Attitude::Curved || k == SurfaceKind::Cone) continue;
                // A round falling away from the floor's edge (a convex edge of the part) rises to
                // no wall: not a fillet the cutter's corner must fit.
                if (s.hi <= e.level + tol) continue;
                if (std::find(fillets.begin(), fillets.end(), n + 1) != fillets.end()) continue;
                fillets.push_back(n + 1);
                if (k == SurfaceKind::Cylinder || k == SurfaceKind::Torus || k == SurfaceKind::Sphere)
                    ff = std::min(ff, faces[n].radius);
            }
        // Fillet corners (tori, spheres) touching the fillets found.
        for (std::size_t q = 0; q < fillets.size(); ++q)
            for (int n : faces[fillets[q] - 1].neighbours) {
                const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                if (s.att == Attitude::Curved && faces[n].kind != SurfaceKind::Cone &&
                    std::fabs(s.lo - e.level) <= tol && !inLoops.count(n + 1) &&
                    std::find(fillets.begin(), fillets.end(), n + 1) == fillets.end())
                    fillets.push_back(n + 1);
            }
        e.filletFaces = fillets;
        e.floorFilletRadius = std::isfinite(ff) ? ff : 0;
        if (!fillets.empty()) {
            AttachedFeature a;
            a.kind = "floor_fillet";
            a.faces = fillets;
            a.radius = e.floorFilletRadius;
            e.attached.push_back(a);
        }
        // Chamfers and bevels on the side walls.
        std::set<int> seen;
        for (int w : inLoops) {
            const FaceInSetup& ws = fs[static_cast<std::size_t>(w - 1)];
            if (ws.att == Attitude::Inclined) {
                AttachedFeature a;
                const double c = dot(faces[w - 1].normal, view.frame.w);
                a.kind = c > 0 ? "open_corner" : "closed_corner";
                a.faces = {w};
                a.size = std::asin(std::min(1.0, std::fabs(c))) * 180 / M_PI;
                // A bevel facing the tool more than sideways takes the rounds that blend it into
                // its neighbours in the loop: what finishes the bevel finishes them.
                if (c > 0 && a.size >= 45)
                    for (int n : faces[w - 1].neighbours)
                        if (inLoops.count(n + 1) && fs[static_cast<std::size_t>(n)].att == Attitude::Curved)
                            a.faces.push_back(n + 1);
                e.attached.push_back(a);
            }
            for (int n : faces[w - 1].neighbours) {
                if (inLoops.count(n + 1) || seen.count(n)) continue;
                const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                if (s.att == Attitude::Inclined && !boxSides[static_cast<std::size_t>(n)]) {
                    seen.insert(n);
                    e.chamferFaces.push_back(n + 1);
                }
            }
        }
        if (!e.chamferFaces.empty()) {
            AttachedFeature a;
            a.kind = "chamfer";
            a.faces = e.chamferFaces;
            // The mill's included angle is twice the planes' angle to the axis; their width across
            // the axis is their height over the tangent of their normal's angle to it.
            double angle = -1;
            double narrowest = kInf, lowest = kInf, highest = -kInf;  // width; lower line's height
            for (int f : e.chamferFaces) {
                const FaceInfo& cf = faces[f - 1];
                const FaceInSetup& s = fs[static_cast<std::size_t>(f - 1)];
                const double c = cf.kind == SurfaceKind::Plane ? dot(cf.normal, view.frame.w) : 0;
                if (!(c > 1e-6 && c < 1 - 1e-6)) {
                    angle = 0;
                    continue;
                }
                const double beta = std::acos(c);
                const double width = (s.hi - s.lo) / std::tan(beta);
                a.size = std::max(a.size, width);
                narrowest = std::min(narrowest, width);
                lowest = std::min(lowest, s.lo), highest = std::max(highest, s.lo);
                const double included = 180 - 2 * beta * 180 / M_PI;
                if (angle < 0) angle = included;
                else if (std::fabs(angle - included) > 0.1) angle = 0;
            }
            a.angle = std::max(0.0, angle);
            // One pass along the outer loop cuts the chamfer only if it runs there at one width
            // from one line, on every wall of the loop (each ending at that line) and on no
            // island: elsewhere the mill's cone would cut a chamfer the part does not have.
            constexpr double kSameWidth = 0.01;  // mm
            const std::set<int> chamfers(e.chamferFaces.begin(), e.chamferFaces.end());
            auto meetsChamfer = [&](int w) {
                for (int n : faces[w - 1].neighbours)
                    if (chamfers.count(n + 1)) return true;
                return false;
            };
            const bool even = a.angle > 0 && a.size - narrowest <= kSameWidth && highest - lowest <= tol;
            auto allMeet = [&](const std::vector<int>& walls) {
                for (int w : walls)
                    if (!meetsChamfer(w) || std::fabs(fs[static_cast<std::size_t>(w - 1)].hi - lowest) > tol) return false;
                return !walls.empty();
            };
            auto noneMeets = [&](const std::vector<int>& walls) {
                return std::none_of(walls.begin(), walls.end(), meetsChamfer);
            };
            bool islandsClear = true;
            std::vector<int> round;  // islands chamfered along every wall
            for (std::size_t k = 0; k < e.islandFaces.size(); ++k) {
                if (noneMeets(e.islandFaces[k])) continue;
                islandsClear = false;
                if (allMeet(e.islandFaces[k])) round.push_back(static_cast<int>(k));
            }
            if (even && allMeet(e.contourFaces) && islandsClear) a.alongContour = true, a.lower = lowest;
            // Round islands only: every island chamfered all round, the outer loop not at all. (All
            // of them: the islands' faces and their loops are not listed in one order.)
            if (even && !round.empty() && round.size() == e.islandFaces.size() && noneMeets(e.contourFaces))
                a.alongIslands = round, a.lower = lowest;
            e.attached.push_back(a);
        }
        // Island tops: faces normal to the axis on top of the island walls.
        for (auto& isl : e.islandFaces) {
            double islTop = -kInf;
            for (int f : isl) islTop = std::max(islTop, fs[static_cast<std::size_t>(f - 1)].hi);
            AttachedFeature a;
            a.kind = "island_top";
            for (int f : isl)
                for (int n : faces[f - 1].neighbours) {
                    const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                    if (s.att == Attitude::Up && std::fabs(s.h - islTop) <= tol && islTop < e.top - tol)
                        pushUnique(a.faces, n + 1);
                }
            if (!a.faces.empty()) e.attached.push_back(a);
        }
        // Top constraint: faces normal to the axis at the top of the walls.
        for (int w : e.contourFaces)
            for (int n : faces[w - 1].neighbours) {
                const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                if (s.att == Attitude::Up && std::fabs(s.h - e.top) <= tol) pushUnique(e.topFaces, n + 1);
            }
    }
}

void attachTreeFeatures(std::vector<ElementDraft>& made) {
    // Joggle: a shallow child pocket that shares a side wall with its parent.
    for (ElementDraft& in : made) {
        DomainElement& e = in.el;
        if (e.parent < 0 || e.hole || e.type == ElementType::Opening) continue;
        DomainElement& p = made[static_cast<std::size_t>(e.parent)].el;
        const double step = p.level - e.level;
        bool shares = false;
        for (int f : e.contourFaces)
            shares |= std::find(p.contourFaces.begin(), p.contourFaces.end(), f) != p.contourFaces.end();
        if (shares && step < 0.5 * p.depth) {
            AttachedFeature a;
            a.kind = "joggle";
            a.element = e.id;
            a.size = step;
            a.faces = e.floorFaces;
            p.attached.push_back(a);
        }
    }
    // Rib: the floor of a region joining several pockets is the top of the rib between them.
    for (ElementDraft& in : made) {
        DomainElement& e = in.el;
        if (e.children.size() >= 2 && e.floorArea < 0.5 * e.area && !e.floorFaces.empty()) {
            AttachedFeature a;
            a.kind = "rib";
            a.faces = e.floorFaces;
            e.attached.push_back(a);
        }
        if (e.type == ElementType::OpenPocket && !e.openEdges.empty() && e.minWidth > 0 &&
            e.area > 4 * e.minWidth * e.minWidth) {
            AttachedFeature a;
            a.kind = "flange";
            a.faces = e.floorFaces;
            a.size = e.minWidth;
            e.attached.push_back(a);
        }
    }
}

}  // namespace aeronc::recognition
