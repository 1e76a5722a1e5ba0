#pragma once
// The plan of a clearing in the plane, the same at every level: the concentric rings of a
// tool-centre region cut from the innermost out, joined into chains of feed moves, each chain
// with its entry.
#include "Clip.h"

namespace aeronc::toolpath {

struct Entry {
    enum class Kind { Helix, Ramp, Plunge };
    Kind kind = Kind::Plunge;
    Point centre{};          // Helix: its centre; the helix starts and ends at the chain's first point
    double radius = 0;       // Helix
    std::size_t rampEnd = 0; // Ramp: the chain's path[0..rampEnd] is a closed loop to ramp down along
};

struct Chain {
    Entry entry;
    std::vector<Point> path;  // feed moves at the level, from where the entry ends
};

struct ClearingOptions {
    double stepOver = 0;
    double reach = 0;         // radius within which a pass leaves the floor flat (the cutter's flat)
    double chordTolerance = 0.01;
    double helixRadius = 0;   // wanted helix radius; helices down to minHelixRadius are tried
    double minHelixRadius = 0;
    double maxEntryLink = 0;  // longest feed from a plunge in the entry area to its chain
    bool climb = true;
};

struct ClearingPlan {
    std::vector<Chain> chains;
    std::size_t rings = 0;  // closed loops cut at each level
};

// `centres`: where the tool centre must pass so that the cutter sweeps the area to clear;
// `allowed`: where it may go (links, entries); `entryArea`: where a plunge meets no material.
ClearingPlan planClearing(const clip::Paths& centres, const clip::Paths& allowed, const clip::Paths& entryArea,
                          const ClearingOptions& options);

}  // namespace aeronc::toolpath
