#pragma once
// Clipper at 0.1 µm and the plane geometry the operations share.
#include <aeronc/toolpath/Toolpath.h>

#include <polyclipping/clipper.hpp>

namespace aeronc::toolpath::clip {

using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

constexpr double kScale = 1e4;  // Clipper units per mm

IntPoint toInt(const Point& p);
Point toPoint(const IntPoint& p);
Path toPath(const Loop& loop);
Loop toLoop(const Path& path);

// Clipper's ArcTolerance for arcs within chordTolerance: Clipper rounds the steps of a join to
// a whole number, which can make one step half as wide again (2.25 times the sagitta).
double arcTolerance(double chordTolerance);

// A region as Clipper paths: outers counter-clockwise, holes clockwise.
// Round-join offset; negative delta erodes. Arcs within chordTolerance.
Paths offset(const Paths& region, double delta, double chordTolerance);
// Mitre-join offset: round a convex corner of the material (a reflex corner of the region
// eroded) the centres keep their distance from both walls' lines, out to the mitre point
// (up to kMitreLimit times delta from the corner). Two floor fillets meet in a mitre at such a
// corner, and a cutter rolled round the corner's edge would cut into it.
constexpr double kMitreLimit = 20;
Paths offsetMitred(const Paths& region, double delta, double chordTolerance);
Paths unite(const Paths& a, const Paths& b);
Paths intersect(const Paths& a, const Paths& b);
Paths subtract(const Paths& a, const Paths& b);
double area(const Paths& region);  // mm², holes subtracted

// One connected piece of a region.
struct Piece {
    Path outer;
    Paths holes;
};
std::vector<Piece> pieces(const Paths& region);
std::vector<Piece> offsetPieces(const Paths& region, double delta, double chordTolerance);
Paths pathsOf(const Piece& piece);

bool contains(const Paths& region, const Point& p);  // boundary counts as inside
double boundaryDistance(const Paths& region, const Point& p);
// a and b in the region and the segment crossing none of its edges.
bool segmentInside(const Paths& region, const Point& a, const Point& b);

// Plane geometry on mm points.
double distance(const Point& a, const Point& b);
Point nearestOnSegment(const Point& p, const Point& a, const Point& b);
double segmentDistance(const Point& p, const Point& a, const Point& b);
// The point of the closed loop nearest to p, and the index i of its edge loop[i] -> loop[i + 1].
struct LoopPoint {
    Point at;
    std::size_t edge = 0;
    double distance = 0;
};
LoopPoint nearestOnLoop(const Loop& loop, const Point& p);
// The closed loop as a polyline that starts and ends at `at`, a point on edge `edge`.
std::vector<Point> loopFrom(const Loop& loop, const LoopPoint& at);
double length(const std::vector<Point>& polyline);
Point centroid(const Loop& loop);
double signedArea(const Loop& loop);

}  // namespace aeronc::toolpath::clip
