#pragma once
// The four 5-axis strategies of the impeller's channels (ImpellerToolpaths.h), each making the
// checked passes of one channel with their links: channel roughing in layers between the walls,
// flank finishing of a blade wall, hub finishing between the fillets, fillet finishing along the
// root of a wall. And the geometry they share.
#include "ChannelGeometry.h"
#include "PassChecks.h"

#include <aeronc/impellerpath/ImpellerToolpaths.h>

#include <vector>

namespace aeronc::impellerpath {

inline double lerp(double a, double b, double t) { return a + (b - a) * t; }

// n positions from a to b, at the middles of n equal steps.
std::vector<double> stations(double a, double b, int n);
// The interpolated ruling direction across the channel at fraction u from wall A to wall B.
Vec3 blendedAxis(const Channel& ch, double r, double z, double thetaA, double thetaB, double u);
// The distance along the arc at radius r from a wall to where a point is `keep` from it.
double arcMargin(const Channel& ch, bool b, double r, double theta, double z, double keep);

// Layers from the shroud down to the hub, lanes across the channel, `roughAllowance` left on
// the walls and the hub; the tool axis the rulings blended across.
void roughChannel(const Channel& ch, const CutterShape& cut, const PathOptions& opt, const Links& links,
                  CheckResult& res, std::vector<Move>& out);
// Wall A (b false) or B of the channel, the cone's generator along the ruling at the wall's foot.
void finishWall(const Channel& ch, bool b, const CutterShape& cut, const PathOptions& opt, const Links& links,
                CheckResult& res, std::vector<Move>& out);
// The hub between the root fillets, lanes at most finishStep apart.
void finishHub(const Channel& ch, const CutterShape& cut, double filletRadius, const PathOptions& opt,
               const Links& links, CheckResult& res, std::vector<Move>& out);
// Along the root fillet of one wall: at each station the rolling ball of the fillet (the point
// the fillet radius from both the wall and the hub, found by Newton steps on the two distances),
// then the cutter's ball moved from it towards the corner until it touches the fillet.
void finishFillet(const Channel& ch, bool b, const CutterShape& cut, double filletRadius, const PathOptions& opt,
                  const Links& links, CheckResult& res, std::vector<Move>& out);

}  // namespace aeronc::impellerpath
