#pragma once
// Datum readings that disagree with the others beyond what the noise explains: a camera that
// read a hole wrongly (a burr, a chip, a reflection). Each is named and left out before the
// compensation, so that it does not move every drilled hole.
//
// The miss of a datum hole is the distance between its measured deviation and the deviation
// the other datum holes predict for it, by the method that predicts it best (the leave-one-out
// of every method, Compensator.h), across the hole's normal when it is known (Datum::normal):
// the camera finds the hole's centre in its picture, and a burr, a chip or a reflection moves
// that sideways, while a skin sags along its normal, where sparse datum holes predict it worst.
// A misread reading is missed by every method. A real distortion is followed by at least one
// method: a bend by the spline, an offset by the fits.
// The whole miss, the distance along the normal included, is kept too. The typical miss of a
// set of datum holes is the median of their misses (and the typical whole miss, of their whole
// misses); the camera noise makes it (with a noise of sigma per coordinate, a little over 1.2
// sigma across the normal, 1.5 sigma whole).
//
// A reading is out of line when its miss is larger than `minimum` and larger than `factor`
// times the typical miss of the others, the others taken without it, and its whole miss is too
// against their typical whole miss: across the normal alone, a bend across the rows of a sparse
// pattern makes a clean corner stand out, while the others' whole misses, raised by the sag,
// show that the methods do not follow that skin closely. Without it: a misread
// reading pulls the predictions of its neighbours (of every hole, for a best fit), and with
// few datum holes it would raise the typical miss above its own. The readings most missed
// (at most `candidates` of them, beyond `minimum`) are tried in turn; the first out of line
// is left out, and the others are checked again without it. A reading left out at a later
// step must also have been out of line among all the datum holes at the start: with three
// datum holes a row, a bend shown by a middle one and its neighbour would otherwise make the
// neighbour look out of line once the first is gone. This stops when none is out of line, or
// when `maxShare` of the datum holes are out. Every step is deterministic: ties go to the
// datum hole given first.
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
    double factor = 5.0;    // a reading is out of line beyond this many typical misses of the others...
    double minimum = 0.1;  // ...and beyond this many mm
    double maxShare = 0.25;  // never leave out more than this share of the datum holes
    size_t minDatums = 6;    // fewer datum holes in use: too few to tell a misread reading
    size_t candidates = 4;   // readings tried per step (each costs a leave-one-out of the others)
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
    double typical = NAN;  // the typical miss of the datum holes in use without it, mm (NaN: not needed)
    double limit = NAN;    // max(factor x typical, minimum), mm
    bool outOfLine = false;  // miss beyond the limit
    std::string reason;             // why it is left out or flagged; empty for an agreeing one
};

struct DatumCheck {
    bool checked = false;  // false: not checked (disabled, or too few datum holes); see `note`
    std::string note;
    double typicalMiss = 0.0;  // median miss over the datum holes in use, mm
    double threshold = 0.0;    // max(factor x typicalMiss, minimum), mm
    DatumCheckOptions options;  // those it was checked with, for the report
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
