#pragma once
// Planar regions at a slicing level, held as Clipper integer polygons.
#include <aeronc/recognition/SetupFrame.h>

#include <polyclipping/clipper.hpp>
#include <vector>

namespace aeronc::recognition {

constexpr double kClipperScale = 1e4;  // 0.1 µm resolution

inline ClipperLib::IntPoint toInt(const P2& p) {
    return {static_cast<ClipperLib::cInt>(std::llround(p.x * kClipperScale)),
            static_cast<ClipperLib::cInt>(std::llround(p.y * kClipperScale))};
}
inline P2 toP2(const ClipperLib::IntPoint& p) { return {p.X / kClipperScale, p.Y / kClipperScale}; }

// Outer boundary (positive orientation) plus holes (negative orientation).
struct Region {
    ClipperLib::Path outer;
    ClipperLib::Paths holes;
    P2 lo, hi;

    void updateBox();
    double area() const;
    bool contains(const P2& p) const;   // inside outer and outside every hole
    ClipperLib::Paths paths() const;
    // Narrowest passage: twice the largest erosion that keeps the region one piece
    // with all its islands.
    double minWidth() const;
    // A point at least `clearance` (or as far as the region allows) from the boundary.
    P2 interiorPoint() const;
    // Up to maxCount points inside the region, `inset` from its boundary (less where the
    // region is narrower), spread along the outer boundary and the islands'.
    std::vector<P2> boundaryProbes(double inset, std::size_t maxCount) const;
};

}  // namespace aeronc::recognition
