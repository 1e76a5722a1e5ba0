// CL program -> machine motion (see Planner.h).
#include <aeronc/kinematics/Planner.h>
#include <aeronc/kinematics/RotaryChoice.h>

#include <cstdio>
#include <memory>

namespace aeronc::kinematics {

namespace {

constexpr double kSameAxis = 1e-9;  // rad: tool axes closer than this are the same axis
// Chords of one linearised arc: a full circle of 10 km radius at 0.001 mm takes about 220,000.
constexpr double kMaxArcChords = 1e6;


// Same axis (unit vectors) within kSameAxis, without the arctangent: this runs for every move.
bool sameAxis(const Vec3& a, const Vec3& b) { return a.dot(b) > 0 && a.cross(b).squaredNorm() <= kSameAxis * kSameAxis; }

std::string describe(const ClRecord& r) {
    char b[160];
    const char* what = r.kind == ClKind::Cycle ? "drilling" : r.motion == Motion::Rapid ? "G0" : r.motion == Motion::Linear ? "G1"
                                                                                       : r.motion == Motion::ArcCW ? "G2" : "G3";
    std::snprintf(b, sizeof b, "%s to (%.3f, %.3f, %.3f), tool axis (%.4f, %.4f, %.4f)", what, r.tip.x(), r.tip.y(),
                  r.tip.z(), r.axis.x(), r.axis.y(), r.axis.z());
    return b;
}

class Planner {
public:
    Planner(const ClProgram& prog, const MachineModel& machine, const PlanOptions& options)
        : prog_(prog), options_(options) {
        plan_.program = &prog;
        plan_.machine = machine;
        setup_.partZero = options.partZero;
        kin_ = std::make_unique<Kinematics>(machine, setup_);
        retract_ = options.retractDistance.value_or(machine.retractDistance);
        if (!(retract_ > 0)) throw inputError("the retract distance must be positive");
        for (const auto& a : machine.rotary) hasHead_ |= a.carrier == Carrier::Head;
    }

    Plan run() {
        markSimultaneousOperations();
        plan_.steps.reserve(prog_.records.size() + 16);
        for (size_t i = 0; i < prog_.records.size(); ++i) {
            const ClRecord& r = prog_.records[i];
            try {
                switch (r.kind) {
                    case ClKind::Move: move(static_cast<int>(i), r); break;
                    case ClKind::Cycle: cycle(static_cast<int>(i), r); break;
                    case ClKind::LoadTool:
                        if (hasHead_) {  // the head's pivots are measured from the tool tip
                            setup_.toolLength = r.tool.length;
                            kin_ = std::make_unique<Kinematics>(plan_.machine, setup_);
                        }
                        [[fallthrough]];
                    default: {
                        PlannedStep s;
                        s.record = static_cast<int>(i);
                        s.kind = r.kind;
                        plan_.steps.push_back(s);
                    }
                }
            } catch (const Error& e) {
                throw inputError(prog_.where(r) + " (" + describe(r) + "): " + e.what());
            }
        }
        return std::move(plan_);
    }

private:
    // An operation is simultaneous 5-axis when a feed move changes the tool axis.
    void markSimultaneousOperations() {
        simultaneous_.assign(prog_.operations.size() + 1, 0);
        int op = -2;
        bool have = false;
        Vec3 last = Vec3::UnitZ();
        for (const auto& r : prog_.records) {
            if (r.op != op) op = r.op, have = false;
            if (r.kind != ClKind::Move && r.kind != ClKind::Cycle) continue;
            if (r.kind == ClKind::Move && r.motion != Motion::Rapid && have && !sameAxis(r.axis, last))
                simultaneous_[r.op + 1] = 1;
            last = r.axis;
            have = true;
        }
    }

    int segmentFor(int op, SegmentMode mode, const Vec3& axis, const RotaryChoice& choice) {
        if (current_ >= 0) {
            const Segment& s = plan_.segments[current_];
            if (s.op == op && s.mode == mode && (mode == SegmentMode::Simultaneous || sameAxis(s.axis, axis)))
                return current_;
        }
        Segment s;
        s.mode = mode;
        s.op = op;
        s.axis = axis;
        s.rotary = choice.angles;
        for (const auto& other : kin_->orientations(axis, choice.angles)) {
            if (std::abs(std::remainder(other.angles[0] - choice.angles[0], 360.0)) > 1e-6 ||
                std::abs(std::remainder(other.angles[1] - choice.angles[1], 360.0)) > 1e-6)
                s.otherRotary = other.angles;
        }
        plan_.segments.push_back(s);
        current_ = static_cast<int>(plan_.segments.size()) - 1;
        return current_;
    }

