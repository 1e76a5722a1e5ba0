#include <aeronc/optimise/Constraints.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace aeronc::optimise {

double Constraint::value(double n, double fz) const {
    return coefficient * std::pow(n, nExp) * std::pow(fz, fzExp);
}

double Constraint::utilisation(double n, double fz) const {
    const double v = value(n, fz);
    return upper ? v / limit : limit / v;
}

std::vector<Constraint> constraintsOf(const Problem& p) {
    const auto& k = p.force;
    const double d = p.cutter.diameter;
    const double forceK = 9.81 * k.cF * std::pow(p.cut.depth, k.xF) * std::pow(p.cut.width, k.uF) * p.cutter.teeth /
                          std::pow(d, k.qF) * k.kFc;
    using K = ConstraintKind;
    std::vector<Constraint> c;
    c.push_back({K::Force, "cutting force", "[F]", "N", forceK, -k.wF, k.yF, p.machine.maxForce, true});
    // P = F_c*v_c/(60000*eta) with v_c = pi*d*n/1000.
    c.push_back({K::Power, "cutting power", "P_max", "kW", forceK * M_PI * d / (1000.0 * 60000.0 * p.machine.efficiency),
                 1.0 - k.wF, k.yF, p.machine.power, true});
    c.push_back({K::Feed, "feed rate", "v_f,max", "mm/min", double(p.cutter.teeth), 1, 1, p.machine.maxFeed, true});
    c.push_back({K::Roughness, "roughness R_a", "R_a,max", "um", p.quality.raCoefficient / p.cutter.cornerRadius, 0, 2,
                 p.quality.raMax, true});
    c.push_back({K::SpindleMax, "spindle speed", "n_max", "r/min", 1, 1, 0, p.machine.maxSpindle, true});
    c.push_back({K::SpindleMin, "spindle speed", "n_min", "r/min", 1, 1, 0, p.machine.minSpindle, false});
    // The tool's chip load, when it has one below the search box, is the upper f_z limit.
    if (p.cutter.maxChipLoad > 0 && p.cutter.maxChipLoad < p.feedPerTooth.max)
        c.push_back({K::FeedPerToothMax, "chip load (tool)", "f_z,max", "mm", 1, 0, 1, p.cutter.maxChipLoad, true});
    else
        c.push_back({K::FeedPerToothMax, "feed per tooth (search range)", "f_z,max", "mm", 1, 0, 1, p.feedPerTooth.max,
                     true});
    c.push_back({K::FeedPerToothMin, "feed per tooth (search range)", "f_z,min", "mm", 1, 0, 1, p.feedPerTooth.min, false});
    return c;
}

Region::Region(std::vector<Constraint> constraints, std::vector<double> spindleSteps)
    : constraints_(std::move(constraints)), steps_(std::move(spindleSteps)) {
    for (const auto& c : constraints_) {
        const double lk = std::log(c.coefficient), ll = std::log(c.limit);
        if (c.upper) planes_.push_back({c.nExp, c.fzExp, ll - lk});
        else planes_.push_back({-c.nExp, -c.fzExp, lk - ll});
    }
}

Region Region::of(const Problem& p) { return Region(constraintsOf(p), p.machine.spindleSteps); }

Region Region::without(std::size_t index) const {
    auto c = constraints_;
    c.erase(c.begin() + long(index));
    return Region(std::move(c), steps_);
}

bool Region::contains(double n, double fz) const {
    if (!(n > 0 && fz > 0)) return false;
    if (stepped() && std::none_of(steps_.begin(), steps_.end(),
                                  [n](double s) { return std::abs(s - n) <= 1e-12 * s; }))
        return false;
    const double X = std::log(n), Y = std::log(fz);
    for (const auto& h : planes_)
        if (!(h.a * X + h.b * Y <= h.c + kFeasibilityTolerance)) return false;  // NaN: not contained
    return true;
}

std::optional<std::array<double, 2>> Region::yRange(double X) const {
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    for (const auto& h : planes_) {
        if (std::abs(h.b) < 1e-15) {
            if (h.a * X > h.c + kFeasibilityTolerance) return std::nullopt;
        } else if (h.b > 0) {
            hi = std::min(hi, (h.c - h.a * X) / h.b);
        } else {
            lo = std::max(lo, (h.c - h.a * X) / h.b);
        }
    }
    if (lo > hi + kFeasibilityTolerance) return std::nullopt;
    if (lo > hi) lo = hi = 0.5 * (lo + hi);  // touching within tolerance
    return std::array<double, 2>{lo, hi};
}

std::optional<std::array<double, 2>> Region::feedPerToothRange(double n) const {
    const auto r = yRange(std::log(n));
    if (!r) return std::nullopt;
    return std::array<double, 2>{std::exp((*r)[0]), std::exp((*r)[1])};
}

