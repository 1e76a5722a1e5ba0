#include <aeronc/optimise/Problem.h>

#include <aeronc/core/Error.h>
#include <aeronc/optimise/CuttingModel.h>
#include <aeronc/optimise/Objective.h>

#include <cmath>
#include <sstream>

namespace aeronc::optimise {

namespace {

std::string num(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

void finite(double v, const std::string& what) {
    if (!std::isfinite(v)) throw inputError(what + " is not a finite number");
}
void positive(double v, const std::string& what) {
    finite(v, what);
    if (v <= 0) throw inputError(what + " must be positive, got " + num(v));
}
void nonNegative(double v, const std::string& what) {
    finite(v, what);
    if (v < 0) throw inputError(what + " must not be negative, got " + num(v));
}

// Each quantity of the model is a product of powers of n and f_z (or a sum of such), so its
// extremes over the search box lie at the box's corners: finite and positive there, it is
// finite and positive everywhere in between. An exponent or coefficient far outside any
// physical range (q_v = -9.2e18, q_F = 2^63) fails here instead of giving NaN or 0 later.
void checkModelRange(const Problem& p) {
    for (const double n : {p.machine.minSpindle, p.machine.maxSpindle})
        for (const double fz : {p.feedPerTooth.min, p.feedPerTooth.max}) {
            const Evaluation e = evaluate(p, n, fz);
            const struct {
                double v;
                const char* what;
            } quantities[] = {{e.force, "cutting force (C_F, x_F, y_F, u_F, q_F, w_F, K_Fc)"},
                              {e.power, "cutting power (the force and eta)"},
                              {e.toolLife, "tool life (C_v, m, q_v, x_v, y_v, u_v, p_v, K_v)"},
                              {e.time, "time per part"}};
            for (const auto& [v, what] : quantities)
                if (!(std::isfinite(v) && v > 0))
                    throw inputError("the coefficients give a " + std::string(what) + " of " + num(v) + " at n = " +
                                     num(n) + " r/min, f_z = " + num(fz) +
                                     " mm (a corner of the search box): a coefficient or exponent is outside any "
                                     "physical range");
            if (!(std::isfinite(e.cost) && e.cost >= 0))
                throw inputError("the coefficients give a cost per part of " + num(e.cost) + " at n = " + num(n) +
                                 " r/min, f_z = " + num(fz) + " mm (a corner of the search box)");
        }
    for (const Posynomial& f : {timePerPart(p), costPerPart(p)})
        for (const auto& t : f.terms)
            if (!std::isfinite(t.coefficient) || !std::isfinite(t.nExp) || !std::isfinite(t.fzExp))
                throw inputError("the tool-life coefficients overflow the objective over the search box: a coefficient "
                                 "or exponent is outside any physical range");
}

}  // namespace

void validate(const Problem& p) {
    const auto& c = p.cutter;
    positive(c.diameter, "cutter diameter d_0");
    if (c.teeth < 1) throw inputError("cutter teeth Z must be at least 1, got " + std::to_string(c.teeth));
    positive(c.cornerRadius, "cutter corner radius r (the roughness model R_a = k*f_z^2/r needs it)");
    if (c.cornerRadius > c.diameter / 2)
        throw inputError("cutter corner radius r = " + num(c.cornerRadius) + " mm exceeds the radius of d_0 = " +
                         num(c.diameter) + " mm");

    nonNegative(c.maxChipLoad, "cutter chip load f_z,max (0: none)");

    positive(p.cut.length, "cut length L");
    positive(p.cut.depth, "depth of cut a_p");
    positive(p.cut.width, "width of cut a_e");
    if (p.cut.width > c.diameter)
        throw inputError("width of cut a_e = " + num(p.cut.width) + " mm exceeds the cutter diameter d_0 = " +
                         num(c.diameter) + " mm");

    const auto& m = p.machine;
    positive(m.minSpindle, "machine minimum spindle speed n_min");
    positive(m.maxSpindle, "machine maximum spindle speed n_max");
    if (m.minSpindle > m.maxSpindle)
        throw inputError("machine minimum spindle speed n_min = " + num(m.minSpindle) + " r/min exceeds n_max = " +
                         num(m.maxSpindle) + " r/min");
    for (std::size_t i = 0; i < m.spindleSteps.size(); ++i) {
        positive(m.spindleSteps[i], "spindle step " + std::to_string(i + 1));
        if (i > 0 && m.spindleSteps[i] <= m.spindleSteps[i - 1])
            throw inputError("spindle steps must be strictly ascending (step " + std::to_string(i + 1) + ": " +
                             num(m.spindleSteps[i]) + " after " + num(m.spindleSteps[i - 1]) + ")");
    }
    positive(m.power, "machine power P_max");
    positive(m.maxFeed, "machine maximum feed v_f,max");
    positive(m.maxForce, "machine force limit [F]");
    positive(m.efficiency, "machine efficiency eta");
    if (m.efficiency > 1) throw inputError("machine efficiency eta must be at most 1, got " + num(m.efficiency));

    const auto& f = p.force;
    positive(f.cF, "force coefficient C_F");
    positive(f.kFc, "force correction K_Fc");
    finite(f.xF, "force exponent x_F");
    finite(f.yF, "force exponent y_F");
    finite(f.uF, "force exponent u_F");
    finite(f.qF, "force exponent q_F");
    finite(f.wF, "force exponent w_F");

    const auto& t = p.toolLife;
    positive(t.cV, "tool-life coefficient C_v");
    positive(t.m, "tool-life exponent m");
    positive(t.kV, "tool-life correction K_v");
    for (auto [v, n] : {std::pair{t.qV, "q_v"}, {t.xV, "x_v"}, {t.yV, "y_v"}, {t.uV, "u_v"}, {t.pV, "p_v"}})
        finite(v, std::string("tool-life exponent ") + n);

    const auto& e = p.economics;
    nonNegative(e.auxiliaryTime, "auxiliary time t_0");
    nonNegative(e.toolChangeTime, "tool-change time t_c");
    nonNegative(e.machineRate, "machine rate c_0");
    nonNegative(e.toolCost, "tool cost c_t");
    nonNegative(e.weightTime, "weight w1 (time)");
    nonNegative(e.weightCost, "weight w2 (cost)");
    if (e.weightTime + e.weightCost <= 0) throw inputError("weights w1 and w2 are both zero");
    if (e.weightCost > 0 && e.machineRate <= 0 && e.toolCost <= 0)
        throw inputError("cost objective has weight w2 > 0 but c_0 and c_t are both zero");

    positive(p.quality.raMax, "roughness limit R_a,max");
    checkModelRange(p);
    positive(p.quality.raCoefficient, "roughness coefficient");
    positive(p.feedPerTooth.min, "f_z search minimum");
    positive(p.feedPerTooth.max, "f_z search maximum");
    if (p.feedPerTooth.min >= p.feedPerTooth.max)
        throw inputError("f_z search minimum " + num(p.feedPerTooth.min) + " mm must be below its maximum " +
                         num(p.feedPerTooth.max) + " mm");
}

}  // namespace aeronc::optimise
