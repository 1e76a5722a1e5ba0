#include <aeronc/optimise/Report.h>

#include <aeronc/core/Error.h>
#include <aeronc/core/SpindleSpeed.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace aeronc::optimise {

Method parseMethod(const std::string& s) {
    if (s == "nlopt") return Method::Deterministic;
    if (s == "ga") return Method::Genetic;
    if (s == "both") return Method::Both;
    throw inputError("--method must be nlopt, ga or both, got '" + s + "'");
}

namespace {

double fitness(const Problem& p, const Solution& s, const Evaluation& e) {
    double f = 0;
    if (p.economics.weightTime > 0) f += p.economics.weightTime * e.time / s.time.at.time;
    if (p.economics.weightCost > 0) f += p.economics.weightCost * e.cost / s.cost.at.cost;
    return f;
}

Optimum pointOf(const Problem& p, const Region& r, const Solution& s, double n, double fz) {
    Optimum o = describePoint(p, r, n, fz, 0, Goal::Combined);
    o.objective = fitness(p, s, o.at);
    return o;
}

BaselineResult baselineOf(const Problem& p, const Region& r, const Solution& s, const BaselineSpec& spec) {
    BaselineResult b;
    b.spec = spec;
    double n = 0;
    if (spec.n) n = *spec.n;
    else if (spec.cuttingSpeed) n = spindleSpeed(*spec.cuttingSpeed, p.cutter.diameter);
    else n = speedForToolLife(p, *spec.toolLife, spec.fz);
    b.asGiven = pointOf(p, r, s, n, spec.fz);
    if (b.asGiven.feasible) return b;
    const auto range = r.speedRange(spec.fz);
    if (!range) {
        b.note = "no spindle speed meets every limit at f_z = " + std::to_string(spec.fz) + " mm";
        return b;
    }
    double corrected = std::clamp(n, (*range)[0], (*range)[1]);
    if (r.stepped()) {
        // The step nearest below (or, if none, above) the clamped speed, within the range.
        std::optional<double> pick;
        for (double st : r.steps())
            if (st >= (*range)[0] * (1 - 1e-12) && st <= (*range)[1] * (1 + 1e-12) &&
                (!pick || std::abs(std::log(st / corrected)) < std::abs(std::log(*pick / corrected))))
                pick = st;
        if (!pick) {
            b.note = "no spindle step meets every limit at f_z = " + std::to_string(spec.fz) + " mm";
            return b;
        }
        corrected = *pick;
    }
    b.corrected = pointOf(p, r, s, corrected, spec.fz);
    return b;
}

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

// One table row; f is normalised with the primary solution's t_min and C_min on every row.
std::string row(const Problem& p, const Solution& primary, const std::string& label, const Optimum& o,
                const std::string& extra = "") {
    const auto& e = o.at;
    std::string s = label;
    s.resize(std::max<std::size_t>(s.size(), 28), ' ');
    s += fmt("%8.1f", e.n) + fmt("%8.4f", e.fz) + fmt("%8.1f", e.cuttingSpeed) + fmt("%8.1f", e.feedRate) +
         fmt("%8.0f", e.force) + fmt("%7.2f", e.power) + fmt("%7.3f", e.roughness) + fmt("%9.0f", e.toolLife) +
         fmt("%8.3f", e.time) + fmt("%8.3f", e.cost) + fmt("%8.4f", fitness(p, primary, e)) + (o.feasible ? "  yes" : "  NO");
    return s + extra + "\n";
}

std::string violated(const Optimum& o) {
    std::string s;
    for (const auto& c : o.constraints)
        if (c.utilisation > 1 + kFeasibilityTolerance)
            s += (s.empty() ? "  breaks " : ", ") + c.constraint.symbol + fmt(" (%.0f %%)", 100 * c.utilisation);
    return s;
}

std::string active(const Optimum& o) {
    std::string s;
    for (const auto& c : o.constraints)
        if (c.active) s += (s.empty() ? "" : ", ") + c.constraint.name + " " + c.constraint.symbol;
    if (!s.empty()) return s;
    // None exactly on its limit (a GA's answer usually): name the two nearest.
    auto cs = o.constraints;
    std::sort(cs.begin(), cs.end(), [](const auto& a, const auto& b) { return a.utilisation > b.utilisation; });
    s = "none exactly; nearest";
    for (std::size_t i = 0; i < 2 && i < cs.size(); ++i)
        s += std::string(i ? "," : "") + " " + cs[i].constraint.name + " " + cs[i].constraint.symbol +
             fmt(" at %.2f %%", 100 * cs[i].utilisation);
    return s;
}

std::string pct(double ratio) { return fmt("%+.1f %%", 100 * (ratio - 1)); }

nlohmann::json pointJson(const Optimum& o) {
    const auto& e = o.at;
    nlohmann::json j{{"n_rpm", e.n},
                     {"f_z_mm", e.fz},
                     {"v_c_m_min", e.cuttingSpeed},
                     {"v_f_mm_min", e.feedRate},
                     {"force_n", e.force},
                     {"power_kw", e.power},
                     {"ra_um", e.roughness},
                     {"tool_life_min", e.toolLife},
                     {"machining_time_min", e.machiningTime},
                     {"time_min", e.time},
                     {"cost", e.cost},
                     {"objective", o.objective},
                     {"feasible", o.feasible}};
    j["active"] = o.activeConstraints();
    nlohmann::json cs = nlohmann::json::array();
    for (const auto& c : o.constraints)
        cs.push_back({{"name", c.constraint.name},
                      {"symbol", c.constraint.symbol},
                      {"unit", c.constraint.unit},
                      {"value", c.value},
                      {"limit", c.constraint.limit},
                      {"utilisation", c.utilisation},
                      {"active", c.active}});
    j["constraints"] = cs;
    return j;
}

}  // namespace

