#pragma once
// What a user must look at before drilling: the flags of a compensation. "Flagged" means one of
//
//   datum left out       a datum reading the check left out (DatumCheck.h), with its miss
//   datum left out by hand
//   datum put back       a datum reading out of line that the user put back, so it is used
//   datum out of line, used   one the check could not leave out (no more of them may be)
//   against neighbours   a drilled hole whose correction departs from the linear trend of its
//                        neighbours' corrections by more than the neighbour tolerance (a
//                        correction field pulled by one datum hole, a seam between rows)
//   beyond tolerance     a drilled hole whose correction is longer than the tolerance the user
//                        set (the assembly moved it farther than the drawing allows unasked)
//
// each with its reason. A datum hole or a drilled hole can carry several flags.
#include <aeronc/compensation/Types.h>

#include <string>
#include <vector>

namespace aeronc::compensation {

enum class FlagKind {
    DatumLeftOut,
    DatumLeftOutByHand,
    DatumPutBack,
    DatumOutOfLineUsed,
    AgainstNeighbours,
    BeyondTolerance,
};
std::string flagKindName(FlagKind kind);  // "datum left out", ..., "beyond tolerance"

struct Flag {
    FlagKind kind = FlagKind::BeyondTolerance;
    std::string id;     // the datum hole or the drilled hole
    double value = 0.0;  // mm: the datum's miss, the departure from the neighbours, the correction
    double limit = 0.0;  // mm: what it is beyond
    std::string reason;
};

// How far each correction departs from the linear trend of its neighbours' corrections: the
// corrections of its `neighbours` nearest holes fitted as a linear function over their plane
// (over their line when they lie on one), evaluated at the hole. Zero for every correction
// field that is linear in position (rigid, similarity, affine), small for a smooth one.
// Fewer than three holes: zeros.
std::vector<double> neighbourDepartures(const std::vector<Vec3>& positions, const std::vector<Vec3>& corrections,
                                        int neighbours = 8);

}  // namespace aeronc::compensation
