#include "FaceRoles.h"

#include <aeronc/recognition/SetupFrame.h>

#include "FaceInSetup.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace aeronc::recognition {
namespace {

// The role of the faces of an attached feature; Unclaimed: the feature gives none.
FaceRole attachedRole(const AttachedFeature& a, const DomainElement& e) {
    if (a.kind == "corner_fillet") return e.hole ? FaceRole::HoleWall : FaceRole::CornerFillet;
    if (a.kind == "floor_fillet") return FaceRole::FloorFillet;
    if (a.kind == "open_corner") return FaceRole::OpenBevel;
    if (a.kind == "closed_corner") return FaceRole::ClosedBevel;
    if (a.kind == "countersink") return FaceRole::Countersink;
    if ((a.kind == "rib" && e.children.size() < 2) || a.kind == "island_top") return FaceRole::RibTop;
    return FaceRole::Unclaimed;
}

}  // namespace

void assignFaceRoles(DomainTree& tree, const FaceCatalogue& faces, const Tolerances& tol) {
    auto set = [&](int f, FaceRole r, int el) {
        const std::size_t i = static_cast<std::size_t>(f - 1);
        if (tree.faceRoles[i] != FaceRole::Unclaimed) return;
        tree.faceRoles[i] = r;
        tree.faceElement[i] = el;
    };
    for (int pass = 0; pass < 4; ++pass)
        for (const DomainElement& e : tree.elements) {
            const bool isHole = e.hole.has_value();
            if (pass == 0) {
                bool counterbore = false;
                for (int c : e.children)
                    counterbore |= isHole && tree.elements[static_cast<std::size_t>(c)].hole.has_value();
                for (int f : e.floorFaces) set(f, counterbore ? FaceRole::CounterboreFloor : FaceRole::Floor, e.id);
            } else if (pass == 1) {
                for (const AttachedFeature& a : e.attached)  // walls of a particular kind first
                    if (a.kind == "corner_fillet" || a.kind == "open_corner" || a.kind == "closed_corner")
                        for (int f : a.faces) set(f, attachedRole(a, e), e.id);
                for (int f : e.contourFaces) set(f, isHole ? FaceRole::HoleWall : FaceRole::Wall, e.id);
                for (auto& isl : e.islandFaces)
                    for (int f : isl) set(f, FaceRole::IslandWall, e.id);
            } else if (pass == 2) {
                for (const AttachedFeature& a : e.attached) {
                    const FaceRole r = attachedRole(a, e);
                    if (r != FaceRole::RibTop && r != FaceRole::Unclaimed)
                        for (int f : a.faces) set(f, r, e.id);
                }
                for (int f : e.chamferFaces) set(f, FaceRole::Chamfer, e.id);
            } else {
                for (const AttachedFeature& a : e.attached)
                    if (attachedRole(a, e) == FaceRole::RibTop)
                        for (int f : a.faces) set(f, FaceRole::RibTop, e.id);
            }
        }
    // What no element machines: the top of the part in the first setup, else stock.
    if (!tree.setups.empty()) {
        const SetupFrame frame(tree.setups[0].direction);
        const std::vector<FaceInSetup> fs = classifyFaces(faces, frame, tol);
        double hi = -std::numeric_limits<double>::infinity();
        for (const FaceInSetup& f : fs) hi = std::max(hi, f.hi);
        for (int i = 0; i < faces.size(); ++i) {
            if (tree.faceRoles[static_cast<std::size_t>(i)] != FaceRole::Unclaimed) continue;
            const FaceInSetup& f = fs[static_cast<std::size_t>(i)];
            const bool top = f.att == Attitude::Up && std::fabs(f.hi - hi) <= 10 * tol.linear;
            tree.faceRoles[static_cast<std::size_t>(i)] = top ? FaceRole::Top : FaceRole::Stock;
        }
    }
}

}  // namespace aeronc::recognition
