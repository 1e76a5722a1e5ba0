#pragma once
// The toolpath of one machining unit, in its setup frame: (u, v) in the slicing plane, h along
// the tool axis (the tool above the part has the larger h). Every point is the tool tip, the
// bottom centre of the cutter.
#include <array>
#include <optional>
#include <vector>

namespace aeronc::toolpath {

using Point = std::array<double, 2>;  // (u, v)
using Loop = std::vector<Point>;      // closed implicitly, either orientation

struct Segment {
    Point a, b;
};

struct Move {
    enum class Kind { Rapid, Feed, Plunge, Drill };
    Kind kind = Kind::Rapid;
    double u = 0, v = 0, h = 0;  // the end point; for Drill the hole's position and its bottom
    // Drill only: R plane (h), peck depth (0: no pecking), dwell at the bottom (s). The cycle
    // starts and ends at the R plane, the way G81/G82/G83 with G99 do.
    double r = 0, q = 0, dwell = 0;
};

struct Toolpath {
    std::vector<Move> moves;
    double cutLength = 0;    // mm at feed: Feed, Plunge and the drilling feeds
    double rapidLength = 0;  // mm at rapid, the drilling cycles' retracts included
};

struct Cutter {
    double diameter = 0;
    double cornerRadius = 0;  // 0: flat end mill; diameter / 2: ball end mill
    double radius() const { return diameter / 2; }
};

// What the milling operations share. Heights are in the setup frame.
struct CutParameters {
    std::optional<double> safeHeight;  // absolute h where the unit starts and ends; top + clearance if unset
    double clearance = 2;              // above top: the plane of the rapids between cuts
    double stepDown = 4;               // mm per level, at most
    std::optional<double> stepOver;    // mm between neighbouring passes, at most the diameter; D/2 if unset
    double radialAllowance = 0;        // left on the walls
    double axialAllowance = 0;         // left on the floor
    double rampAngleDeg = 3;           // descent of the helical and linear ramps
    double chordTolerance = 0.01;      // arcs written as polylines stray from the arc by at most this
    bool climb = true;                 // climb milling for a clockwise (M3) spindle
};

}  // namespace aeronc::toolpath
