#pragma once
// Compensation of the holes still to be drilled from the measured deviations of the datum
// holes, by one of seven methods, with each method's leave-one-out error over the datum holes.
//
//   seed                 the seed's interpolation along rows (RowInterpolation.h)
//   rigid, similarity    the best-fit transform of the datum holes alone (BestFit.h)
//   rigid+idw, ...       the best fit, then its residuals interpolated by inverse distance
//   rigid+tps, ...       weighting or by a thin-plate spline (ResidualField.h)
//
// No method wins every distortion (a similarity fit is best for rigid and scale errors, an
// interpolated residual for bending), so the proposed method is the one whose leave-one-out
// error is lowest: each datum hole predicted from the others.
//
// Before that, datum readings out of line with the others are left out (DatumCheck.h); after
// it, what a user must look at is flagged (HoleFlags.h).
#include <aeronc/compensation/Compensator.h>
#include <aeronc/compensation/DatumCheck.h>
#include <aeronc/compensation/HoleFlags.h>
#include <aeronc/compensation/HoleRows.h>

#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace aeronc::compensation {

struct HoleCorrection {
    std::string id;
    Vec3 nominal = Vec3::Zero();
    Vec3 correction = Vec3::Zero();
    Vec3 compensated = Vec3::Zero();
    Vec3 normal = Vec3::UnitZ();  // the nominal normal turned by the fit
    bool exceedsTolerance = false;
    double neighbourDeparture = 0.0;  // from the linear trend of its neighbours' corrections, mm
    bool againstNeighbours = false;   // neighbourDeparture beyond the neighbour tolerance
    std::string note;
};

struct DatumResidual {
    std::string id;
    Vec3 deviation = Vec3::Zero();  // measured - nominal
    Vec3 residual = Vec3::Zero();   // measured - fit(nominal): what the fit leaves
    DatumVerdict verdict;           // used or left out, its miss, why
};

struct CompensationInput {
    std::vector<Datum> datums;
    std::vector<NominalHole> holes;
    double tolerance = 0.5;           // a correction longer than this is flagged, mm
    double neighbourTolerance = 0.05;  // a correction departing more from its neighbours' is flagged, mm
    RowOptions rows;                  // used when rows are not given
    DatumCheckOptions check;
    std::set<std::string> keep;  // datum holes put back by the user: never left out
    std::set<std::string> drop;  // datum holes left out by the user
};

struct CompensationResult {
    Method method = Method::Seed;
    std::optional<Method> proposed;  // none when no method's leave-one-out error can be computed
    SimilarityTransform fit;
    std::vector<LeaveOneOut> leaveOneOut;  // in allMethods() order, over the datum holes used
    DatumCheck check;                      // its `used` are the datum holes the fit and fields use
    std::vector<DatumResidual> datums;     // every datum hole given, used or not
    std::vector<HoleCorrection> holes;
    std::vector<Flag> flags;  // datum flags first (in the datums' order), then the holes' in theirs
    int flaggedHoles = 0;     // drilled holes with at least one flag
};

// Finds rows (HoleRows.h) over the datum and nominal holes together when any of them has
// row -1, and gives every point its row and station.
void assignRows(std::vector<Datum>& datums, std::vector<NominalHole>& holes, const RowOptions& options = {});

// Corrects each hole with a fitted method; a correction longer than `tolerance` is flagged, and
// one departing from its neighbours' trend by more than `neighbourTolerance`.
std::vector<HoleCorrection> correctHoles(const Compensator& compensator, const std::vector<NominalHole>& holes,
                                         double tolerance, double neighbourTolerance = INFINITY);

// Checks the input (at least two datum holes, finite values, unique ids), assigns rows, leaves
// out the datum readings out of line (DatumCheck.h), computes the leave-one-out figures over the
// datum holes used, compensates every hole with `method` (the proposed one when nullopt) and
// flags what to look at (HoleFlags.h).
CompensationResult compensate(CompensationInput input, std::optional<Method> method = std::nullopt);

}  // namespace aeronc::compensation