    RotaryChoice choose(const Vec3& axis, bool partial) const {
        std::array<double, 2> prev = rotary_;
        if (partial) {
            // A move that gives only some coordinates is a plain 3-axis move: an axis left free
            // by the pole goes to its zero, so machine and workpiece coordinates agree.
            for (int k = 0; k < 2; ++k) {
                const auto& a = plan_.machine.rotary[k];
                if (auto z = windNearest(0.0, rotary_[k], a.min, a.max)) prev[k] = *z;
            }
        }
        return chooseRotary(*kin_, axis, prev);
    }

    void checkTravel(const PlannedStep& s) const {
        if (!plan_.machine.travel || !s.tipKnown()) return;
        const auto& t = *plan_.machine.travel;
        const char* names = "XYZ";
        // The travel is the machine's, from its table reference; the coordinates are from the
        // program zero, which sits at the part zero from there.
        const Vec3 zero = setup_.partZero ? *setup_.partZero : plan_.machine.partZero;
        for (int k = 0; k < 3; ++k) {
            const double v = s.joints.linear[k] + zero[k];
            if (v < t.min[k] - 1e-6 || v > t.max[k] + 1e-6) {
                char b[256];
                std::snprintf(b, sizeof b,
                              "%c=%.3f is beyond the travel [%.3f, %.3f] of machine %s (at %s=%.3f %s=%.3f); "
                              "move the part zero (--part-zero) or the part",
                              names[k], v, t.min[k], t.max[k], plan_.machine.name.c_str(),
                              plan_.machine.rotary[0].name.c_str(), s.joints.rotary[0],
                              plan_.machine.rotary[1].name.c_str(), s.joints.rotary[1]);
                throw inputError(b);
            }
        }
    }

    PlannedStep step(int record, ClKind kind, MoveOrigin origin, Motion motion, const Vec3& tip, const Vec3& axis,
                     const std::array<double, 2>& rotary, int segment, std::array<bool, 3> known = {true, true, true}) {
        PlannedStep s;
        s.record = record;
        s.kind = kind;
        s.origin = origin;
        s.motion = motion;
        s.pose.tip = tip;
        s.pose.axis = axis;
        s.known = known;
        s.joints.rotary = rotary;
        s.joints.linear = kin_->linearFor(tip, rotary);
        s.segment = segment;
        s.rotaryMoved = std::abs(rotary[0] - rotary_[0]) > 1e-9 || std::abs(rotary[1] - rotary_[1]) > 1e-9;
        checkTravel(s);
        return s;
    }

    // Duration of a feed move at `feed` (mm/min): the tip's path in the workpiece, or the
    // rotary motion at the machine's rotary feed, whichever is longer.
    double minutes(double length, const std::array<double, 2>& rotary, double feed) const {
        const double rot = std::max(std::abs(rotary[0] - rotary_[0]), std::abs(rotary[1] - rotary_[1]));
        return std::max(feed > 0 ? length / feed : 0.0, rot / plan_.machine.maxRotaryFeed);
    }

    void advance(const PlannedStep& s) {
        rotary_ = s.joints.rotary;
        tip_ = s.pose.tip;
        axis_ = s.pose.axis;
        known_ = s.known;
        plan_.steps.push_back(s);
    }

    bool tipKnown() const { return known_[0] && known_[1] && known_[2]; }

    void move(int index, const ClRecord& r) {
        const bool partial = !r.tipKnown();
        const RotaryChoice choice = choose(r.axis, partial);
        const SegmentMode mode = simultaneous_[r.op + 1] ? SegmentMode::Simultaneous : SegmentMode::Plane;
        const int seg = segmentFor(r.op, mode, r.axis, choice);

        if (choice.branchChange && r.motion == Motion::Linear && tipKnown() && !partial) {
            // The limits break continuity in the cut: leave along the tool axis, swing to the
            // other solution clear of the part, and come back in along the new axis.
            ++plan_.branchChanges;
            advance(step(index, ClKind::Move, MoveOrigin::Retract, Motion::Rapid, tip_ + retract_ * axis_, axis_, rotary_, seg));
            advance(step(index, ClKind::Move, MoveOrigin::Reposition, Motion::Rapid, r.tip + retract_ * r.axis, r.axis,
                         choice.angles, seg));
            PlannedStep in = step(index, ClKind::Move, MoveOrigin::ReEnter, Motion::Linear, r.tip, r.axis, choice.angles, seg);
            in.feed = r.feed;
            in.minutes = minutes(retract_, choice.angles, r.feed);
            advance(in);
            return;
        }

        const bool arc = r.motion == Motion::ArcCW || r.motion == Motion::ArcCCW;
        if (arc && mode == SegmentMode::Simultaneous && options_.linearizeSimultaneousArcs) {
            linearizeArc(index, r, choice.angles, seg);
            return;
        }
        PlannedStep s = step(index, ClKind::Move, MoveOrigin::Input, r.motion, r.tip, r.axis, choice.angles, seg, r.known);
        s.centre = r.centre;
        if (r.motion != Motion::Rapid) {
            s.feed = r.feed;
            const double length = arc ? arcLength(r) : (tipKnown() ? (r.tip - tip_).norm() : 0.0);
            s.minutes = minutes(length, choice.angles, r.feed);
        }
        advance(s);
    }

