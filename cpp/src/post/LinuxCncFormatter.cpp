// LinuxCNC dialect (see NcFormat.h): the post does the kinematics, LinuxCNC runs trivkins.
// X Y Z are the machine coordinates of the tool tip (G43 compensates the length along the
// fixed spindle), A and C the table angles. On a table-table machine the tool axis is the
// machine's Z, so arcs at a constant orientation are G17 arcs in machine coordinates and
// drilling cycles drill along machine Z. A head-head machine (a gantry's fork head) is posted
// only with its spindle along machine Z (3-axis planes, the head unswivelled): LinuxCNC's G43
// compensates the tool length along machine Z, which a swivelled head's tool is not.
#include "NcFormatter.h"

#include <cmath>
#include <cstdio>

namespace aeronc::post {

using namespace kinematics;

namespace {

class LinuxCncFormatter : public NcFormatter {
public:
    LinuxCncFormatter(const Plan& plan, const NcOptions& o) : NcFormatter(plan, o, false, "G4 P") {
        int head = 0;
        for (const auto& a : m_.rotary) {
            if (a.carrier == Carrier::Head) ++head;
            if (a.name != "A" && a.name != "B" && a.name != "C")
                throw inputError("LinuxCNC names rotary axes A, B or C, not " + a.name);
        }
        if (head == 1)
            throw inputError("the LinuxCNC dialect is for table-table or head-head machines; machine " + m_.name +
                             " has one rotary axis in the head and one in the table");
        head_ = head == 2;
        if ((m_.toolDirection - Vec3::UnitZ()).norm() > 1e-12)
            throw inputError("the LinuxCNC dialect needs the tool along machine +Z");
    }

private:
    void header() override {
        if (o_.comments) {
            w_.comment(postedBy(o_.programName, "LinuxCNC trivkins"));
            w_.comment("machine coordinates of the tool tip in mm, rotary axes in degrees");
        }
        w_.line("G17 G21 G90 G40 G49 G80 G94");
    }

    void footer() override {
        endCycles();
        if (inverse_) w_.line("G94");
        stopSpindleAndCoolant();
        w_.line("G49");
        w_.line("M2");
    }

    void endCycles() {
        if (!cycles_) return;
        w_.line("G80");
        cycles_ = false;
        g_.forget();
    }

    void beforeStep(const PlannedStep& s) override {
        if (s.kind != ClKind::Cycle) endCycles();
    }

    void operation(const ClRecord& r) override {
        NcFormatter::operation(r);
        forgetModal();
    }

    void workOffset(const ClRecord& r) override {
        static const char* allowed[] = {"G54", "G55", "G56", "G57", "G58", "G59", "G59.1", "G59.2", "G59.3"};
        bool ok = false;
        for (auto* a : allowed) ok |= r.text == a;
        if (!ok) throw inputError("work offset " + r.text + " is not one of LinuxCNC's G54 to G59.3");
        w_.line(r.text);
        forgetModal();
    }

    void loadTool(const ClRecord& r) override {
        if (o_.comments) w_.comment("tool: " + r.tool.name);
        w_.line("T" + std::to_string(r.tool.number) + " M6");
        w_.line("G43 H" + std::to_string(r.tool.number));
        forgetModal();
    }

    bool atZero(const std::array<double, 2>& r) const {
        return std::abs(std::remainder(r[0], 360.0)) < 1e-9 && std::abs(std::remainder(r[1], 360.0)) < 1e-9;
    }

    // Feed of a move: inverse time (G93, F = 1/minutes) when it turns a rotary axis and the
    // option is on; else units per minute, scaled so that the machine takes the time the
    // tip needs at the programmed feed along the part (LinuxCNC's F applies to XYZ, or to
    // the rotary axes when only they move).
    void feedWord(const PlannedStep& s) {
        if (s.motion == Motion::Rapid) return;
        if (inverse_) {
            checkValue("inverse-time feed", 1.0 / s.minutes, "1/min", 4, true);
            w_.value("F", 1.0 / s.minutes, 4);
        } else if (s.rotaryMoved && s.minutes > 0) {
            // LinuxCNC times the move by the XYZ words it reads (rounded as written), or by the
            // rotary words when no linear word changes.
            const double lin = std::pow(10.0, o_.precision), ang = std::pow(10.0, o_.anglePrecision);
            double xyz = 0, rot = 0;
            for (int k = 0; k < 3; ++k) {
                const double d = (std::round(s.joints.linear[k] * lin) - std::round(lastLinear_[k] * lin)) / lin;
                xyz += d * d;
            }
            for (int k = 0; k < 2; ++k)
                rot = std::max(rot, std::abs(std::round(s.joints.rotary[k] * ang) - std::round(lastRotary_[k] * ang)) / ang);
            xyz = std::sqrt(xyz);
            const double f = (xyz > 0 ? xyz : rot) / s.minutes;
            if (f > 0) {
                checkValue("feed", f, "mm/min", 3, true);
                w_.value("F", f, 3);
                f_.forget();
            } else {
                w_.modal("F", s.feed, 3, f_);
            }
        } else {
            w_.modal("F", s.feed, 3, f_);
        }
    }

