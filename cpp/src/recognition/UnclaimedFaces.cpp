#include "UnclaimedFaces.h"

#include <cmath>
#include <string>

namespace aeronc::recognition {

void markBlankBoundaryFaces(const SetupView& view, std::vector<bool>& onBlank) {
    const FaceCatalogue& faces = view.faces;
    const SetupFrame& fr = view.frame;
    const double tol = 10 * view.tol.linear;
    onBlank.resize(static_cast<std::size_t>(faces.size()), false);
    // A plane lies on a side of the box when it is square to that side's axis at its height.
    auto onSide = [&](const FaceInfo& f, const Vec3& axis, double lo, double hi) {
        if (std::fabs(dot(f.normal, axis)) < view.tol.parallelCos) return false;
        const double h = dot(f.planePoint, axis);
        return std::fabs(h - lo) <= tol || std::fabs(h - hi) <= tol;
    };
    for (int i = 0; i < faces.size(); ++i) {
        const FaceInfo& f = faces[i];
        if (f.kind != SurfaceKind::Plane) continue;
        if (onSide(f, fr.w, view.blankH0, view.blankH1) || onSide(f, fr.u, view.blankLo.x, view.blankHi.x) ||
            onSide(f, fr.v, view.blankLo.y, view.blankHi.y))
            onBlank[static_cast<std::size_t>(i)] = true;
    }
}

void reportUnclaimedFaces(DomainTree& tree, const std::vector<bool>& onBlank) {
    tree.unclaimedFaces.clear();
    for (std::size_t i = 0; i < tree.faceElement.size(); ++i)
        if (tree.faceElement[i] < 0 && !(i < onBlank.size() && onBlank[i]))
            tree.unclaimedFaces.push_back(static_cast<int>(i) + 1);
    if (tree.unclaimedFaces.empty()) return;
    std::string list;
    for (int f : tree.unclaimedFaces) list += (list.empty() ? "Face" : ", Face") + std::to_string(f);
    const std::size_t n = tree.unclaimedFaces.size();
    tree.warnings.push_back(std::to_string(n) + (n == 1 ? " face lies" : " faces lie") +
                            " inside the blank but no element machines " + (n == 1 ? "it: " : "them: ") + list);
}

}  // namespace aeronc::recognition