Comparison compare(const Parameters& params, Method method, const GeneticOptions& ga) {
    Comparison c;
    c.parameters = params;
    const Problem& p = params.problem;
    if (method != Method::Genetic) c.deterministic = solve(p);
    if (method != Method::Deterministic) {
        if (!c.deterministic) {  // the GA alone would not say why nothing is feasible
            validate(p);
            const Region r = Region::of(p);
            if (r.empty()) throw inputError(infeasibilityMessage(r));
        }
        c.genetic = solveGenetic(p, ga);
    }
    const Region region = Region::of(p);
    for (const auto& ref : params.references) {
        Optimum o = pointOf(p, region, c.primary(), ref.n, ref.fz);
        c.references.push_back(o);
    }
    if (params.baseline) c.baseline = baselineOf(p, region, c.primary(), *params.baseline);
    return c;
}

std::string toText(const Comparison& c) {
    const Problem& p = c.parameters.problem;
    std::ostringstream o;
    o << "Cutting-parameter optimisation" << (p.name.empty() ? "" : ": " + p.name) << "\n";
    o << "  cutter d_0 " << p.cutter.diameter << " mm, Z " << p.cutter.teeth << ", r " << p.cutter.cornerRadius
      << " mm; a_p " << p.cut.depth << " mm, a_e " << p.cut.width << " mm, L " << p.cut.length << " mm\n";
    o << "  limits: [F] " << p.machine.maxForce << " N, P_max " << p.machine.power << " kW (eta "
      << p.machine.efficiency << "), v_f,max " << p.machine.maxFeed << " mm/min, n " << p.machine.minSpindle << ".."
      << p.machine.maxSpindle << " r/min"
      << (p.machine.spindleSteps.empty() ? std::string(" (stepless)")
                                         : " (" + std::to_string(p.machine.spindleSteps.size()) + " steps)")
      << ", R_a,max " << p.quality.raMax << " um\n\n";
    o << "                               n r/min  f_z mm  v_c m/min v_f    F_c N   P kW  R_a um    T min   t min       C       f  ok\n";
    const auto& e = p.economics;
    for (std::size_t i = 0; i < c.references.size(); ++i) {
        const auto& ref = c.parameters.references[i];
        const std::string printed = ref.fitness ? fmt("  (printed fitness %.3f)", *ref.fitness) : "";
        o << row(p, c.primary(), ref.label, c.references[i], violated(c.references[i]) + printed);
    }
    if (c.deterministic) o << row(p, c.primary(), "ours: scan+SLSQP", c.deterministic->combined);
    if (c.genetic) o << row(p, c.primary(), "ours: genetic algorithm", c.genetic->combined, violated(c.genetic->combined));
    if (c.baseline) {
        o << row(p, c.primary(), c.baseline->spec.label, c.baseline->asGiven, violated(c.baseline->asGiven));
        if (c.baseline->corrected) o << row(p, c.primary(), "  speed corrected to limits", *c.baseline->corrected);
        else if (!c.baseline->note.empty()) o << "  (" << c.baseline->note << ")\n";
    }
    o << "\n  f = " << e.weightTime << "*t/t_min + " << e.weightCost << "*C/C_min; t in min per part, C in "
      << "currency units per part; v_f in mm/min\n";
    const Solution& s = c.primary();
    o << "  single-objective optima (" << s.method << "): t_min = " << fmt("%.4f", s.time.at.time) << " min at n = "
      << fmt("%.1f", s.time.n) << ", f_z = " << fmt("%.4f", s.time.fz) << "; C_min = " << fmt("%.4f", s.cost.at.cost)
      << " at n = " << fmt("%.1f", s.cost.n) << ", f_z = " << fmt("%.4f", s.cost.fz) << "\n";
    if (c.deterministic) o << "  active at the optimum (scan+SLSQP): " << active(c.deterministic->combined) << "\n";
    if (c.genetic) {
        o << "  active at the optimum (GA): " << active(c.genetic->combined) << "\n";
        if (c.deterministic) {
            const auto &d = c.deterministic->combined, &g = c.genetic->combined;
            o << "  GA against scan+SLSQP: n " << pct(g.n / d.n) << ", f_z " << pct(g.fz / d.fz) << ", f "
              << pct(fitness(p, s, g.at) / fitness(p, s, d.at)) << " (" << c.genetic->evaluations << " against "
              << c.deterministic->evaluations << " evaluations)\n";
        }
    }
    if (c.baseline) {
        const Optimum& b = c.baseline->corrected ? *c.baseline->corrected : c.baseline->asGiven;
        const Optimum& opt = s.combined;
        o << "  optimum against " << c.baseline->spec.label << (c.baseline->corrected ? " (speed corrected)" : "")
          << ": productivity " << pct(b.at.time / opt.at.time) << ", time per part " << pct(opt.at.time / b.at.time)
          << ", cost per part " << pct(opt.at.cost / b.at.cost) << "\n";
    }
    for (std::size_t i = 0; i < c.references.size(); ++i) {
        const auto& ref = c.references[i];
        o << "  ours against " << c.parameters.references[i].label << ": n " << pct(s.combined.n / ref.n) << ", f_z "
          << pct(s.combined.fz / ref.fz) << "\n";
    }
    return o.str();
}

