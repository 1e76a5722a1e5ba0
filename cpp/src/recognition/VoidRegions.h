#pragma once
// The void at one slicing level, as regions: closed ones inside the part's section (with
// the material loops inside them as islands) and exterior ones between the part and the
// blank (with their open edges on the blank). Each knows the faces bounding it.
#include "LevelSlicer.h"
#include "Region.h"

#include <utility>
#include <vector>

namespace aeronc::recognition {

struct VoidRegion {
    Region region;
    bool exterior = false;
    std::vector<int> contourFaces;              // 0-based
    std::vector<std::vector<int>> islandFaces;  // 0-based, one list per island loop
    std::vector<const SectionLoop*> contourLoops;  // loops bounding it (void side known)
    std::vector<bool> contourVoidLeft;
    std::vector<const SectionLoop*> islandLoops;
    std::vector<std::pair<P2, P2>> openEdges;  // boundary pieces on the blank
    // Filled by the level slicing: the faces normal to the axis at the level under it.
    std::vector<int> floors;
    std::vector<int> ribTops;
    P2 sample{0, 0};  // a point inside, on a floor when there is one
    bool hasSample = false;
};

// loops: the section at the level (they must outlive the regions); the blank as the
// rectangle [blankLo, blankHi] of the slicing plane.
std::vector<VoidRegion> voidRegions(const std::vector<SectionLoop>& loops, const P2& blankLo, const P2& blankHi,
                                    double linTol);

}  // namespace aeronc::recognition
