#include <aeronc/optimise/Objective.h>

#include <cmath>

namespace aeronc::optimise {

double Posynomial::operator()(double n, double fz) const {
    double s = constant;
    for (const auto& t : terms) s += t.coefficient * std::pow(n, t.nExp) * std::pow(fz, t.fzExp);
    return s;
}

double Posynomial::atLog(double X, double Y, double& dX, double& dY) const {
    double s = constant;
    dX = dY = 0;
    for (const auto& t : terms) {
        const double v = t.coefficient * std::exp(t.nExp * X + t.fzExp * Y);
        s += v;
        dX += t.nExp * v;
        dY += t.fzExp * v;
    }
    return s;
}

Posynomial Posynomial::plus(const Posynomial& other, double scale) const {
    Posynomial r = *this;
    r.constant += scale * other.constant;
    for (const auto& t : other.terms) r.terms.push_back({scale * t.coefficient, t.nExp, t.fzExp});
    return r;
}

const char* toString(Goal g) {
    switch (g) {
        case Goal::Time: return "time";
        case Goal::Cost: return "cost";
        case Goal::Combined: return "combined";
    }
    return "?";
}

namespace {

// t_m = L/(Z*n*f_z)
Posynomial::Term machiningTime(const Problem& p) { return {p.cut.length / p.cutter.teeth, -1, -1}; }

// t_m/T, the share of a tool life one part uses. T = (V/v_c)^(1/m) with v_c = pi*d*n/1000 and
// V = C_v*d^q*K_v/(a_p^x*f_z^y*a_e^u*Z^p), so 1/T = (pi*d*n/1000 * a_p^x*f_z^y*a_e^u*Z^p /
// (C_v*d^q*K_v))^(1/m).
Posynomial::Term toolsPerPart(const Problem& p) {
    const auto& t = p.toolLife;
    const double d = p.cutter.diameter;
    const double g = M_PI * d / 1000.0 * std::pow(p.cut.depth, t.xV) * std::pow(p.cut.width, t.uV) *
                     std::pow(double(p.cutter.teeth), t.pV) / (t.cV * std::pow(d, t.qV) * t.kV);
    const double inv = 1.0 / t.m;
    return {p.cut.length / p.cutter.teeth * std::pow(g, inv), inv - 1.0, t.yV * inv - 1.0};
}

}  // namespace

Posynomial timePerPart(const Problem& p) {
    Posynomial f;
    f.constant = p.economics.auxiliaryTime;
    f.terms.push_back(machiningTime(p));
    auto w = toolsPerPart(p);
    w.coefficient *= p.economics.toolChangeTime;
    if (w.coefficient > 0) f.terms.push_back(w);
    return f;
}

Posynomial costPerPart(const Problem& p) {
    const auto& e = p.economics;
    Posynomial f;
    f.constant = e.machineRate * e.auxiliaryTime;
    auto tm = machiningTime(p);
    tm.coefficient *= e.machineRate;
    if (tm.coefficient > 0) f.terms.push_back(tm);
    auto w = toolsPerPart(p);
    w.coefficient *= e.machineRate * e.toolChangeTime + e.toolCost;
    if (w.coefficient > 0) f.terms.push_back(w);
    return f;
}

Posynomial combinedObjective(const Problem& p, double tMin, double cMin) {
    Posynomial f;
    const auto& e = p.economics;
    if (e.weightTime > 0) f = f.plus(timePerPart(p), e.weightTime / tMin);
    if (e.weightCost > 0) f = f.plus(costPerPart(p), e.weightCost / cMin);
    return f;
}

}  // namespace aeronc::optimise