nlohmann::json toJson(const Comparison& c) {
    const Problem& p = c.parameters.problem;
    const Solution& primary = c.primary();
    // Every point carries f normalised with the primary solution's t_min and C_min ("fitness"),
    // besides the objective its own solver minimised ("objective").
    auto point = [&](const Optimum& o) {
        nlohmann::json j = pointJson(o);
        j["fitness"] = fitness(p, primary, o.at);
        return j;
    };
    auto solution = [&](const Solution& s) {
        return nlohmann::json{{"method", s.method},
                              {"evaluations", s.evaluations},
                              {"optimum", point(s.combined)},
                              {"time_optimum", point(s.time)},
                              {"cost_optimum", point(s.cost)}};
    };
    nlohmann::json j;
    j["name"] = p.name;
    j["objective"] = {{"w_time", p.economics.weightTime},
                      {"w_cost", p.economics.weightCost},
                      {"t_min", primary.time.at.time},
                      {"C_min", primary.cost.at.cost}};
    if (c.deterministic) j["deterministic"] = solution(*c.deterministic);
    if (c.genetic) j["genetic"] = solution(*c.genetic);
    nlohmann::json refs = nlohmann::json::array();
    for (std::size_t i = 0; i < c.references.size(); ++i) {
        auto r = point(c.references[i]);
        r["label"] = c.parameters.references[i].label;
        if (c.parameters.references[i].fitness) r["printed_fitness"] = *c.parameters.references[i].fitness;
        refs.push_back(r);
    }
    j["references"] = refs;
    if (c.baseline) {
        nlohmann::json b = point(c.baseline->asGiven);
        b["label"] = c.baseline->spec.label;
        if (c.baseline->corrected) b["speed_corrected"] = point(*c.baseline->corrected);
        if (!c.baseline->note.empty()) b["note"] = c.baseline->note;
        j["baseline"] = b;
    }
    return j;
}

}  // namespace aeronc::optimise
