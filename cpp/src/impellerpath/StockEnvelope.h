#pragma once
// The blank as the envelope of the stock: the part and whatever stock remains always lie inside
// it, so a rapid whose tool stays outside it cuts nothing. Distances are exact for the revolved
// profile: they are taken in the meridian plane of the point.
#include "ChannelGeometry.h"

#include <aeronc/impeller/Blank.h>
#include <aeronc/impellerpath/ImpellerToolpaths.h>

namespace aeronc::impellerpath {

class StockEnvelope {
public:
    StockEnvelope(impeller::BlankProfile blank, const Frame& frame);
    // Distance from p to the blank (0 inside it).
    double distance(const Vec3& p) const;
    // The blank's highest station along the axis.
    double top() const;
    // How far the cutter at (centre, axis), its flutes and shank up to its reach, stays outside
    // the blank (negative: it reaches into it).
    double clearance(const CutterShape& cutter, const Vec3& centre, const Vec3& axis) const;

private:
    impeller::BlankProfile blank_;
    Frame frame_;
};

// The least clearance of the cutter outside the blank along a straight move from a to b (the
// centre moving linearly, the axis turning with it), sampled every half millimetre.
double rapidClearance(const StockEnvelope& stock, const CutterShape& cutter, const Move& a, const Move& b);

}  // namespace aeronc::impellerpath
