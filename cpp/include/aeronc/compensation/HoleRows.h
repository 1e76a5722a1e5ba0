#pragma once
// Rows of holes: chains of holes that follow each other at about the same pitch without sharp
// turns (a fastener row along a rib, a stringer or a spar; straight on a flat skin, following
// the curvature on a curved one). The seed's method interpolates along them, and S is the
// distance travelled along the row (the station).
#include <aeronc/compensation/Types.h>

#include <vector>

namespace aeronc::compensation {

struct RowOptions {
    double maxTurnDegrees = 30.0;  // a link may turn the row by at most this much
    double maxGapFactor = 2.5;     // a link is at most this many times its holes' nearest spacing
};

struct HoleRows {
    std::vector<int> row;                  // per point: its row (0-based)
    std::vector<double> station;           // per point: distance from the row's first hole along the row
    std::vector<std::vector<int>> members;  // per row: its points in order along the row
};

// Links the points into rows: the shortest admissible links first, each point linked to at
// most two others, no cycles, no turn sharper than maxTurnDegrees. A row runs from its end with
// the lower point index. Rows are numbered in the order of their lowest point index. Runs in
// about O(n log n) (a grid finds each point's nearest neighbours).
HoleRows findRows(const std::vector<Vec3>& points, const RowOptions& options = {});

}  // namespace aeronc::compensation
