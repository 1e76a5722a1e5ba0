#include <aeronc/optimise/Solver.h>

#include <aeronc/core/Error.h>

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aeronc::optimise {

std::vector<ConstraintState> constraintStates(const Problem& p, double n, double fz) {
    std::vector<ConstraintState> out;
    for (const auto& c : constraintsOf(p)) {
        const double u = c.utilisation(n, fz);
        out.push_back({c, c.value(n, fz), u, u >= 1.0 - kActiveTolerance});
    }
    return out;
}

std::vector<std::string> Optimum::activeConstraints() const {
    std::vector<std::string> names;
    for (const auto& s : constraints)
        if (s.active) names.push_back(s.constraint.name + " " + s.constraint.symbol);
    return names;
}

Optimum describePoint(const Problem& p, const Region& region, double n, double fz, double objective, Goal goal) {
    Optimum o;
    o.goal = goal;
    o.n = n;
    o.fz = fz;
    o.objective = objective;
    o.feasible = region.contains(n, fz) && std::isfinite(objective);
    o.at = evaluate(p, n, fz);
    o.constraints = constraintStates(p, n, fz);
    return o;
}

namespace {

constexpr int kScan = 33;            // grid points per axis of the scan
constexpr int kGoldenSteps = 90;     // 0.618^90 ~ 1e-19 of the interval
const double kGolden = (std::sqrt(5.0) - 1) / 2;

struct Counter {
    const Posynomial& f;
    long count = 0;
    double operator()(double n, double fz) {
        ++count;
        return f(n, fz);
    }
};

// Least of a function convex in y on [lo, hi] (both finite).
template <class F>
std::pair<double, double> goldenSection(F f, double lo, double hi) {
    double a = lo, b = hi;
    double x1 = b - kGolden * (b - a), x2 = a + kGolden * (b - a);
    double f1 = f(x1), f2 = f(x2);
    for (int i = 0; i < kGoldenSteps && b - a > 1e-15 * (1 + std::abs(a)); ++i) {
        if (f1 <= f2) {
            b = x2, x2 = x1, f2 = f1;
            x1 = b - kGolden * (b - a);
            f1 = f(x1);
        } else {
            a = x1, x1 = x2, f1 = f2;
            x2 = a + kGolden * (b - a);
            f2 = f(x2);
        }
    }
    // The ends too: the optimum often sits on a limit.
    std::pair<double, double> best{x1, f1};
    if (f2 < best.second) best = {x2, f2};
    for (double y : {lo, hi}) {
        const double v = f(y);
        if (v < best.second) best = {y, v};
    }
    return best;
}

struct SlsqpData {
    const Posynomial* objective;
    double scale;
    long* count;
};
struct PlaneData {
    double a, b, c;  // a*X + b*Y - c <= 0
};

double slsqpObjective(const std::vector<double>& x, std::vector<double>& grad, void* data) {
    auto* d = static_cast<SlsqpData*>(data);
    ++*d->count;
    double dX, dY;
    const double v = d->objective->atLog(x[0], x[1], dX, dY);
    if (!grad.empty()) grad[0] = dX / d->scale, grad[1] = dY / d->scale;
    return v / d->scale;
}

double slsqpPlane(const std::vector<double>& x, std::vector<double>& grad, void* data) {
    auto* h = static_cast<PlaneData*>(data);
    if (!grad.empty()) grad[0] = h->a, grad[1] = h->b;
    return h->a * x[0] + h->b * x[1] - h->c;
}

}  // namespace

Optimum minimise(const Problem& p, const Region& region, const Posynomial& objective, Goal goal, long* evaluations) {
    Counter f{objective};
    double bestN = 0, bestFz = 0, bestV = std::numeric_limits<double>::infinity();
    auto consider = [&](double n, double fz) {
        if (!region.contains(n, fz)) return;
        const double v = f(n, fz);
        if (v < bestV) bestV = v, bestN = n, bestFz = fz;
    };

    const auto corners = region.corners();
    if (corners.empty()) throw inputError(infeasibilityMessage(region));

    if (region.stepped()) {
        for (double s : region.steps()) {
            const auto r = region.feedPerToothRange(s);
            if (!r) continue;
            const auto [y, v] = goldenSection([&](double Y) { return f(s, std::exp(Y)); }, std::log((*r)[0]),
                                              std::log((*r)[1]));
            (void)v;
            consider(s, std::exp(y));
        }
    } else {
        double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
        for (const auto& c : corners) {
            consider(c.n, c.fz);
            x0 = std::min(x0, std::log(c.n)), x1 = std::max(x1, std::log(c.n));
            y0 = std::min(y0, std::log(c.fz)), y1 = std::max(y1, std::log(c.fz));
        }
        for (int i = 0; i < kScan; ++i)
            for (int j = 0; j < kScan; ++j)
                consider(std::exp(x0 + (x1 - x0) * i / (kScan - 1)), std::exp(y0 + (y1 - y0) * j / (kScan - 1)));

        if (x1 - x0 < 1e-12 || y1 - y0 < 1e-12) {
            // A segment (n or f_z pinned by its limits): a line search along the free variable.
            if (x1 - x0 < 1e-12) {
                const double n = std::exp(0.5 * (x0 + x1));
                const auto [y, v] = goldenSection([&](double Y) { return f(n, std::exp(Y)); }, y0, y1);
                (void)v;
                consider(n, std::exp(y));
            } else {
                const double fz = std::exp(0.5 * (y0 + y1));
                const auto [x, v] = goldenSection([&](double X) { return f(std::exp(X), fz); }, x0, x1);
                (void)v;
                consider(std::exp(x), fz);
            }
        } else {
            // Polish with SLSQP in (ln n, ln f_z), where every constraint is linear.
            long count = 0;
            SlsqpData data{&objective, bestV, &count};
            std::vector<PlaneData> planes;
            for (const auto& c : region.constraints()) {
                const double lk = std::log(c.coefficient), ll = std::log(c.limit);
                planes.push_back(c.upper ? PlaneData{c.nExp, c.fzExp, ll - lk} : PlaneData{-c.nExp, -c.fzExp, lk - ll});
            }
            nlopt::opt opt(nlopt::LD_SLSQP, 2);
            opt.set_lower_bounds({x0, y0});
            opt.set_upper_bounds({x1, y1});
            opt.set_min_objective(slsqpObjective, &data);
            for (auto& h : planes) opt.add_inequality_constraint(slsqpPlane, &h, 1e-13);
            opt.set_xtol_abs(1e-13);
            opt.set_ftol_rel(1e-15);
            opt.set_maxeval(400);
            // exp/log round trips can leave the start a hair outside the box, which NLopt refuses.
            std::vector<double> x{std::clamp(std::log(bestN), x0, x1), std::clamp(std::log(bestFz), y0, y1)};
            double fx = 0;
            try {
                opt.optimize(x, fx);
            } catch (const std::exception&) {
                // Round-off stops SLSQP at the optimum of a vertex; x holds its last point.
            }
            f.count += count;
            consider(std::exp(x[0]), std::exp(x[1]));
        }
    }
    if (!std::isfinite(bestV)) throw inputError(infeasibilityMessage(region));
    if (evaluations) *evaluations += f.count;
    return describePoint(p, region, bestN, bestFz, bestV, goal);
}

Solution solve(const Problem& p) {
    validate(p);
    const Region region = Region::of(p);
    if (region.empty()) throw inputError(infeasibilityMessage(region));
    Solution s;
    s.method = region.stepped() ? "golden section at each spindle step" : "scan + SLSQP (NLopt)";
    s.time = minimise(p, region, timePerPart(p), Goal::Time, &s.evaluations);
    s.cost = minimise(p, region, costPerPart(p), Goal::Cost, &s.evaluations);
    const double cMin = p.economics.weightCost > 0 ? s.cost.at.cost : 1.0;
    s.combined = minimise(p, region, combinedObjective(p, s.time.at.time, cMin), Goal::Combined, &s.evaluations);
    return s;
}

}  // namespace aeronc::optimise
