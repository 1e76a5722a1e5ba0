#pragma once
// The pocket as a Clipper region (outers CCW, holes CW), shared by the selectors.
#include <aeronc/toolselect/PocketGeometry.h>
#include <aeronc/toolselect/Selection.h>

#include <polyclipping/clipper.hpp>

namespace aeronc::toolselect {

constexpr double kScale = 1e4;  // 0.1 µm, as recognition's kClipperScale

struct PocketRegion {
    ClipperLib::Paths paths;
    double area = 0;  // mm²
};

// Outer minus the union of the islands. Throws aeronc::inputError when degenerate.
PocketRegion makeRegion(const PocketGeometry& pocket);

double areaOf(const ClipperLib::Paths& ps);  // mm², holes subtracted

// Round-join offset of a whole region; negative delta erodes.
ClipperLib::Paths offsetRegion(const ClipperLib::Paths& ps, double delta, double arcTolerance);

// offsetRegion(ps, delta, arcTolerance) as a set, computed without letting the corner spikes
// of stretches that curve more tightly than |delta| cross one another (see PocketRegion.cpp).
ClipperLib::Paths offsetRegionFast(const ClipperLib::Paths& ps, double delta, double arcTolerance);

// Chord error (sagitta) of the round joins. Coarser is faster; with the equal-area
// correction in openRegion, 2e-3·r keeps eta within ~1e-4.
double arcToleranceFor(double radius);

// eta only (erode, dilate, subtract from the region), the part the roughing search repeats.
// `eroded` is the erosion by r, cleaned.
struct Opening {
    ClipperLib::Paths eroded;
    // The pieces of the region the opening leaves (A_m is the region's area less theirs).
    struct Piece {
        ClipperLib::Path outer;
        ClipperLib::Paths holes;
        double area = 0;  // mm², holes subtracted
    };
    std::vector<Piece> unreached;
    double machinableArea = 0;
};
Opening openRegion(const PocketRegion& region, double radius);

// The full ratio (narrow passages included) from an opening already computed with `radius`.
MachinableRatio machinableRatio(const PocketRegion& region, const Opening& opening, double radius);

}  // namespace aeronc::toolselect
