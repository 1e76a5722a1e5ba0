#pragma once
// The inputs of the cutting-parameter optimiser (impeller paper section 3): one milling
// operation, its cutter, the machine's limits, the empirical coefficients and the shop's
// economics. Plain data: no database and no file format here (see ProblemJson.h and the
// knowledge-base adapter for where the values come from).
//
// Units: mm, r/min, mm/min, m/min, N, kW, min, currency units; roughness in micrometres.
#include <string>
#include <vector>

namespace aeronc::optimise {

struct Cutter {
    double diameter = 0;      // d_0
    int teeth = 0;            // Z
    double cornerRadius = 0;  // r, the insert's nose radius (roughness)
    // The largest feed per tooth the tool takes (its maker's chip load); 0: no such limit.
    double maxChipLoad = 0;
};

struct Cut {
    double length = 0;  // feed path of one part
    double depth = 0;   // a_p, axial
    double width = 0;   // a_e, radial
};

struct MachineLimits {
    std::string name;
    double minSpindle = 1;  // n_min
    double maxSpindle = 0;  // n_max
    // The gearbox's speeds, ascending; empty for a stepless spindle. Steps outside
    // [minSpindle, maxSpindle] are never used.
    std::vector<double> spindleSteps;
    double power = 0;       // P_max, kW at the motor
    double maxFeed = 0;     // v_f,max
    double maxForce = 0;    // [F]
    double efficiency = 0;  // eta, spindle drive
};

// F_c = 9.81*C_F*a_p^x_F*f_z^y_F*a_e^u_F*Z / (d_0^q_F*n^w_F) * K_Fc   [N]
struct ForceCoefficients {
    double cF = 0, xF = 0, yF = 0, uF = 0, qF = 0, wF = 0, kFc = 1;
};

// Handbook tool-life form v_c = C_v*d_0^q_v*K_v / (T^m*a_p^x_v*f_z^y_v*a_e^u_v*Z^p_v), solved
// for T. With only C_v and m it is the plain Taylor law v_c*T^m = C.
struct ToolLifeCoefficients {
    double cV = 0, m = 0;
    double qV = 0, xV = 0, yV = 0, uV = 0, pV = 0, kV = 1;
};

struct Economics {
    double auxiliaryTime = 0;  // t_0, min per part (loading, approach, measuring)
    double toolChangeTime = 0; // t_c, min per tool change
    double machineRate = 0;    // c_0, cost per minute of machine and operator
    double toolCost = 0;       // c_t, cost of one tool life (inserts, regrind)
    double weightTime = 0.5;   // w1 of the combined objective
    double weightCost = 0.5;   // w2
};

struct Quality {
    double raMax = 0;  // R_a,max
    // R_a = k*f_z^2/r. 1000/(18*sqrt(3)) = 32.08 is the centre-line average of the scallops a
    // round nose of radius r leaves at feed f_z (mm in, micrometres out).
    double raCoefficient = 32.075014954979;
};

// The search box for f_z. Not a physical limit, but reported as active if the optimum sits on it.
struct FeedPerToothRange {
    double min = 0.005;
    double max = 1.0;
};

struct Problem {
    std::string name;
    Cutter cutter;
    Cut cut;
    MachineLimits machine;
    ForceCoefficients force;
    ToolLifeCoefficients toolLife;
    Economics economics;
    Quality quality;
    FeedPerToothRange feedPerTooth;
};

// Throws aeronc::inputError naming the first non-physical or missing value (zero or negative
// diameter, teeth, depths, limits, coefficients; NaN; n_min > n_max; weights both zero ...).
void validate(const Problem& p);

}  // namespace aeronc::optimise
