// Impeller figures: generating the test part, recognising it (target: 2 x 9 blades in under
// 1 s) and measuring its dimensions, for 2 x 5, 2 x 7 and 2 x 9 blades. Wall-clock and processor
// time (recognition integrates face areas on two threads, so processor time can exceed the wall
// clock); the median of five runs.
// Usage: aeronc_impeller_bench [--blades 9]
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
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

void run(int blades) {
    aeronc::testparts::ImpellerSpec spec;
    spec.bladeCount = blades;
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
    std::printf("%2d x 2 blades  %4d faces  generate %6.2f s  recognise %6.3f s (cpu %6.3f s)  measure %6.3f s\n",
                blades, f.faceCount, gen, median(wall), median(proc), median(measure));
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<int> sizes{5, 7, 9};
    if (argc == 3 && std::strcmp(argv[1], "--blades") == 0) sizes = {std::stoi(argv[2])};
    std::printf("impeller recognition (target: 2 x 9 blades under 1 s)\n");
    for (int n : sizes) run(n);
    return 0;
}
