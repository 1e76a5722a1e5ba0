#pragma once
// The optimiser's constraints. Each one is a monomial in (n, f_z),
//     value = coefficient * n^nExp * f_z^fzExp   compared with a limit,
// so in the log variables X = ln n, Y = ln f_z every constraint is a half-plane and the feasible
// set is a convex polygon (or, for a stepped gearbox, a set of segments at the step speeds).
// Region computes on that exactly: emptiness, corners, the feasible f_z at one speed, and the
// least relaxation of one limit that makes an empty region non-empty.
#include <aeronc/optimise/Problem.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace aeronc::optimise {

enum class ConstraintKind { Force, Power, Feed, Roughness, SpindleMax, SpindleMin, FeedPerToothMax, FeedPerToothMin };

struct Constraint {
    ConstraintKind kind;
    std::string name;    // "cutting power"
    std::string symbol;  // "P_max": the limit's name
    std::string unit;    // "kW"
    double coefficient = 1, nExp = 0, fzExp = 0;
    double limit = 0;
    bool upper = true;  // value <= limit; false: value >= limit

    double value(double n, double fz) const;
    // value/limit for an upper limit, limit/value for a lower one: at most 1 when met.
    double utilisation(double n, double fz) const;
};

// Force, power, feed, roughness, the spindle range and the f_z search range, in that order.
std::vector<Constraint> constraintsOf(const Problem& p);

// A constraint counts as met when its utilisation is at most 1 + kFeasibilityTolerance, and
// as active at a point when its utilisation is at least 1 - kActiveTolerance.
constexpr double kFeasibilityTolerance = 1e-9;
constexpr double kActiveTolerance = 1e-6;

struct RegionPoint {
    double n = 0, fz = 0;
};

class Region {
public:
    // spindleSteps empty: n is continuous (bounded by the SpindleMin/Max constraints).
    Region(std::vector<Constraint> constraints, std::vector<double> spindleSteps);
    static Region of(const Problem& p);

    const std::vector<Constraint>& constraints() const { return constraints_; }
    bool stepped() const { return !steps_.empty(); }
    const std::vector<double>& steps() const { return steps_; }

    // The same region with constraint `index` left out.
    Region without(std::size_t index) const;

    bool contains(double n, double fz) const;
    bool empty() const { return !minimum(0, 0).has_value(); }
    // Where n^a*f_z^b is least over the region; nullopt when the region is empty.
    std::optional<RegionPoint> minimum(double a, double b) const;
    // Corners of the polygon (stepless) or ends of the segments (stepped).
    std::vector<RegionPoint> corners() const;
    // The feasible f_z at speed n as [low, high]; nullopt when none.
    std::optional<std::array<double, 2>> feedPerToothRange(double n) const;
    // The feasible n at feed f_z, ignoring steps; nullopt when none.
    std::optional<std::array<double, 2>> speedRange(double fz) const;

private:
    struct HalfPlane {
        double a, b, c;  // a*X + b*Y <= c
    };
    std::vector<Constraint> constraints_;
    std::vector<double> steps_;
    std::vector<HalfPlane> planes_;
    std::optional<std::array<double, 2>> yRange(double X) const;
};

// The least change of one limit that alone makes an empty region non-empty.
struct Relaxation {
    Constraint constraint;
    double neededLimit = 0;  // the limit that would just admit a point
    RegionPoint at;          // the point it would admit
    double change() const;   // neededLimit/limit - 1
};

// Every single limit whose relaxation alone restores feasibility, least relative change first.
std::vector<Relaxation> singleRelaxations(const Region& region);

// A message for an empty region: which limits conflict and the nearest relaxations.
std::string infeasibilityMessage(const Region& region);

}  // namespace aeronc::optimise
