#pragma once
// Holes found over the face adjacency, whatever the setup directions: coaxial chains of
// concave cylinders (each covering more than half its circle, split faces joined), joined
// through planar steps and cones on their axis, with the ends a tool can enter by. The
// setups then take the chains along their direction as holes, and the chains no setup
// takes propose setups of their own.
#include "FaceCatalogue.h"
#include "Tolerances.h"

#include <vector>

namespace aeronc::recognition {

// One diameter of a hole: the concave cylinder faces on its axis with its radius.
struct HoleSegment {
    std::vector<int> faces;  // 0-based
    double radius = 0;
    double lo = 0, hi = 0;   // extent along the chain's axis (heights along HoleChain::axis)
    // The ends a tool reaches it from: open, and no segment on the way in narrower than the
    // next. +1: from +axis (the top end), -1: from -axis.
    std::vector<int> entries;
    // The entries where material stands within nine tenths of its radius along the axis
    // beyond the mouth (a wall over part of it): no tool as wide as it comes down from there.
    std::vector<int> overhung;
};

struct HoleChain {
    Vec3 axis{0, 0, 1};   // unit; heights along it order the segments
    Vec3 point{0, 0, 0};  // on the axis
    std::vector<HoleSegment> segments;  // ascending along axis
    std::vector<int> steps;             // planes square to the axis between segments, and flat bottoms
    std::vector<int> cones;             // coaxial cones: countersinks, drill points, chamfered steps
    bool openTop = false, openBottom = false;
    bool through() const { return openTop && openBottom; }
    // All its faces (0-based): walls, steps and cones.
    std::vector<int> faces() const;
    bool enterable() const {
        for (const HoleSegment& s : segments)
            if (!s.entries.empty()) return true;
        return false;
    }
};

std::vector<HoleChain> findHoleChains(const FaceCatalogue& faces, const Tolerances& tol);

}  // namespace aeronc::recognition
