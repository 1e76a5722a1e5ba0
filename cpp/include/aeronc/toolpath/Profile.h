#pragma once
// Profile: the cutter along a drive loop or polyline, on one side of it, level by level.
#include <aeronc/toolpath/Toolpath.h>

namespace aeronc::toolpath {

struct ProfileUnit {
    Loop drive;          // the wall to machine, as the part's edge at the slicing plane
    bool closed = true;  // false: an open polyline from drive.front() to drive.back()
    // Open polylines only: the drive is cut between the points of the polyline nearest these.
    std::optional<Point> startLimit, endLimit;
    double top = 0, bottom = 0;
    // Of the floor's edge along the wall: near the floor the cutter keeps out of it, level by
    // level (FloorFillet.h wallFilletOffset).
    double floorFilletRadius = 0;
    // The element's other walls (its other wall runs and its islands, closed loops with the
    // first point repeated): the leads keep the cutter as far from them as from the drive.
    std::vector<std::vector<Point>> clearOf;
};

// The side of the drive that the cutter runs on, the side of the material it removes.
// Outside and Inside are for closed loops; Left and Right are seen along the drive as given.
enum class ToolSide { Outside, Inside, Left, Right };
enum class Lead { Arc, Line, None };

struct ProfileParameters : CutParameters {
    ToolSide side = ToolSide::Outside;
    Lead lead = Lead::Arc;
    std::optional<double> leadRadius;  // arc radius or line length; the cutter radius if unset
};

Toolpath profile(const ProfileUnit& unit, const Cutter& cutter, const ProfileParameters& parameters);

}  // namespace aeronc::toolpath
