#pragma once
// Setup directions (tool axes): the ones asked for, checked, or found from the part by
// what is still to machine, then the part's principal axes.
#include <aeronc/recognition/DomainTree.h>

#include "FaceCatalogue.h"
#include "Tolerances.h"

#include <optional>
#include <string>
#include <vector>

namespace aeronc::recognition {

// "+Z", "-X", ... for the world axes, else the vector.
std::string directionName(const Vec3& d);

// ± two square planar normals and their cross product: of the frame whose axes the most
// planar area is normal to, each axis the normal of its largest face; empty for a part
// without planar faces.
std::vector<Vec3> principalAxes(const FaceCatalogue& faces, const Tolerances& tol);

// The k-th (0-based) direction asked for, made unit; throws an input error when it is no
// vector or no planar face of the part is normal to it.
Vec3 checkedDirection(const FaceCatalogue& faces, const Tolerances& tol, const Vec3& d, std::size_t k);

// Directions found from the part, one at a time, as the setups claim faces.
class SetupDirectionSearch {
public:
    SetupDirectionSearch(const FaceCatalogue& faces, const Tolerances& tol);
    // The untried direction with the most unclaimed floor-like area (reachable floors,
    // concave cylinders along it), a principal axis first if one has any; none when nothing
    // is left to machine. The faces that called for it call for no other direction.
    std::optional<Vec3> next(const std::vector<bool>& claimed);
    // The principal axes not tried yet: through openings have no floor to call for them.
    std::vector<Vec3> untriedPrincipalAxes();
    // Records a direction tried for another reason (a hole's axis); false if it was tried.
    bool markTried(const Vec3& d);
    // Faces that call for no direction (per face): the blank's edge chamfers.
    void setAside(const std::vector<bool>& faces);

private:
    double score(const Vec3& d, const std::vector<bool>& claimed, bool consume);
    const FaceCatalogue& faces_;
    Tolerances tol_;
    std::vector<bool> consumed_;  // faces whose direction was already tried
    std::vector<Vec3> tried_;
    std::vector<Vec3> axes_;  // principal axes, on first use
};

// Setups that found nothing are noise in the tree: drops them and renumbers the rest.
void dropEmptySetups(DomainTree& tree);

}  // namespace aeronc::recognition
