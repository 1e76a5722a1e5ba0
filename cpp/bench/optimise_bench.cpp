// Cutting-parameter optimiser figures: one optimisation of the seed example (median of many),
// the genetic algorithm for comparison, and a 500-operation job of varied cuts.
// Usage: aeronc_optimise_bench [--operations N] [--repeat K]
#include <aeronc/optimise/Genetic.h>
#include <aeronc/optimise/ProblemJson.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace aeronc::optimise;

namespace {
using Clock = std::chrono::steady_clock;
double ms(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

template <class F>
double medianMs(int repeat, F f) {
    std::vector<double> t;
    for (int i = 0; i < repeat; ++i) {
        const auto a = Clock::now();
        f();
        t.push_back(ms(a, Clock::now()));
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}
}  // namespace

int main(int argc, char** argv) {
    int operations = 500, repeat = 101;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--operations")) operations = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--repeat")) repeat = std::atoi(argv[i + 1]);
    }
    std::ifstream in(std::string(AERONC_RESOURCES) + "/optimise/xa5032_face_mill_45_steel.json");
    const Problem seed = parseParameters(nlohmann::json::parse(in)).problem;

    double check = 0;  // keeps the work from being optimised away
    const double one = medianMs(repeat, [&] { check += solve(seed).combined.n; });
    Problem stepped = seed;
    stepped.machine.spindleSteps = {30, 37.5, 47.5, 60, 75, 95, 118, 150, 190, 235, 300, 375, 475, 600, 750, 950, 1180, 1500};
    const double oneStepped = medianMs(repeat, [&] { check += solve(stepped).combined.n; });
    const double ga = medianMs(std::max(5, repeat / 10), [&] { check += solveGenetic(seed).combined.n; });

    // A job: operations with depths 0.5..5 mm, widths 20..100 % of the cutter, roughness
    // limits 0.8..12.5 um, every fourth on the stepped gearbox.
    std::vector<Problem> job;
    const double ra[] = {0.8, 1.6, 3.2, 6.3, 12.5};
    for (int i = 0; i < operations; ++i) {
        Problem p = i % 4 == 3 ? stepped : seed;
        p.cut.depth = 0.5 + 4.5 * ((i * 37) % 100) / 99.0;
        p.cut.width = p.cutter.diameter * (0.2 + 0.8 * ((i * 61) % 100) / 99.0);
        p.quality.raMax = ra[i % 5];
        job.push_back(p);
    }
    int solved = 0;
    const auto a = Clock::now();
    for (const auto& p : job) {
        const Solution s = solve(p);
        check += s.combined.n;
        solved += s.combined.feasible;
    }
    const double jobMs = ms(a, Clock::now());

    std::printf("one optimisation, seed example (t_min, C_min, combined), stepless: %.3f ms (median of %d)\n", one,
                repeat);
    std::printf("one optimisation, seed example, 18 spindle steps:                %.3f ms (median of %d)\n",
                oneStepped, repeat);
    std::printf("genetic algorithm, seed example (60 x 150, three runs):          %.3f ms (median of %d)\n", ga,
                std::max(5, repeat / 10));
    std::printf("job of %d operations (a quarter stepped): %.3f s, %d feasible optima, %.3f ms each\n", operations,
                jobMs / 1000, solved, jobMs / operations);
    std::printf("targets: one optimisation < 20 ms, 500 operations < 5 s   (checksum %.6g)\n", check);
    return 0;
}
