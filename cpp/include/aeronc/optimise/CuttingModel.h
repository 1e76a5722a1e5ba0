#pragma once
// The physical model at one point (n, f_z): cutting speed, force, power, feed, roughness,
// tool life, time and cost per part. These are the formulas the report prints; the solver
// works on the same model written as monomials and posynomials (Constraints.h, Objective.h).
#include <aeronc/optimise/Problem.h>

namespace aeronc::optimise {

struct Evaluation {
    double n = 0;             // r/min
    double fz = 0;            // mm/z
    double cuttingSpeed = 0;  // v_c = pi*d_0*n/1000, m/min
    double feedRate = 0;      // v_f = f_z*Z*n, mm/min
    double force = 0;         // F_c, N
    double power = 0;         // F_c*v_c/(60000*eta), kW at the motor
    double roughness = 0;     // R_a, micrometres
    double toolLife = 0;      // T, min
    double machiningTime = 0; // t_m = L/v_f, min
    double time = 0;          // t = t_0 + t_m + t_c*t_m/T, min per part
    double cost = 0;          // C = c_0*(t_0 + t_m) + (c_0*t_c + c_t)*t_m/T per part
};

double cuttingSpeed(const Problem& p, double n);
double cuttingForce(const Problem& p, double n, double fz);
double cuttingPower(const Problem& p, double n, double fz);
double roughness(const Problem& p, double fz);
double toolLife(const Problem& p, double n, double fz);
// The spindle speed at which the tool-life formula gives tool life T at feed f_z.
double speedForToolLife(const Problem& p, double T, double fz);

Evaluation evaluate(const Problem& p, double n, double fz);

}  // namespace aeronc::optimise
