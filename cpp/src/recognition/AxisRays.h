#pragma once
// Rays along one setup axis against the part's faces, with a grid over the slicing plane
// so each ray meets only the faces above or below its foot point.
#include <aeronc/recognition/SetupFrame.h>

#include "FaceCatalogue.h"

#include <memory>
#include <unordered_map>
#include <vector>

namespace aeronc::recognition {

class AxisRays {
public:
    AxisRays(const FaceCatalogue& faces, const SetupFrame& frame);
    // Distance from p along +w (up = true) or -w to the first face; infinity if none.
    double firstHit(const Vec3& p, bool up);
    // Whether the ray meets any face: planes first, and it stops at the first it meets.
    bool anyHit(const Vec3& p, bool up);
    // Whether the ray up from inside face i leaves the part: the tool reaches the face.
    bool reachable(int i);

private:
    double cast(const Vec3& p, bool up, bool any);
    const FaceCatalogue& faces_;
    SetupFrame frame_;
    std::vector<P2> lo_, hi_;  // projected box of each face
    std::vector<double> h0_, h1_;  // and its height range along the axis
    double cell_ = 1;
    std::unordered_map<long long, std::vector<int>> grid_;
    long long key(long long a, long long b) const { return a * 1000003LL + b; }
};

}  // namespace aeronc::recognition
