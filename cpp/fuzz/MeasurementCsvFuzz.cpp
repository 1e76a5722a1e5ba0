// The camera's measurement file (measured-hole import): the reader, what it accepts written
// back and read again, then the import through the transform chains of a four-hole photo-hole
// set and the compensation of six drilling holes by every method.
#include "FuzzCommon.h"

#include <aeronc/compensation/MeasurementCsv.h>

#include <cmath>
#include <cstdio>

using namespace aeronc;
using namespace aeronc::compensation;

namespace {

// Two rows of five holes 25 mm apart, 40 mm between the rows; the row ends are the datum
// holes DH1..DH4, photographed from 60 mm along the normal with the camera 90 mm below the
// gauge point (a seed reading (0, 0, 60) is the nominal hole).
struct Layout {
    std::vector<DatumFrame> frames;
    std::vector<NominalHole> holes;
};

const Layout& layout() {
    static const Layout l = [] {
        Layout out;
        Mat4 mountFromCamera;
        mountFromCamera << 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, -90, 0, 0, 0, 1;
        for (int row = 0; row < 2; ++row)
            for (int k = 0; k < 5; ++k) {
                const Vec3 p(25.0 * k, 40.0 * row, 0.0);
                if (k == 0 || k == 4) {
                    DatumFrame f;
                    f.id = "DH" + std::to_string(out.frames.size() + 1);
                    f.nominal = p;
                    f.chain.mountFromCamera = mountFromCamera;
                    f.chain.machineFromMount = frameAt(p + 150.0 * Vec3::UnitZ(), Vec3::UnitZ(), Vec3::UnitX());
                    out.frames.push_back(f);
                } else {
                    NominalHole h;
                    h.id = "H" + std::to_string(out.holes.size() + 1);
                    h.position = p;
                    out.holes.push_back(h);
                }
            }
        return out;
    }();
    return l;
}

std::string written(const std::vector<CameraReading>& readings) {
    std::string s = "hole,u,v,height,quality\n";
    char b[128];
    for (const auto& r : readings) {
        s += r.id;
        std::snprintf(b, sizeof b, ",%.17g,%.17g,%.17g", r.u, r.v, r.height);
        s += b;
        if (r.quality) std::snprintf(b, sizeof b, ",%.17g\n", *r.quality);
        else std::snprintf(b, sizeof b, "\n");
        s += b;
    }
    return s;
}

bool same(const CameraReading& a, const CameraReading& b) {
    return a.id == b.id && a.u == b.u && a.v == b.v && a.height == b.height && a.quality == b.quality;
}

void checkReadings(const std::vector<CameraReading>& readings) {
    if (readings.empty()) fuzz::finding("the reader accepted a file without measurements");
    for (const auto& r : readings) {
        if (r.id.empty() || r.id.find_first_of(",\n") != std::string::npos)
            fuzz::finding("an accepted hole id is empty or holds a comma or line break");
        if (!std::isfinite(r.u) || !std::isfinite(r.v) || !std::isfinite(r.height) || !(r.height > 0.0) ||
            (r.quality && !std::isfinite(*r.quality)))
            fuzz::finding("an accepted reading holds a value that is not finite, or a height that is not positive");
    }
}

void checkCompensation(const std::vector<ImportedDatum>& imported) {
    CompensationInput in;
    for (const auto& d : imported) in.datums.push_back(d.datum);
    in.holes = layout().holes;
    CompensationResult r;
    if (!fuzz::expectingErrors([&] { r = compensate(in); })) return;
    for (const auto& h : r.holes)
        if (!finite(h.compensated) || !finite(h.normal)) fuzz::finding("a compensated hole is not finite");
    for (const auto& f : r.leaveOneOut) {
        if (!f.available) continue;
        std::vector<Vec3> c;
        if (!fuzz::expectingErrors([&] {
                std::vector<Datum> datums = in.datums;
                std::vector<NominalHole> holes = in.holes;
                assignRows(datums, holes);
                c = Compensator(f.method, datums).corrections(holes);
            }))
            fuzz::finding(methodName(f.method) + " has a leave-one-out error but refuses the datum holes");
        for (const auto& v : c)
            if (!finite(v)) fuzz::finding(methodName(f.method) + " gives a correction that is not finite");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<CameraReading> readings;
    if (!fuzz::expectingErrors([&] { readings = readMeasurementCsv(fuzz::text(data, size)); })) return 0;
    checkReadings(readings);

    std::vector<CameraReading> again;
    if (!fuzz::expectingErrors([&] { again = readMeasurementCsv(written(readings)); }))
        fuzz::finding("readings the reader accepted do not read back once written");
    if (again.size() != readings.size()) fuzz::finding("readings written and read again change in number");
    for (size_t i = 0; i < readings.size(); ++i)
        if (!same(readings[i], again[i])) fuzz::finding("a reading written and read again changes");

    std::vector<ImportedDatum> imported;
    if (!fuzz::expectingErrors([&] { imported = importMeasurements(readings, layout().frames); })) return 0;
    for (const auto& d : imported)
        if (!finite(d.datum.measured)) fuzz::finding("an imported datum hole is not finite");
    checkCompensation(imported);
    return 0;
}
