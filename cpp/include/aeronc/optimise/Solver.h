#pragma once
// The deterministic solver: the same input gives the same answer, bit for bit.
//
// Stepless spindle: a scan of the feasible polygon (its corners and a grid over its box, in
// ln n and ln f_z) picks the best point, and NLopt's SLSQP polishes it with exact gradients.
// The problem is convex in (ln n, ln f_z), so the polished point is the global optimum.
// Stepped gearbox: at every step the feasible f_z range is exact and the objective convex in
// ln f_z, so a golden-section search at each step and the best step give the optimum.
#include <aeronc/optimise/Constraints.h>
#include <aeronc/optimise/CuttingModel.h>
#include <aeronc/optimise/Objective.h>

#include <string>
#include <vector>

namespace aeronc::optimise {

struct ConstraintState {
    Constraint constraint;
    double value = 0;
    double utilisation = 0;  // at most 1 when met
    bool active = false;     // utilisation >= 1 - kActiveTolerance
};

std::vector<ConstraintState> constraintStates(const Problem& p, double n, double fz);

struct Optimum {
    Goal goal = Goal::Combined;
    double n = 0, fz = 0;
    double objective = 0;
    bool feasible = false;
    Evaluation at;
    std::vector<ConstraintState> constraints;

    // "cutting power P_max", ... for the active constraints.
    std::vector<std::string> activeConstraints() const;
};

struct Solution {
    std::string method;
    Optimum time;      // least time per part, t_min
    Optimum cost;      // least cost per part, C_min
    Optimum combined;  // least w1*t/t_min + w2*C/C_min
    long evaluations = 0;
};

// Validates p, throws aeronc::inputError with infeasibilityMessage() when no point is feasible.
Solution solve(const Problem& p);

// One objective over a non-empty region; adds its objective evaluations to *evaluations.
Optimum minimise(const Problem& p, const Region& region, const Posynomial& objective, Goal goal,
                 long* evaluations = nullptr);

// Fills in the evaluation, constraint states and feasibility of a point.
Optimum describePoint(const Problem& p, const Region& region, double n, double fz, double objective, Goal goal);

}  // namespace aeronc::optimise
