#pragma once
// A cutter moving along a straight segment, seen in the tool-axis frame: w = z for a tool axis
// of +Z (the cutter comes from above), w = -z for -Z. In that frame the cutter removes
// everything at and above its lower envelope.
#include <aeronc/verify/Cutter.h>

namespace aeronc::verify {

class SweptSegment {
public:
    // The tip moves from (x0, y0, w0) to (x1, y1, w1).
    SweptSegment(double x0, double y0, double w0, double x1, double y1, double w1);

    // Horizontal distance from (x, y) to the segment's projection.
    double distance(double x, double y) const;
    // The lowest w of the swept cutter over (x, y), exact for any segment direction; +infinity
    // where the cutter does not pass over (x, y). A ball swept along a line is a capsule, met
    // in closed form; for a bull nose the height along the segment is convex, so its minimum is
    // found by bisection of the slope.
    double envelope(const Cutter& cutter, double x, double y) const;
    // A cheap bound the envelope never goes below, at horizontal distance d from the projection.
    double lowerBound(const Cutter& cutter, double d) const {
        return (w0_ < w1_ ? w0_ : w1_) + cutter.height(d < cutter.radius ? d : cutter.radius);
    }
    // The x-range [xa, xb] of the points of row y within `reach` of the projection; false when
    // the row misses it.
    bool rowSpan(double y, double reach, double& xa, double& xb) const;

    double minY() const { return y0_ < y1_ ? y0_ : y1_; }
    double maxY() const { return y0_ < y1_ ? y1_ : y0_; }

private:
    double ballEnvelope(double radius, double x, double y) const;

    double x0_, y0_, w0_, x1_, y1_, w1_;
    double ux_ = 0, uy_ = 0;  // unit direction of the projection (0 for a plunge)
    double length_ = 0;       // length of the projection
    double slope_ = 0;        // dw per unit of projected length
};

}  // namespace aeronc::verify
