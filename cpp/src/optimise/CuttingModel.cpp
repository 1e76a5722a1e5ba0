#include <aeronc/optimise/CuttingModel.h>

#include <aeronc/core/SpindleSpeed.h>

#include <cmath>

namespace aeronc::optimise {

double cuttingSpeed(const Problem& p, double n) { return aeronc::cuttingSpeed(n, p.cutter.diameter); }

double cuttingForce(const Problem& p, double n, double fz) {
    const auto& k = p.force;
    return 9.81 * k.cF * std::pow(p.cut.depth, k.xF) * std::pow(fz, k.yF) * std::pow(p.cut.width, k.uF) *
           p.cutter.teeth / (std::pow(p.cutter.diameter, k.qF) * std::pow(n, k.wF)) * k.kFc;
}

double cuttingPower(const Problem& p, double n, double fz) {
    // N * m/min / 60000 = kW at the tool; divided by eta for the motor.
    return cuttingForce(p, n, fz) * cuttingSpeed(p, n) / (60000.0 * p.machine.efficiency);
}

double roughness(const Problem& p, double fz) { return p.quality.raCoefficient * fz * fz / p.cutter.cornerRadius; }

namespace {
// v_c at tool life 1 min for this feed and engagement: C_v*d^q*K_v / (a_p^x*f_z^y*a_e^u*Z^p).
double speedAtUnitLife(const Problem& p, double fz) {
    const auto& t = p.toolLife;
    return t.cV * std::pow(p.cutter.diameter, t.qV) * t.kV /
           (std::pow(p.cut.depth, t.xV) * std::pow(fz, t.yV) * std::pow(p.cut.width, t.uV) *
            std::pow(double(p.cutter.teeth), t.pV));
}
}  // namespace

double toolLife(const Problem& p, double n, double fz) {
    return std::pow(speedAtUnitLife(p, fz) / cuttingSpeed(p, n), 1.0 / p.toolLife.m);
}

double speedForToolLife(const Problem& p, double T, double fz) {
    const double v = speedAtUnitLife(p, fz) / std::pow(T, p.toolLife.m);
    return spindleSpeed(v, p.cutter.diameter);
}

Evaluation evaluate(const Problem& p, double n, double fz) {
    Evaluation e;
    e.n = n;
    e.fz = fz;
    e.cuttingSpeed = cuttingSpeed(p, n);
    e.feedRate = fz * p.cutter.teeth * n;
    e.force = cuttingForce(p, n, fz);
    e.power = cuttingPower(p, n, fz);
    e.roughness = roughness(p, fz);
    e.toolLife = toolLife(p, n, fz);
    e.machiningTime = p.cut.length / e.feedRate;
    const auto& k = p.economics;
    const double toolsPerPart = e.machiningTime / e.toolLife;
    e.time = k.auxiliaryTime + e.machiningTime + k.toolChangeTime * toolsPerPart;
    e.cost = k.machineRate * (k.auxiliaryTime + e.machiningTime) +
             (k.machineRate * k.toolChangeTime + k.toolCost) * toolsPerPart;
    return e;
}

}  // namespace aeronc::optimise
