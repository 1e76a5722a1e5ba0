#pragma once
// The seven compensation methods fitted to a set of datum holes, and each method's
// leave-one-out error over them (each datum hole predicted from the others).
//
//   seed                 the seed's interpolation along rows (RowInterpolation.h)
//   rigid, similarity    the best-fit transform of the datum holes alone (BestFit.h)
//   rigid+idw, ...       the best fit, then its residuals interpolated by inverse distance
//   rigid+tps, ...       weighting or by a thin-plate spline (ResidualField.h)
#include <aeronc/compensation/BestFit.h>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace aeronc::compensation {

enum class Method { Seed, Rigid, Similarity, RigidIdw, SimilarityIdw, RigidTps, SimilarityTps };

// Every method, simplest first (the order that breaks ties in the leave-one-out proposal).
const std::vector<Method>& allMethods();
std::string methodName(Method m);                            // "seed", "rigid", "similarity+tps", ...
std::optional<Method> methodFromName(const std::string& name);  // nullopt for an unknown name

// A measured datum hole: its nominal position and where it was measured, in the part frame.
// row and station (distance along the row) matter for the seed's method; row -1 lets
// compensate() find the rows.
struct Datum {
    std::string id;
    Vec3 nominal = Vec3::Zero();
    Vec3 measured = Vec3::Zero();
    int row = -1;
    double station = 0.0;
    // The unit surface normal at the hole, the camera's axis (zero: not known). Only the datum
    // check uses it: a misread reading is off across it (docs/compensation.md).
    Vec3 normal = Vec3::Zero();
    Vec3 deviation() const { return measured - nominal; }
};

// A hole still to be drilled: nominal position and unit surface normal.
struct NominalHole {
    std::string id;
    Vec3 position = Vec3::Zero();
    Vec3 normal = Vec3::UnitZ();
    int row = -1;
    double station = 0.0;
};

// The datum hole as a hole to predict (its nominal position, row and station).
inline NominalHole asHole(const Datum& d) {
    NominalHole h;
    h.id = d.id;
    h.position = d.nominal;
    h.row = d.row;
    h.station = d.station;
    return h;
}

// A method fitted to a set of datum holes: the correction at any nominal hole.
class Compensator {
public:
    // Throws when the datum holes do not support the method: none at all; a 3-D fit with fewer
    // than three or with collinear datum holes; rows missing for the seed's method. (One datum
    // hole is enough for the seed's method here: a leave-one-out prediction from two.)
    Compensator(Method method, std::vector<Datum> datums);

    Method method() const { return method_; }
    // The correction dP at a hole; `note` (if given) says when the seed's method extrapolates.
    Vec3 correction(const NominalHole& hole, std::string* note = nullptr) const;
    // correction() of many holes at once (faster for the spline); notes as correction() gives them.
    std::vector<Vec3> corrections(const std::vector<NominalHole>& holes, std::vector<std::string>* notes = nullptr) const;
    // The fitted transform (identity for the seed's method); it also turns the normals.
    const SimilarityTransform& fit() const { return fit_; }
    bool usesFit() const { return method_ != Method::Seed; }

private:
    Vec3 seedCorrection(const NominalHole& hole, std::string* note) const;

    Method method_;
    std::vector<Datum> datums_;
    SimilarityTransform fit_;
    std::vector<Vec3> residuals_;  // measured - fit(nominal) per datum
    std::map<int, std::vector<int>> rowDatums_;  // per row: its datum holes by station
    struct Fields;
    std::shared_ptr<const Fields> fields_;
};

struct LeaveOneOut {
    Method method = Method::Seed;
    bool available = false;
    std::string reason;          // why not available
    double rms = 0.0, max = 0.0;  // over the datum holes, mm
    std::vector<double> errors;  // per datum hole: |predicted - measured deviation|
    std::vector<Vec3> predicted;  // per datum hole: its deviation predicted from the others
};

// Each method's leave-one-out error over the datum holes (rows assigned).
std::vector<LeaveOneOut> leaveOneOut(const std::vector<Datum>& datums);

// The available method with the lowest leave-one-out RMS error; a method within 1e-9 mm or
// 0.5 % of the best and earlier in allMethods() wins the tie.
std::optional<Method> proposedMethod(const std::vector<LeaveOneOut>& figures);

}  // namespace aeronc::compensation
