#pragma once
// The objectives as posynomials in (n, f_z): a constant plus positive multiples of monomials.
// With t_m = L/(f_z*Z*n) and the tool-life formula, t_m/T is itself a monomial, so
//     t = t_0 + t_m + t_c*t_m/T
//     C = c_0*(t_0 + t_m) + (c_0*t_c + c_t)*t_m/T
//     f = w1*t/t_min + w2*C/C_min
// are posynomials. A posynomial is convex in X = ln n, Y = ln f_z; the feasible set is a convex
// polygon there (Constraints.h), so a local optimum the solver polishes is the global one.
#include <aeronc/optimise/Problem.h>

#include <vector>

namespace aeronc::optimise {

struct Posynomial {
    struct Term {
        double coefficient, nExp, fzExp;
    };
    double constant = 0;
    std::vector<Term> terms;

    double operator()(double n, double fz) const;
    // The value at X = ln n, Y = ln f_z and its gradient there.
    double atLog(double X, double Y, double& dX, double& dY) const;
    // this + scale*other
    Posynomial plus(const Posynomial& other, double scale) const;
};

enum class Goal { Time, Cost, Combined };
const char* toString(Goal g);

Posynomial timePerPart(const Problem& p);
Posynomial costPerPart(const Problem& p);
// w1*t/tMin + w2*C/cMin; a zero weight leaves its term out.
Posynomial combinedObjective(const Problem& p, double tMin, double cMin);

}  // namespace aeronc::optimise
