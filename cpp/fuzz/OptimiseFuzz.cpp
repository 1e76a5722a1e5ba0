// The optimiser's parameter file: reader, solver, a small genetic run and objective map. A
// result called feasible must have finite, positive figures.
#include "FuzzCommon.h"

#include <aeronc/optimise/Genetic.h>
#include <aeronc/optimise/ObjectiveMap.h>
#include <aeronc/optimise/ProblemJson.h>
#include <aeronc/optimise/Solver.h>

#include <cmath>

using namespace aeronc;
using namespace aeronc::optimise;

namespace {
void checkOptimum(const Optimum& o) {
    if (!o.feasible) return;
    if (!std::isfinite(o.objective) || !(o.at.force > 0) || !(o.at.power > 0) || !std::isfinite(o.at.time) ||
        !(o.at.toolLife > 0))
        fuzz::finding("a feasible optimum with figures that are not finite and positive");
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    Parameters p;
    if (!fuzz::expectingErrors([&] { p = parseParameters(parameterJson(fuzz::text(data, size))); })) return 0;
    Solution s;
    if (fuzz::expectingErrors([&] { s = solve(p.problem); })) {
        checkOptimum(s.combined);
        MapBox box;
        box.nCount = box.fzCount = 4;
        fuzz::expectingErrors([&] { objectiveMap(p.problem, s, box); });
    }
    GeneticOptions ga;
    ga.population = 8;
    ga.generations = 4;
    ga.elites = 1;
    Solution g;
    if (fuzz::expectingErrors([&] { g = solveGenetic(p.problem, ga); })) checkOptimum(g.combined);
    return 0;
}