    void axes(const PlannedStep& s) {
        const int p = o_.precision;
        if (s.known[0]) w_.modal("X", s.joints.linear.x(), p, x_);
        if (s.known[1]) w_.modal("Y", s.joints.linear.y(), p, y_);
        if (s.known[2]) w_.modal("Z", s.joints.linear.z(), p, z_);
        for (int k = 0; k < 2; ++k) w_.modal(m_.rotary[k].name, s.joints.rotary[k], o_.anglePrecision, a_[k]);
    }

    // The tool axis in the machine: the head's rotation of the tool direction (the table's of
    // machine Z leaves the spindle along Z).
    void checkSpindleAlongZ(const PlannedStep& s) const {
        if (!head_) return;
        const Vec3 axis = tableRotation(s.joints.rotary) * m_.toolDirection;
        if ((axis - Vec3::UnitZ()).norm() > 1e-9) {
            char b[200];
            std::snprintf(b, sizeof b,
                          "the LinuxCNC dialect posts head machine %s only with the spindle along machine Z "
                          "(3-axis planes); this move swivels the head to %s=%.3f %s=%.3f: post it with the 840D post",
                          m_.name.c_str(), m_.rotary[0].name.c_str(), s.joints.rotary[0], m_.rotary[1].name.c_str(),
                          s.joints.rotary[1]);
            throw inputError(b);
        }
    }

    void move(const PlannedStep& s) override {
        checkSpindleAlongZ(s);
        if (!s.tipKnown() && !atZero(s.joints.rotary))
            throw inputError("a move that gives only some of X, Y, Z needs the rotary axes at zero; give the full tip position");
        const bool arc = s.motion == Motion::ArcCW || s.motion == Motion::ArcCCW;
        feedMode(s);
        motionWord(s.motion);
        axes(s);
        if (arc) {
            // The arc keeps its orientation: its centre turns with the table like the tip, and
            // its plane is normal to machine Z.
            const ClRecord& r = plan_.program->records[s.record];
            // A head machine's workpiece stands still: the centre is where the part has it.
            const Vec3 centre = s.joints.linear + (head_ ? Mat3::Identity() : tableRotation(s.joints.rotary)) *
                                                      (r.centre - s.pose.tip);
            w_.value("I", centre.x() - lastLinear_.x(), o_.precision);
            w_.value("J", centre.y() - lastLinear_.y(), o_.precision);
        }
        feedWord(s);
        w_.end();
        lastLinear_ = s.joints.linear;
        lastRotary_ = s.joints.rotary;
    }

    Mat3 tableRotation(const std::array<double, 2>& rotary) const {
        Mat3 rot = Mat3::Identity();
        for (int i = 0; i < 2; ++i)
            rot = rot * Eigen::AngleAxisd(toRadians(rotary[i]), m_.rotary[i].direction).toRotationMatrix();
        return rot;
    }

    void cycle(const PlannedStep& s, const ClRecord& r) override {
        // The planner put the tool on the hole axis at the return level; the cycle drills along
        // machine Z from there.
        checkSpindleAlongZ(s);
        const bool toInitial = r.clearance > r.retract + 1e-9;
        unitsPerMinute();
        std::string g = toInitial ? "G98 " : "G99 ";
        g += r.cycle == CycleKind::Drill ? "G81" : r.cycle == CycleKind::DrillDwell ? "G82" : r.cycle == CycleKind::Peck ? "G83" : "G73";
        w_.word(g);
        g_.forget();
        const Vec3 bottom = s.joints.linear;
        w_.value("X", bottom.x(), o_.precision);
        w_.value("Y", bottom.y(), o_.precision);
        w_.value("Z", bottom.z(), o_.precision);
        w_.value("R", bottom.z() + r.retract, o_.precision);
        if (r.cycle == CycleKind::Peck || r.cycle == CycleKind::ChipBreak) w_.value("Q", r.peck, o_.precision);
        if (r.cycle == CycleKind::DrillDwell || (r.seconds > 0 && r.cycle == CycleKind::Peck)) w_.value("P", r.seconds, 3);
        f_.forget();
        w_.modal("F", r.feed, 3, f_);
        w_.end();
        cycles_ = true;
        // Afterwards the tool is above the hole at the return level.
        const Vec3 after = bottom + Vec3::UnitZ() * r.clearance;
        x_.forget(), y_.forget(), z_.forget();
        lastLinear_ = after;
        lastRotary_ = s.joints.rotary;
    }

    bool cycles_ = false;
    bool head_ = false;  // both rotary axes in the head
    Vec3 lastLinear_ = Vec3::Zero();
    std::array<double, 2> lastRotary_{0.0, 0.0};
};

}  // namespace

std::string formatLinuxCnc(const Plan& plan, const NcOptions& o) { return LinuxCncFormatter(plan, o).run(); }

}  // namespace aeronc::post
