#pragma once
// The checks made while the passes are made (ImpellerToolpaths.h): every cutting position
// measured against the channel's walls and hub, stepped back from a gouge and tilted to clear
// the holder; every link between passes (entry and exit along the tool axis at feed, rapids over
// the clearance plane) checked against the part and the blank.
#include "ChannelGeometry.h"
#include "StockEnvelope.h"

#include <aeronc/impellerpath/ImpellerToolpaths.h>

#include <vector>

namespace aeronc::impellerpath {

constexpr double kPi = 3.14159265358979323846;
constexpr double kGougeAim = 0.002;  // mm: finishing positions are stepped back to at most this
// mm: a position that still cuts deeper than this after stepping back is left out (half the
// program check's limit of 0.01 mm: the posted program rounds its coordinates).
constexpr double kGougeLeaveOut = 0.005;

struct Links;

// Cutting positions of one pass, checked; the holder cleared by tilting towards the channel's
// middle (about the local radial direction, both ways, in growing steps).
struct Checker {
    const Channel& ch;
    const CutterShape& cutter;
    const PathOptions& opt;
    CheckResult& result;
    double stock = 0;  // distance to keep beyond the cutter (roughing's allowance)

    // A position closer to the part than the cutter and the stock allow (OCCT's approximations,
    // a twisted ruling, a slanted wall) is stepped back from the nearest point of the part.
    Move place(Vec3 centre, Vec3 axis);
    // The position placed and added to the pass; one whose holder still touches after tilting,
    // or that still gouges, is left out (counted, not recorded as a cut): the pass ends before
    // it (with its links to `out`) and a new one starts after it, so no move runs through it.
    void add(std::vector<Move>& pass, Vec3 centre, Vec3 axis, const Links& links, std::vector<Move>& out);
    // A position that is not moved, measured as the program's re-check measures it.
    void tally(const Move& m);
    void record(const Clearance& c, const Vec3& centre);

    bool leavingOut_ = false, lastSafe_ = true;  // add()'s state
};

// Links between passes. A pass is entered and left along the tool axis at feed, from and to the
// point where the whole tool is `clearance` outside the blank (the envelope of the part and of
// any stock left); from there rapids run along the axis up to the clearance plane, and across
// it to the next pass. Every link is checked: the feed stretches against the part (the tool
// swept along its axis), the rapids against the blank.
struct Links {
    const StockEnvelope& stock;
    double plane;      // axial height of the ball centre on the clearance plane
    double clearance;  // mm the tool keeps outside the blank on rapids

    // Up the tool axis from m until the tool is clear of the blank.
    Move outside(const Move& m, const CutterShape& c) const;
    Move onPlane(const Move& m, const Frame& fr) const;
    // Feed along the tool axis between a cutting position and a point above it. Moving along its
    // own axis, the tool sweeps what the tool at the cutting position covers with its shank longer
    // by the distance (and no narrower than the flutes' top): one measure of that longer tool.
    void checkFeed(const Move& cutting, const Move& above, Checker& check) const;
    bool feedTouches(const Move& cutting, const Move& above, const Checker& check) const;
    // A rapid from a to b: the tool outside the blank all along.
    void checkRapid(const Move& a, const Move& b, Checker& check) const;
    // The pass with its entry and exit links appended to `out`; leading and trailing positions
    // that cannot be left along the tool axis without touching the part are left out.
    void append(std::vector<Move>& out, const std::vector<Move>& pass, Checker& check) const;
};

// Moves as Links::append writes them (each pass: two rapids in, the cutting positions, the exit
// at feed, a rapid out) turned about the axis by `angle`, then placed again as `check`'s channel
// asks: every cutting position stepped back, tilted or left out against that channel's own
// blades and hub (an exporter's blades are not exact copies), the links made and checked anew.
void placeTurned(const std::vector<Move>& linked, double angle, Checker& check, const Links& links,
                 std::vector<Move>& out);

// Adds the counts of r to `into`, keeping the deeper gouge and where it is.
void merge(CheckResult& into, const CheckResult& r);

}  // namespace aeronc::impellerpath
