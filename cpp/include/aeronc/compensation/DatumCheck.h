#pragma once
// Datum readings that disagree with the others beyond what the noise explains: a camera that
// read a hole wrongly (a burr, a chip, a reflection). Each is named and left out before the
// compensation, so that it does not move every drilled hole.
//
// The miss of a datum hole is the distance between its measured deviation and the deviation
// the other datum holes predict for it, by the method that predicts it best (the leave-one-out
// of every method, Compensator.h). A misread reading is missed by every method. A real
// distortion is followed by at least one method: a bend by the spline, an offset by the fits.
// The typical miss is the median over the datum holes in use; the camera noise makes it (with
// noise sigma per coordinate, the miss of a clean reading is about 1.6 sigma). A reading is
// left out when its miss is larger than `factor` times the typical miss and larger than
// `minimum`. The worst reading goes first. Then the others are checked again without it,
// because a misread reading pulls the predictions of its neighbours. This stops when no
// reading is out of line, or when `maxShare` of the datum holes are out. Every step is
// deterministic: ties go to the datum hole given first.
//
// The user has the last word. A datum hole put back (`keep`) is never left out, but it is still
// flagged when it disagrees. A datum hole left out by hand (`drop`) is never used.
#include <aeronc/compensation/Compensator.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace aeronc::compensation {

struct DatumCheckOptions {
    bool enabled = true;
    double factor = 5.0;    // a reading is out of line beyond this many typical misses...
    double minimum = 0.05;  // ...and beyond this many mm: what a camera and a fixture never explain
    double maxShare = 0.25;  // never leave out more than this share of the datum holes
    size_t minDatums = 6;    // fewer datum holes in use: too few to tell a misread reading
};

enum class DatumUse {
    Used,           // agrees with the others, used
    LeftOut,        // out of line: left out by the check
    LeftOutByHand,  // left out by the user
    PutBack,        // the check would leave it out; the user put it back, used
};
std::string datumUseName(DatumUse use);  // "used", "left out", "left out by hand", "put back"

struct DatumVerdict {
    std::string id;
    DatumUse use = DatumUse::Used;
    // How far the datum holes in use (the others, for one in use) predict its deviation from
    // the measured one, by `predictor`, the method that predicts it best; NaN when no method can.
    double miss = 0.0;
    std::optional<Method> predictor;
    Vec3 predicted = Vec3::Zero();  // that prediction of its deviation
    bool outOfLine = false;         // miss beyond the threshold
    std::string reason;             // why it is left out or flagged; empty for an agreeing one
};

struct DatumCheck {
    bool checked = false;  // false: not checked (disabled, or too few datum holes); see `note`
    std::string note;
    double typicalMiss = 0.0;  // median miss over the datum holes in use, mm
    double threshold = 0.0;    // max(factor x typicalMiss, minimum), mm
    std::vector<DatumVerdict> datums;      // in the order given
    std::vector<Datum> used;               // the datum holes the compensation uses, in the order given
    std::vector<LeaveOneOut> leaveOneOut;  // every method's leave-one-out over `used`
    std::vector<std::string> leftOut;      // ids left out by the check, in the order they were found
};

// Checks the datum holes (rows assigned, ids unique). Ids in keep or drop that are not datum
// holes are ignored; an id in both is refused.
DatumCheck checkDatums(const std::vector<Datum>& datums, const DatumCheckOptions& options = {},
                       const std::set<std::string>& keep = {}, const std::set<std::string>& drop = {});

}  // namespace aeronc::compensation
