#include <aeronc/optimise/Genetic.h>

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace aeronc::optimise {

namespace {

// Uniform in [0, 1) from the top 53 bits: the same on every standard library, unlike
// std::uniform_real_distribution.
struct Random {
    std::mt19937_64 engine;
    double uniform() { return double(engine() >> 11) * 0x1.0p-53; }
    int below(int k) { return int(uniform() * k); }
};

struct Individual {
    double X = 0, Y = 0;  // ln n (or a fractional step index when stepped), ln f_z
    double n = 0, fz = 0;
    double objective = 0;
    double violation = 0;  // sum of ln(utilisation) over the limits exceeded
};

bool better(const Individual& a, const Individual& b) {
    if (a.violation == 0 && b.violation == 0) return a.objective < b.objective;
    if (a.violation == 0 || b.violation == 0) return a.violation == 0;
    return a.violation < b.violation;
}

class Search {
public:
    Search(const Problem& p, const GeneticOptions& o, const Posynomial& f, std::uint64_t seed)
        : p_(p), o_(o), f_(f), constraints_(constraintsOf(p)) {
        rng_.engine.seed(seed);
        const auto& steps = p.machine.spindleSteps;
        if (steps.empty()) {
            lo_[0] = std::log(p.machine.minSpindle), hi_[0] = std::log(p.machine.maxSpindle);
        } else {
            lo_[0] = 0, hi_[0] = double(steps.size()) - 1e-9;
        }
        lo_[1] = std::log(p.feedPerTooth.min), hi_[1] = std::log(p.feedPerTooth.max);
    }

    Individual run(long& evaluations) {
        std::vector<Individual> pop(std::size_t(o_.population));
        for (auto& x : pop) {
            x.X = lo_[0] + rng_.uniform() * (hi_[0] - lo_[0]);
            x.Y = lo_[1] + rng_.uniform() * (hi_[1] - lo_[1]);
            assess(x);
        }
        for (int g = 0; g < o_.generations; ++g) {
            std::stable_sort(pop.begin(), pop.end(), better);
            std::vector<Individual> next(pop.begin(), pop.begin() + std::min<long>(o_.elites, long(pop.size())));
            while (next.size() < pop.size()) {
                Individual a = tournament(pop), b = tournament(pop);
                if (rng_.uniform() < o_.crossoverRate) crossover(a, b);
                mutate(a);
                mutate(b);
                assess(a);
                next.push_back(a);
                if (next.size() < pop.size()) {
                    assess(b);
                    next.push_back(b);
                }
            }
            pop.swap(next);
        }
        evaluations += count_;
        return *std::min_element(pop.begin(), pop.end(), better);
    }

private:
    void assess(Individual& x) {
        ++count_;
        const auto& steps = p_.machine.spindleSteps;
        x.n = steps.empty() ? std::exp(x.X) : steps[std::size_t(std::clamp(x.X, 0.0, hi_[0]))];
        x.fz = std::exp(x.Y);
        x.objective = f_(x.n, x.fz);
        x.violation = 0;
        constexpr double kNever = std::numeric_limits<double>::infinity();  // NaN is no solution
        for (const auto& c : constraints_) {
            const double u = c.utilisation(x.n, x.fz);
            if (!(u <= 1 + kFeasibilityTolerance)) x.violation += std::isfinite(u) ? std::log(u) : kNever;
        }
        if (!std::isfinite(x.objective)) x.violation = kNever;
    }

    const Individual& tournament(const std::vector<Individual>& pop) {
        const Individual& a = pop[std::size_t(rng_.below(int(pop.size())))];
        const Individual& b = pop[std::size_t(rng_.below(int(pop.size())))];
        return better(a, b) ? a : b;
    }

    // Simulated binary crossover (distribution index 15), gene by gene.
    void crossover(Individual& a, Individual& b) {
        for (int k = 0; k < 2; ++k) {
            double& u = k ? a.Y : a.X;
            double& v = k ? b.Y : b.X;
            if (rng_.uniform() > 0.5) continue;
            const double r = rng_.uniform();
            const double beta = r <= 0.5 ? std::pow(2 * r, 1.0 / 16) : std::pow(1 / (2 * (1 - r)), 1.0 / 16);
            const double c1 = 0.5 * ((1 + beta) * u + (1 - beta) * v), c2 = 0.5 * ((1 - beta) * u + (1 + beta) * v);
            u = std::clamp(c1, lo_[k], hi_[k]);
            v = std::clamp(c2, lo_[k], hi_[k]);
        }
    }

    // Polynomial mutation (distribution index 20).
    void mutate(Individual& x) {
        for (int k = 0; k < 2; ++k) {
            if (rng_.uniform() >= o_.mutationRate) continue;
            double& g = k ? x.Y : x.X;
            const double r = rng_.uniform(), span = hi_[k] - lo_[k];
            const double d = r < 0.5 ? std::pow(2 * r, 1.0 / 21) - 1 : 1 - std::pow(2 * (1 - r), 1.0 / 21);
            g = std::clamp(g + d * span, lo_[k], hi_[k]);
        }
    }

    const Problem& p_;
    const GeneticOptions& o_;
    const Posynomial& f_;
    std::vector<Constraint> constraints_;
    Random rng_;
    double lo_[2]{}, hi_[2]{};
    long count_ = 0;
};

}  // namespace

Solution solveGenetic(const Problem& p, const GeneticOptions& o) {
    validate(p);
    if (o.population < 4 || o.generations < 1 || o.elites < 0 || o.elites >= o.population)
        throw inputError("genetic algorithm: population must be at least 4, generations at least 1, and elites "
                         "fewer than the population");
    const Region region = Region::of(p);
    Solution s;
    s.method = "genetic algorithm (seed " + std::to_string(o.seed) + ", " + std::to_string(o.population) + " x " +
               std::to_string(o.generations) + ")";
    auto best = [&](const Posynomial& f, Goal goal, std::uint64_t stream) {
        // Each problem draws from its own seeded stream, so the three runs do not depend on each other.
        const Individual x = Search(p, o, f, o.seed * 3 + stream).run(s.evaluations);
        return describePoint(p, region, x.n, x.fz, x.objective, goal);
    };
    s.time = best(timePerPart(p), Goal::Time, 0);
    s.cost = best(costPerPart(p), Goal::Cost, 1);
    const double cMin = p.economics.weightCost > 0 ? s.cost.at.cost : 1.0;
    s.combined = best(combinedObjective(p, s.time.at.time, cMin), Goal::Combined, 2);
    return s;
}

}  // namespace aeronc::optimise
