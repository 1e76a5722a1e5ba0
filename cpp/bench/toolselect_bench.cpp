// Tool-selection figures: one machinable-ratio evaluation on a 200-vertex pocket with 5
// islands, and finishing + roughing selection for many pockets against 30 tools.
// Usage: aeronc_toolselect_bench [--pockets N] [--reps R]
//   --pockets N  pockets selected for (default 1000)
//   --reps R     repetitions of the per-evaluation timing; the best is printed (default 5)
// The selection asks for the roughing tool's full ratio, as the planner does (planTools).
#include <aeronc/toolselect/Selection.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace aeronc::toolselect;

namespace {
using Clock = std::chrono::steady_clock;
double secs(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

// 160 x 100 rounded rectangle (corner radius 8) as 200 points, with 5 elliptic islands.
PocketGeometry testPocket(double dx) {
    PocketGeometry p;
    const double w = 160, h = 100, r = 8;
    const double cx[4] = {w - r, r, r, w - r}, cy[4] = {h - r, h - r, r, r};
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 50; ++k) {
            const double a = M_PI / 2 * (c + k / 49.0);
            p.outer.push_back({dx + cx[c] + r * std::cos(a), cy[c] + r * std::sin(a)});
        }
    for (int i = 0; i < 5; ++i) {
        std::vector<std::array<double, 2>> isl;
        for (int k = 0; k < 24; ++k) {
            const double a = -2 * M_PI * k / 24;  // islands run the other way
            isl.push_back({dx + 20 + 30 * i + 6 * std::cos(a), 50 + 12 * std::sin(a)});
        }
        p.islands.push_back(isl);
    }
    p.depth = 20;
    p.minCornerRadius = 8;
    p.floorFilletRadius = 2;
    p.name = "bench";
    return p;
}

std::vector<Tool> thirtyTools() {
    std::vector<Tool> t;
    int n = 0;
    for (double d : {2, 3, 4, 5, 6, 8, 10, 12, 16, 20})
        for (double cr : {0.0, 1.0, 2.0}) {
            Tool x;
            x.id = "T" + std::to_string(++n);
            x.type = cr > 0 ? "bull" : "flat";
            x.material = "carbide";
            x.diameter = d, x.cornerRadius = std::min(cr, d / 2), x.flutes = 3;
            x.fluteLength = 3 * d, x.reach = 4 * d + 10;
            t.push_back(x);
        }
    return t;
}
}  // namespace

int main(int argc, char** argv) {
    int pockets = 1000, reps = 5;
    for (int i = 1; i + 1 < argc; ++i) {
        if (!std::strcmp(argv[i], "--pockets")) pockets = std::atoi(argv[i + 1]);
        if (!std::strcmp(argv[i], "--reps")) reps = std::max(1, std::atoi(argv[i + 1]));
    }
    const PocketGeometry p = testPocket(0);
    std::printf("# machinable ratio, 200-vertex pocket with 5 islands (ms per evaluation, best of %d x 50)\n",
                reps);
    for (double r : {2.0, 5.0, 8.0, 12.0}) {
        double best = 1e300;
        MachinableRatio m;
        for (int rep = 0; rep < reps; ++rep) {
            const int n = 50;
            const auto t0 = Clock::now();
            for (int k = 0; k < n; ++k) m = machinableRatio(p, r);
            best = std::min(best, 1e3 * secs(t0) / n);
        }
        std::printf("  r = %5.1f mm: %.3f ms  (eta %.6f, narrow passages %d)\n", r, best, m.eta, m.narrowPassages);
    }
    const std::vector<Tool> tools = thirtyTools();
    const auto t0 = Clock::now();
    int found = 0;
    double etaSum = 0;
    for (int k = 0; k < pockets; ++k) {
        const PocketGeometry q = testPocket(200.0 * k);
        found += finishingTool(q, tools) != nullptr;
        MachinableRatio m;
        found += roughingTool(q, tools, 0.85, &m) != nullptr;
        etaSum += m.eta;
    }
    std::printf("# finishing + roughing selection, %d pockets x %zu tools: %.2f s (%d choices, mean eta %.6f)\n",
                pockets, tools.size(), secs(t0), found, etaSum / std::max(1, pockets));
    return 0;
}
