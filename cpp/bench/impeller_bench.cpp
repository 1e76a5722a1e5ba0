// Impeller figures: generating the test part, recognising it (target: 2 x 9 blades in under
// 1 s) and measuring its dimensions, for 2 x 5, 2 x 7 and 2 x 9 blades. Wall-clock and processor
// time (recognition integrates face areas on two threads, so processor time can exceed the wall
// clock); the median of five runs. Then the 5-axis toolpaths of the 2 x 9 impeller (every
// channel and the inducers, 24 stations a pass, fillet finishing included) with the route's
// tools, once: generation and check time.
// With --families, the wider families of docs/impeller.md (recognition time and face count each)
// instead of the sizes.
// Usage: aeronc_impeller_bench [--blades 9] [--no-paths] [--families]
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impellerpath/AxialOperations.h>
#include <aeronc/impellerpath/ImpellerToolpaths.h>
#include <aeronc/testparts/ImpellerGenerator.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;
double secs(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }
double cpu() { return double(std::clock()) / CLOCKS_PER_SEC; }

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

void recognition(const aeronc::testparts::ImpellerSpec& spec, const std::string& name) {
    auto t0 = Clock::now();
    const auto imp = aeronc::testparts::makeImpeller(spec);
    const double gen = secs(t0);
    std::vector<double> wall, proc, measure;
    aeronc::impeller::ImpellerFeatures f;
    for (int i = 0; i < 5; ++i) {
        const double c0 = cpu();
        t0 = Clock::now();
        f = aeronc::impeller::recogniseImpeller(imp.shape);
        wall.push_back(secs(t0));
        proc.push_back(cpu() - c0);
        t0 = Clock::now();
        aeronc::impeller::measureImpeller(imp.shape, f);
        measure.push_back(secs(t0));
    }
    std::printf("%-14s %4d faces  generate %6.2f s  recognise %6.3f s (cpu %6.3f s)  measure %6.3f s\n",
                name.c_str(), f.faceCount, gen, median(wall), median(proc), median(measure));
}

void run(int blades) {
    aeronc::testparts::ImpellerSpec spec;
    spec.bladeCount = blades;
    recognition(spec, std::to_string(blades) + " x 2 blades");
}

// The tools the default route picks for the 2 x 9 impeller (tests/impeller check the choice).
void paths() {
    const auto imp = aeronc::testparts::makeImpeller({});
    const auto f = aeronc::impeller::recogniseImpeller(imp.shape);
    const auto d = aeronc::impeller::measureImpeller(imp.shape, f);
    aeronc::impellerpath::CutterShape rough{"EM-BALL8", 1, 4, 0, 16, 4, 25, 18000, 2160};
    aeronc::impellerpath::CutterShape finish{"TB-4-3", 2, 2, 3, 25, 5, 50, 18000, 4320};
    aeronc::impellerpath::CutterShape fillet{"EM-BALL4", 3, 2, 0, 16, 2, 26, 18000, 1500};
    const double c0 = cpu();
    const auto t0 = Clock::now();
    const auto p = aeronc::impellerpath::impellerToolpaths(imp.shape, f, d, {rough, finish, fillet});
    size_t moves = 0;
    for (const auto& op : p.operations) moves += op.moves.size();
    std::printf("toolpaths 2 x 9 blades, %zu operations: %zu moves (%d positions of 3 channel kinds checked, %d links) "
                "in %.1f s (cpu %.1f s); deepest gouge %.4f mm, %d holder collisions, %d tilted, %d links touching\n",
                p.operations.size(), moves, p.check.positions, p.check.links, secs(t0), cpu() - c0, p.check.maxGouge,
                p.check.holderCollisions, p.check.tilted, p.check.linkCollisions);
    // Turning, facing, drilling and boring with the default route's tools.
    aeronc::impellerpath::AxialCutters axial;
    axial.faceMill = aeronc::impellerpath::flatCutter("FM-125", 4, 125, 6, 63, 500, 1000);
    axial.drill = aeronc::impellerpath::flatCutter("DR-18", 5, 18, 130, 145, 500, 100);
    axial.boringMill = aeronc::impellerpath::flatCutter("EM-F16", 6, 16, 32, 45, 3000, 600);
    const double c1 = cpu();
    const auto t1 = Clock::now();
    const auto a = aeronc::impellerpath::axialToolpaths(imp.shape, f, d, axial);
    moves = 0;
    for (const auto& op : a.operations) moves += op.moves.size();
    std::printf("turn, face, drill, bore: %zu operations, %zu moves (%d positions checked) in %.1f s (cpu %.1f s); "
                "deepest gouge %.4f mm, %d holder collisions\n",
                a.operations.size(), moves, a.check.positions, secs(t1), cpu() - c1, a.check.maxGouge,
                a.check.holderCollisions);
}

// The wider families (the specs of cpp/tests/impeller/ImpellerFamiliesTest.cpp).
void families() {
    using aeronc::testparts::ImpellerSpec;
    ImpellerSpec radial;
    radial.wrapDeg = 0, radial.leanDeg = 0;
    recognition(radial, "radial 2 x 9");
    ImpellerSpec seam;
    seam.hubSpline = true, seam.seamAcrossBlade = true;
    recognition(seam, "seam 2 x 9");
    ImpellerSpec pump;
    pump.pumpPlate = true, pump.splitters = false, pump.bladeCount = 6, pump.wrapDeg = 0, pump.leanDeg = 0;
    pump.filletRadius = 0, pump.boreDiameter = 16, pump.leadingRadius = 16, pump.bladeHeight = 14;
    recognition(pump, "pump 6 radial");
    pump.bladeCount = 9, pump.wrapDeg = 25, pump.filletRadius = 1.5;
    recognition(pump, "pump 9 curved");
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> sizes{5, 7, 9};
    bool withPaths = true, withFamilies = false;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--blades") == 0 && i + 1 < argc) sizes = {std::stoi(argv[++i])};
        else if (std::strcmp(argv[i], "--no-paths") == 0) withPaths = false;
        else if (std::strcmp(argv[i], "--families") == 0) withFamilies = true;
    }
    if (withFamilies) {
        families();
        return 0;
    }
    std::printf("impeller recognition (target: 2 x 9 blades under 1 s)\n");
    for (int n : sizes) run(n);
    if (withPaths) paths();
    return 0;
}
