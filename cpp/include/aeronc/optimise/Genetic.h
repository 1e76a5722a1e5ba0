#pragma once
// A genetic algorithm over (n, f_z), offered for comparison with the deterministic solver as
// the impeller paper used one. Real-coded in (ln n, ln f_z): tournament selection with
// feasibility rules (a feasible point beats an infeasible one; of two infeasible points the
// one that violates less wins), simulated binary crossover, polynomial mutation, and the best
// individuals kept. Its random numbers come from std::mt19937_64, whose sequence the C++
// standard fixes, turned into doubles here: a fixed seed gives the same answer everywhere.
#include <aeronc/optimise/Solver.h>

#include <cstdint>

namespace aeronc::optimise {

struct GeneticOptions {
    std::uint64_t seed = 1;
    int population = 60;
    int generations = 150;
    double crossoverRate = 0.9;
    double mutationRate = 0.5;  // per gene
    int elites = 2;
};

// Validates p and solves the three problems (t_min, C_min, combined) like solve(). A run that
// ends without a feasible individual returns it with feasible = false rather than throwing.
Solution solveGenetic(const Problem& p, const GeneticOptions& options = {});

}  // namespace aeronc::optimise
