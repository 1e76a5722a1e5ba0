#pragma once
// The camera's measurement file and its import (docs/compensation.md):
//
//   # comment lines and blank lines are skipped
//   hole,u,v,height,quality          (optional header, these names in this order)
//   DH1,0.012,-0.034,60.021,0.98     hole id, U and V in the camera frame (mm), the height of
//   DH2,-0.051,0.020,59.987          the camera above the hole (mm), optional quality figure
//
// Comma separated, UTF-8 (a byte-order mark is skipped), one datum hole per line.
#include <aeronc/compensation/Compensation.h>
#include <aeronc/compensation/TransformChain.h>

#include <optional>
#include <string>
#include <vector>

namespace aeronc::compensation {

struct CameraReading {
    std::string id;
    double u = 0.0, v = 0.0, height = 0.0;
    std::optional<double> quality;
    int line = 0;  // 1-based line in the file
};

// Parses the file; refuses (naming the line) a malformed line, a field that is not a number,
// NaN or an infinite value, an empty id, a hole given twice, a file without measurements.
std::vector<CameraReading> readMeasurementCsv(const std::string& text);

// A datum hole of the photo-hole set and the transform chain of its picture.
struct DatumFrame {
    std::string id;
    Vec3 nominal = Vec3::Zero();
    Vec3 normal = Vec3::UnitZ();
    TransformChain chain;
};

struct ImportOptions {
    double maxDeviation = 5.0;  // a measured hole farther than this from nominal is an outlier, mm
    double minQuality = 0.0;    // a quality figure below this is refused (when the file has them)
};

struct ImportedDatum {
    Datum datum;  // nominal and measured in the part frame
    CameraReading reading;
};

// Maps every reading through its datum's transform chain. Refuses ids not in the set, datum
// holes of the set missing from the file, fewer than two datum holes, outliers, low quality
// and transforms that are not rigid, each with a message listing the holes at fault.
// The result follows the order of `datums`.
std::vector<ImportedDatum> importMeasurements(const std::vector<CameraReading>& readings,
                                              const std::vector<DatumFrame>& datums, const ImportOptions& options = {});

}  // namespace aeronc::compensation
