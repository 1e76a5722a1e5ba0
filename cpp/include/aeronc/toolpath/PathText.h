#pragma once
// A toolpath as the G-code text of a FreeCAD Path (what Path.setFromGCode reads), and its
// machining time: rapids G0, feeds and plunges G1 at the horizontal and the vertical feed,
// drill cycles G81 (G82 with a dwell, G83 with a peck) with X Y Z R F between G99 (each cycle
// ends at its R plane, as the generator plans) and G80: the words FreeCAD's own operations
// write, so every post reads them alike. Feeds in FreeCAD's mm/s.
#include <aeronc/toolpath/Toolpath.h>

#include <string>

namespace aeronc::toolpath {

struct PathFeeds {
    double horizontal = 0, vertical = 0;             // feeds, mm/s
    double horizontalRapid = 0, verticalRapid = 0;   // rapids, mm/s; 0: rapids take no time
};

// One line per command, the first a comment holding `label` (its parentheses made brackets).
// Coordinates in the shortest form that reads back to the same double; a move writes only the
// coordinates and the feed that change (all of them for the first move and a move that stays).
std::string pathText(const Toolpath& toolpath, const PathFeeds& feeds, const std::string& label);

// Feeds and plunges at their feed, rapids at the rapid rates (horizontal and vertical parts
// apart), a drill cycle from R to the bottom at the vertical feed and back at the vertical rapid.
double estimatedSeconds(const Toolpath& toolpath, const PathFeeds& feeds);

}  // namespace aeronc::toolpath