std::optional<std::array<double, 2>> Region::speedRange(double fz) const {
    const double Y = std::log(fz);
    double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
    for (const auto& h : planes_) {
        if (std::abs(h.a) < 1e-15) {
            if (h.b * Y > h.c + kFeasibilityTolerance) return std::nullopt;
        } else if (h.a > 0) {
            hi = std::min(hi, (h.c - h.b * Y) / h.a);
        } else {
            lo = std::max(lo, (h.c - h.b * Y) / h.a);
        }
    }
    if (lo > hi + kFeasibilityTolerance) return std::nullopt;
    if (lo > hi) lo = hi = 0.5 * (lo + hi);
    return std::array<double, 2>{std::exp(lo), std::exp(hi)};
}

std::vector<RegionPoint> Region::corners() const {
    std::vector<RegionPoint> out;
    if (stepped()) {
        for (double s : steps_) {
            const auto r = yRange(std::log(s));
            if (!r) continue;
            for (double y : *r)
                if (std::isfinite(y)) out.push_back({s, std::exp(y)});
        }
        return out;
    }
    for (std::size_t i = 0; i < planes_.size(); ++i)
        for (std::size_t j = i + 1; j < planes_.size(); ++j) {
            const auto &p = planes_[i], &q = planes_[j];
            const double det = p.a * q.b - q.a * p.b;
            if (std::abs(det) < 1e-12) continue;  // parallel
            const double X = (p.c * q.b - q.c * p.b) / det, Y = (p.a * q.c - q.a * p.c) / det;
            bool inside = true;
            for (const auto& h : planes_)
                if (h.a * X + h.b * Y > h.c + kFeasibilityTolerance) {
                    inside = false;
                    break;
                }
            if (inside) out.push_back({std::exp(X), std::exp(Y)});
        }
    return out;
}

// A linear function over a polygon is least at a corner; over segments, at an end. Only used
// where the minimum is bounded: the region keeps a bound opposite to the direction minimised.
std::optional<RegionPoint> Region::minimum(double a, double b) const {
    std::optional<RegionPoint> best;
    double bestValue = std::numeric_limits<double>::infinity();
    for (const auto& p : corners()) {
        const double v = a * std::log(p.n) + b * std::log(p.fz);
        if (v < bestValue) bestValue = v, best = p;
    }
    return best;
}

double Relaxation::change() const { return neededLimit / constraint.limit - 1.0; }

std::vector<Relaxation> singleRelaxations(const Region& region) {
    std::vector<Relaxation> out;
    const auto& cs = region.constraints();
    for (std::size_t i = 0; i < cs.size(); ++i) {
        const Region rest = region.without(i);
        const Constraint& c = cs[i];
        // An upper limit must rise to the least value the rest admits, a lower one fall to the most.
        const auto at = c.upper ? rest.minimum(c.nExp, c.fzExp) : rest.minimum(-c.nExp, -c.fzExp);
        if (!at) continue;
        out.push_back({c, c.value(at->n, at->fz), *at});
    }
    std::sort(out.begin(), out.end(), [](const Relaxation& x, const Relaxation& y) {
        return std::abs(std::log1p(x.change())) < std::abs(std::log1p(y.change()));
    });
    return out;
}

namespace {
std::string num(double v) {
    std::ostringstream s;
    s << std::setprecision(4) << v;
    return s.str();
}
std::string describe(const Constraint& c) {
    return c.name + " " + c.symbol + " = " + num(c.limit) + " " + c.unit;
}
}  // namespace

std::string infeasibilityMessage(const Region& region) {
    std::ostringstream m;
    m << "infeasible: no spindle speed n and feed per tooth f_z meet every limit";
    if (region.stepped()) m << " at the machine's " << region.steps().size() << " spindle steps";
    const auto rel = singleRelaxations(region);
    if (!rel.empty()) {
        m << ". Limits in conflict: ";
        for (std::size_t i = 0; i < rel.size(); ++i) m << (i ? ", " : "") << describe(rel[i].constraint);
        m << ". Nearest relaxation: ";
        for (std::size_t i = 0; i < rel.size(); ++i) {
            const auto& r = rel[i];
            if (i == 1) m << "; or, each alone: ";
            else if (i > 1) m << "; ";
            m << (r.constraint.upper ? "raise " : "lower ") << r.constraint.symbol << " from " << num(r.constraint.limit)
              << " to " << num(r.neededLimit) << " " << r.constraint.unit << " (" << (r.change() >= 0 ? "+" : "")
              << num(100 * r.change()) << " %), which admits n = " << num(r.at.n) << " r/min, f_z = " << num(r.at.fz)
              << " mm";
        }
        return m.str();
    }
    // No single limit is to blame: name the pairs whose joint relaxation would do.
    const auto& cs = region.constraints();
    std::vector<std::string> pairs;
    for (std::size_t i = 0; i < cs.size(); ++i)
        for (std::size_t j = i + 1; j < cs.size(); ++j)
            if (!region.without(j).without(i).empty())
                pairs.push_back(cs[i].symbol + " (" + cs[i].name + ") with " + cs[j].symbol + " (" + cs[j].name + ")");
    if (pairs.empty()) {
        m << "; no one or two limits can be relaxed to change that";
    } else {
        m << "; no single limit can be relaxed to change that; relaxing both of ";
        for (std::size_t i = 0; i < pairs.size(); ++i) m << (i ? ", or " : "") << pairs[i];
        m << " would";
    }
    return m.str();
}

}  // namespace aeronc::optimise
