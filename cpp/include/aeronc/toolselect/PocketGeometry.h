#pragma once
// A machining unit reduced to what tool selection needs: 2-D in the setup plane, mm.
#include <array>
#include <string>
#include <vector>

namespace aeronc::toolselect {

struct PocketGeometry {
    std::vector<std::array<double, 2>> outer;                 // any orientation
    std::vector<std::vector<std::array<double, 2>>> islands;  // any orientation
    double depth = 0;
    double minCornerRadius = -1;  // smallest concave corner radius; < 0: no limit
    double floorFilletRadius = 0;
    bool open = false;  // not used yet: the contour is treated as a wall all round
    std::string name;
};

}  // namespace aeronc::toolselect
