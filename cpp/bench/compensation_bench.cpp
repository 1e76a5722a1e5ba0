// Compensation figures: 100,000 drilling holes on a curved skin per method, and the import of a
// measurement file of 10,000 datum holes through the transform chain.
// Usage: aeronc_compensation_bench [--holes N] [--measured N]
#include <aeronc/compensation/Compensation.h>
#include <aeronc/compensation/MeasurementCsv.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace aeronc::compensation;

namespace {

using Clock = std::chrono::steady_clock;
double secs(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }
// Processor time of this process: on a shared machine the wall-clock time also counts others' work.
double cpu() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Rows of holes on a skin curved chordwise (radius 5 m), 15 mm pitch, rows 25 mm apart.
constexpr double kRadius = 5000.0;
Vec3 skin(double chord, double span) {
    const double t = chord / kRadius;
    return {kRadius * std::sin(t), span, kRadius * (std::cos(t) - 1.0)};
}
Vec3 normalAt(double chord) { return {std::sin(chord / kRadius), 0.0, std::cos(chord / kRadius)}; }
Vec3 bend(const Vec3& x) {
    return x + Vec3(0.3 * std::sin(x.y() / 3000.0), 0.2 * std::cos(x.x() / 2000.0), 0.6 * std::sin(x.x() / 1500.0 + x.y() / 5000.0));
}

}  // namespace

int main(int argc, char** argv) {
    int holes = 100000, measured = 10000;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--holes")) holes = std::atoi(argv[i + 1]);
        if (!std::strcmp(argv[i], "--measured")) measured = std::atoi(argv[i + 1]);
    }
    // 400 rows of holes/400 holes each, datum holes every 25th hole of every 25th row.
    const int rows = 400, perRow = holes / rows;
    CompensationInput in;
    for (int r = 0; r < rows; ++r)
        for (int k = 0; k <= perRow; ++k) {
            const double chord = 15.0 * k - 7.5 * perRow;
            const Vec3 p = skin(chord, 25.0 * r);
            if ((r % 25 == 0 || r == rows - 1) && (k % 25 == 0 || k == perRow)) {
                Datum d;
                d.id = "D" + std::to_string(in.datums.size() + 1);
                d.nominal = p;
                d.measured = bend(p);
                in.datums.push_back(d);
            } else if (static_cast<int>(in.holes.size()) < holes) {
                NominalHole h;
                h.id = "H" + std::to_string(in.holes.size() + 1);
                h.position = p;
                h.normal = normalAt(chord);
                in.holes.push_back(h);
            }
        }
    std::printf("compensation core, %zu drilling holes, %zu datum holes, curved skin (one run each)\n", in.holes.size(),
                in.datums.size());
    std::printf("  %-16s %8s   %8s\n", "", "wall", "processor");
    auto t0 = Clock::now();
    double c0 = cpu();
    assignRows(in.datums, in.holes, in.rows);
    std::printf("  %-16s %8.3f s %8.3f s\n", "rows found", secs(t0), cpu() - c0);
    t0 = Clock::now();
    c0 = cpu();
    const DatumCheck check = checkDatums(in.datums);
    const auto& loo = check.leaveOneOut;
    std::printf("  %-16s %8.3f s %8.3f s   (all seven methods' leave-one-out over the %zu datum holes; %zu left out)\n",
                "datum check", secs(t0), cpu() - c0, in.datums.size(), check.leftOut.size());
    for (Method m : allMethods()) {
        t0 = Clock::now();
        c0 = cpu();
        const Compensator c(m, in.datums);
        const auto holes = correctHoles(c, in.holes, 0.5);
        const double t = secs(t0), tc = cpu() - c0;
        if (m == Method::RigidTps) {
            // The neighbour check of the corrections: once per compensation, whatever the method.
            std::vector<Vec3> positions, corrections;
            for (const auto& h : holes) positions.push_back(h.nominal), corrections.push_back(h.correction);
            const auto tn = Clock::now();
            const double cn = cpu();
            const auto departures = neighbourDepartures(positions, corrections);
            std::printf("  %-16s %8.3f s %8.3f s   (%zu holes' departure from their neighbours' corrections, largest "
                        "%.4f mm)\n",
                        "neighbour check", secs(tn), cpu() - cn, departures.size(),
                        *std::max_element(departures.begin(), departures.end()));
        }
        double rms = 0.0;
        for (const auto& h : holes) rms += (h.compensated - bend(h.nominal)).squaredNorm();
        std::printf("  %-16s %8.3f s %8.3f s   (fit and %zu holes; error RMS %.4f mm, leave-one-out RMS %.4f mm)\n",
                    methodName(m).c_str(), t, tc, holes.size(), std::sqrt(rms / static_cast<double>(holes.size())),
                    loo[static_cast<size_t>(m)].rms);
    }

    // A measurement file of `measured` datum holes, each photographed along its normal.
    std::vector<DatumFrame> frames;
    std::string csv = "hole,u,v,height,quality\n";
    Mat4 mountFromCamera;
    mountFromCamera << 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, -90, 0, 0, 0, 1;
    char b[200];
    for (int i = 0; i < measured; ++i) {
        const double chord = 15.0 * (i % 200) - 1500.0;
        DatumFrame f;
        f.id = "DH" + std::to_string(i + 1);
        f.nominal = skin(chord, 25.0 * (i / 200));
        f.normal = normalAt(chord);
        f.chain.mountFromCamera = mountFromCamera;
        f.chain.machineFromMount = frameAt(f.nominal + 150.0 * f.normal, f.normal, Vec3::UnitX());
        const Vec3 c = f.chain.toCamera(bend(f.nominal));
        std::snprintf(b, sizeof b, "%s,%.6f,%.6f,%.6f,0.95\n", f.id.c_str(), c.x(), c.y(), c.z());
        csv += b;
        frames.push_back(f);
    }
    t0 = Clock::now();
    c0 = cpu();
    const auto readings = readMeasurementCsv(csv);
    const double tRead = secs(t0);
    t0 = Clock::now();
    const auto imported = importMeasurements(readings, frames);
    const double tImport = secs(t0);
    std::printf("measurement file, %d datum holes (%.2f MB): read %.4f s, through the chain %.4f s, total %.4f s "
                "(processor %.4f s)\n",
                measured, csv.size() / 1e6, tRead, tImport, tRead + tImport, cpu() - c0);
    return imported.size() == frames.size() ? 0 : 1;
}