    // Signed sweep (rad) about the tool axis from the current tip to r.tip, counter-clockwise positive.
    double sweep(const ClRecord& r) const {
        const Vec3& u = r.axis;
        Vec3 a = tip_ - r.centre, b = r.tip - r.centre;
        a -= u * a.dot(u), b -= u * b.dot(u);
        double t = std::atan2(u.dot(a.cross(b)), a.dot(b));
        if (r.motion == Motion::ArcCCW && t <= 1e-12) t += 2 * kPi;
        if (r.motion == Motion::ArcCW && t >= -1e-12) t -= 2 * kPi;
        return t;
    }

    double arcLength(const ClRecord& r) const {
        Vec3 a = tip_ - r.centre;
        a -= r.axis * a.dot(r.axis);
        const double planar = a.norm() * std::abs(sweep(r));
        const double rise = (r.tip - tip_).dot(r.axis);
        return std::hypot(planar, rise);
    }

    void linearizeArc(int index, const ClRecord& r, const std::array<double, 2>& rotary, int seg) {
        const double t = sweep(r);
        Vec3 a = tip_ - r.centre;
        const double h0 = a.dot(r.axis);
        a -= r.axis * h0;
        const double radius = a.norm();
        const double rise = (r.tip - tip_).dot(r.axis);
        const double tol = std::min(options_.chordTolerance, radius);
        const double maxStep = 2 * std::acos(1 - tol / radius);
        // An absurd radius (1e110 mm) makes the step 0 and the count infinite; an int cannot hold it.
        const double chords = std::ceil(std::abs(t) / maxStep - 1e-9);
        if (!(chords <= kMaxArcChords)) {
            char b[200];
            std::snprintf(b, sizeof b, "the arc (radius %g mm, %g degrees) needs more than %g chords within the chord "
                          "tolerance %g mm", radius, std::abs(t) * 180 / kPi, kMaxArcChords, options_.chordTolerance);
            throw inputError(b);
        }
        const int n = std::max(1, static_cast<int>(chords));
        const double length = std::hypot(radius * std::abs(t), rise) / n;
        for (int k = 1; k <= n; ++k) {
            const double f = static_cast<double>(k) / n;
            const Vec3 p = k == n ? r.tip
                                  : Vec3(r.centre + Eigen::AngleAxisd(t * f, r.axis) * a + r.axis * (h0 + rise * f));
            PlannedStep s = step(index, ClKind::Move, k == n ? MoveOrigin::Input : MoveOrigin::ArcPoint, Motion::Linear, p,
                                 r.axis, rotary, seg);
            s.feed = r.feed;
            s.minutes = minutes(length, rotary, r.feed);
            advance(s);
        }
    }

    void cycle(int index, const ClRecord& r) {
        const RotaryChoice choice = choose(r.axis, false);
        const int seg = segmentFor(r.op, SegmentMode::Plane, r.axis, choice);
        const Vec3 approach = r.tip + r.clearance * r.axis;
        if (!tipKnown() || (tip_ - approach).norm() > 1e-6 || !sameAxis(axis_, r.axis))
            advance(step(index, ClKind::Move, MoveOrigin::CycleApproach, Motion::Rapid, approach, r.axis, choice.angles, seg));
        PlannedStep s = step(index, ClKind::Cycle, MoveOrigin::Input, Motion::Linear, r.tip, r.axis, choice.angles, seg);
        s.feed = r.feed;
        checkTravel(s);
        plan_.steps.push_back(s);
        // The tool ends the cycle back at the approach point.
        tip_ = approach;
        axis_ = r.axis;
        known_ = {true, true, true};
    }

    const ClProgram& prog_;
    PlanOptions options_;
    Plan plan_;
    MachineSetup setup_;
    std::unique_ptr<Kinematics> kin_;
    double retract_ = 50.0;
    bool hasHead_ = false;
    std::vector<char> simultaneous_;
    int current_ = -1;
    std::array<double, 2> rotary_{0.0, 0.0};
    Vec3 tip_ = Vec3::Zero();
    Vec3 axis_ = Vec3::UnitZ();
    std::array<bool, 3> known_{false, false, false};
};

}  // namespace

Plan planProgram(const ClProgram& program, const MachineModel& machine, const PlanOptions& options) {
    return Planner(program, machine, options).run();
}

}  // namespace aeronc::kinematics
