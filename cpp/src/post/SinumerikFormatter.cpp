// Sinumerik 840D dialect (see NcFormat.h).
//
// 3+2 segments swivel the working plane with CYCLE800, axis by axis (_MODE 57: about X, then
// the new Y, then the new Z): the plane's Z is the tool axis, written as a rotation a about
// X and b about the new Y (c = 0), and every point is written in that plane's coordinates.
// _DIR picks the solution with the higher (+1) or lower (-1) value of the machine's
// direction-reference axis. Simultaneous segments run under TRAORI: X Y Z are the tool tip in
// the workpiece frame, orientation is machine A/C words or A3= B3= C3=.
#include "NcFormatter.h"

#include <map>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace aeronc::post {

using namespace kinematics;

namespace {

struct Frame {
    Mat3 r = Mat3::Identity();    // plane -> workpiece
    Vec3 origin = Vec3::Zero();  // the plane's zero in the workpiece (CYCLE800 _X0 _Y0 _Z0)
    double a = 0, b = 0;          // degrees: about X, then about the new Y
    bool identity = true;
    Vec3 local(const Vec3& p) const { return r.transpose() * (p - origin); }
};

Frame frameFor(const Vec3& u) {
    Frame f;
    const double b = std::asin(std::clamp(u.x(), -1.0, 1.0));
    const double a = std::atan2(-u.y(), u.z());
    f.r = Eigen::AngleAxisd(a, Vec3::UnitX()).toRotationMatrix() * Eigen::AngleAxisd(b, Vec3::UnitY()).toRotationMatrix();
    f.a = toDegrees(a);
    f.b = toDegrees(b);
    f.identity = std::abs(a) < 1e-12 && std::abs(b) < 1e-12;
    return f;
}

std::string programName(const std::string& name) {
    std::string s;
    for (char c : name) s += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(c)) : '_';
    if (s.size() < 2 || !std::isalpha(static_cast<unsigned char>(s[0])) || !(std::isalpha(static_cast<unsigned char>(s[1])) || s[1] == '_'))
        s = "AERONC_" + s;  // the first two characters must be letters
    if (s.size() > 24) s.resize(24);
    return s;
}

class SinumerikFormatter : public NcFormatter {
public:
    SinumerikFormatter(const Plan& plan, const NcOptions& o) : NcFormatter(plan, o, true, "G4 F") {
        // CYCLE832 smooths milling: segments with feed moves and no drilling cycle.
        milling_.assign(plan.segments.size(), 0);
        std::vector<char> drilling(plan.segments.size(), 0);
        for (const auto& s : plan.steps) {
            if (s.kind == ClKind::Cycle) drilling[s.segment] = 1;
            if (s.kind == ClKind::Move && s.motion != Motion::Rapid) milling_[s.segment] = 1;
        }
        for (size_t i = 0; i < milling_.size(); ++i) milling_[i] &= !drilling[i];
        if (o.smoothing == "finish") smoothing_ = "_FINISH";
        else if (o.smoothing == "semifinish") smoothing_ = "_SEMIFIN";
        else if (o.smoothing == "rough") smoothing_ = "_ROUGH";
        else if (o.smoothing != "off") throw inputError("unknown smoothing '" + o.smoothing + "' (finish, semifinish, rough, off)");
        if (!smoothing_.empty() && !(o.smoothingTolerance > 0 && o.smoothingTolerance < 1000))
            throw inputError("the smoothing tolerance must be a positive number of mm below 1000");
    }

private:
    void header() override {
        const std::string name = programName(o_.programName);
        w_.raw("%_N_" + name + "_MPF");
        w_.raw(";$PATH=/_N_MPF_DIR");
        if (o_.comments) {
            w_.comment(postedBy(name, m_.controller.empty() ? "Sinumerik 840D" : m_.controller));
            w_.comment("lengths in mm, angles in degrees; 3+2 planes by CYCLE800, simultaneous 5-axis under TRAORI");
            // The tool list an operator loads the magazine from: each tool once, by number.
            std::map<int, const kinematics::ClRecord*> tools;
            for (const auto& r : prog_.records)
                if (r.kind == ClKind::LoadTool) tools.emplace(r.tool.number, &r);
            for (const auto& [number, r] : tools) {
                char b[64];
                std::snprintf(b, sizeof b, "  diameter %.3f", r->tool.diameter);
                w_.comment("T" + std::to_string(number) + " " + r->tool.name + (r->tool.diameter > 0 ? b : ""));
            }
        }
        w_.line("G17 G90 G71 G94 G40");
        w_.line("TRAFOOF");
        w_.line("CYCLE800()");
        swivelled_ = false;
    }

    // Resets the swivelled plane, when one is active.
    void resetPlane() {
        if (swivelled_) w_.line("CYCLE800()");
        swivelled_ = false;
    }

    void footer() override {
        leaveSegment();
        if (smoothingOn_) w_.line("CYCLE832(0,_OFF,1)");
        stopSpindleAndCoolant();
        resetPlane();
        w_.line("M30");
    }

    void forgetPosition() {
        forgetModal();
        for (auto& v : v_) v.forget();
    }

    void leaveSegment() {
        if (traori_) w_.line("TRAFOOF");
        traori_ = false;
        active_ = -1;
        forgetPosition();
    }

    void setSmoothing(bool on) {
        if (smoothing_.empty() || on == smoothingOn_) return;
        char b[96];
        if (on)
            std::snprintf(b, sizeof b, "CYCLE832(%g,%s,1)", o_.smoothingTolerance, smoothing_.c_str());
        else
            std::snprintf(b, sizeof b, "CYCLE832(0,_OFF,1)");
        w_.line(b);
        smoothingOn_ = on;
    }

    // The value a length has once written with the program's precision.
    double written(double v) const {
        std::string t;
        appendNumber(t, v, o_.precision);
        return std::strtod(t.c_str(), nullptr);
    }

    void enterSegment(int index, const PlannedStep& first) {
        const Segment& seg = plan_.segments[index];
        leaveSegment();
        active_ = index;
        if (seg.mode == SegmentMode::Plane) {
            frame_ = frameFor(seg.axis);
            // A tilted plane turns about its first point, so that the coordinates in it stay
            // local and small; the 3-axis plane keeps the workpiece zero.
            if (!frame_.identity)
                frame_.origin = Vec3(written(first.pose.tip.x()), written(first.pose.tip.y()), written(first.pose.tip.z()));
            int dir = 1;
            const int ref = m_.directionReference;
            if (seg.otherRotary && seg.rotary[ref] < (*seg.otherRotary)[ref]) dir = -1;
            if (o_.comments) {
                if (frame_.identity) {
                    w_.comment("3-axis plane");
                } else {
                    std::string c = "3+2 plane, tool axis ";
                    for (int k = 0; k < 3; ++k) appendNumber(c += k ? "," : "(", seg.axis[k], 4);
                    c += ") = ";
                    for (int k = 0; k < 2; ++k)
                        appendNumber(c += (k ? " " : "") + m_.rotary[k].name, seg.rotary[k], o_.anglePrecision);
                    w_.comment(c);
                }
            }
            std::string call = "CYCLE800(1,\"" + m_.swivelDataRecord + "\",0,57,";
            for (int k = 0; k < 3; ++k) appendNumber(call, frame_.origin[k], o_.precision), call += ',';
            appendNumber(call, frame_.a, o_.anglePrecision);
            call += ',';
            appendNumber(call, frame_.b, o_.anglePrecision);
            call += ",0,0,0,0,";
            call += dir > 0 ? "1" : "-1";
            call += ",100,1)";
            w_.line(call);
            swivelled_ = true;
            setSmoothing(milling_[index]);
        } else {
            if (o_.comments) w_.comment("simultaneous 5-axis: tool tip in the workpiece frame under TRAORI");
            resetPlane();
            w_.line("TRAORI");
            traori_ = true;
            setSmoothing(milling_[index]);
        }
    }

    void feedWord(const PlannedStep& s) {
        if (s.motion == Motion::Rapid) return;
        if (inverse_) {
            checkValue("inverse-time feed", 1.0 / s.minutes, "1/min", 4, true);
            w_.value("F", 1.0 / s.minutes, 4);
        } else {
            checkFeed(s.feed, std::min(o_.precision, 3));
            w_.modal("F", s.feed, std::min(o_.precision, 3), f_);
        }
    }

    void xyz(const Vec3& p, const std::array<bool, 3>& known) {
        if (known[0]) w_.modal("X", p.x(), o_.precision, x_);
        if (known[1]) w_.modal("Y", p.y(), o_.precision, y_);
        if (known[2]) w_.modal("Z", p.z(), o_.precision, z_);
    }

    void workOffset(const ClRecord& r) override {
        static const char* allowed[] = {"G54", "G55", "G56", "G57"};
        bool ok = false;
        for (auto* a : allowed) ok |= r.text == a;
        if (!ok) throw inputError("work offset " + r.text + " has another meaning on a Sinumerik; use G54 to G57");
        leaveSegment();
        w_.line(r.text);
    }

    void loadTool(const ClRecord& r) override {
        leaveSegment();
        if (!smoothing_.empty() && smoothingOn_) setSmoothing(false);
        resetPlane();  // no tool change in a swivelled plane
        if (o_.comments) w_.comment("tool: " + r.tool.name);
        std::string t;
        if (o_.toolByName) {
            std::string n = r.tool.name;
            for (char& c : n)
                if (c == '"') c = '\'';
                else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';  // one block, one line
            t = "T=\"" + n + "\" D1 M6";
        } else {
            t = "T" + std::to_string(r.tool.number) + " D1 M6";
        }
        w_.line(t);
    }

    void move(const PlannedStep& s) override {
        if (s.segment != active_) enterSegment(s.segment, s);
        const Segment& seg = plan_.segments[s.segment];
        if (seg.mode == SegmentMode::Plane) {
            if (!s.tipKnown() && !frame_.identity)
                throw inputError("a move that gives only some of X, Y, Z cannot be written in a swivelled plane");
            const Vec3 p = frame_.local(s.pose.tip);
            feedMode(s);
            motionWord(s.motion);
            xyz(p, s.known);
            if (s.motion == Motion::ArcCW || s.motion == Motion::ArcCCW) {
                const Vec3 c = frame_.r.transpose() * (s.centre - last_);
                w_.value("I", c.x(), o_.precision);
                w_.value("J", c.y(), o_.precision);
            }
            feedWord(s);
            w_.end();
        } else {
            if (s.motion == Motion::ArcCW || s.motion == Motion::ArcCCW)
                throw inputError("internal: an arc reached a TRAORI segment unlinearised");
            feedMode(s);
            motionWord(s.motion);
            xyz(s.pose.tip, s.known);
            if (o_.vectors) {
                const char* names[3] = {"A3=", "B3=", "C3="};
                bool changed = false;
                std::string tmp;
                for (int k = 0; k < 3; ++k) {
                    tmp.clear();
                    appendNumber(tmp, s.pose.axis[k], o_.vectorPrecision);
                    changed |= !v_[k].valid || v_[k].last != tmp;
                }
                if (changed)
                    for (int k = 0; k < 3; ++k) {
                        v_[k].forget();
                        w_.modal(names[k], s.pose.axis[k], o_.vectorPrecision, v_[k]);
                    }
            } else {
                for (int k = 0; k < 2; ++k) w_.modal(m_.rotary[k].name, s.joints.rotary[k], o_.anglePrecision, a_[k]);
            }
            feedWord(s);
            w_.end();
        }
        last_ = s.pose.tip;
    }

    void cycle(const PlannedStep& s, const ClRecord& r) override {
        if (s.segment != active_) enterSegment(s.segment, s);
        const Vec3 u = s.pose.axis;
        const double dp = frame_.local(s.pose.tip).z();
        const double rfp = frame_.local(s.pose.tip + r.retract * u).z();
        const double rtp = frame_.local(s.pose.tip + r.clearance * u).z();
        unitsPerMinute();
        checkFeed(r.feed, std::min(o_.precision, 3));
        w_.modal("F", r.feed, std::min(o_.precision, 3), f_);
        w_.end();
        std::string call;
        auto arg = [&](double v) {
            appendNumber(call, v, o_.precision);
            call += ',';
        };
        switch (r.cycle) {
            case CycleKind::Drill:
                call = "CYCLE81(";
                arg(rtp), arg(rfp), arg(0), arg(dp);
                call.back() = ')';
                break;
            case CycleKind::DrillDwell:
                call = "CYCLE82(";
                arg(rtp), arg(rfp), arg(0), arg(dp);
                call += ',';
                appendNumber(call, r.seconds, 3);
                call += ")";
                break;
            case CycleKind::Peck:
            case CycleKind::ChipBreak:
                // FDPR = peck depth, DAM = 0 (no degression), DTB dwell at the bottom, DTS 0,
                // FRF 1, VARI 1 = full retract (G83) or 0 = chip breaking (G73).
                call = "CYCLE83(";
                arg(rtp), arg(rfp), arg(0), arg(dp);
                call += ",,";
                arg(r.peck);
                call += "0,";
                appendNumber(call, r.seconds, 3);
                call += ",0,1,";
                call += r.cycle == CycleKind::Peck ? "1)" : "0)";
                break;
        }
        w_.line(call);
        last_ = s.pose.tip + r.clearance * u;
        // The cycle leaves the tool at its return plane above the hole.
        z_.forget();
        g_.forget();
    }

    std::vector<char> milling_;
    std::string smoothing_;
    bool smoothingOn_ = false;
    bool traori_ = false;
    bool swivelled_ = false;
    int active_ = -1;
    Frame frame_;
    Vec3 last_ = Vec3::Zero();
    Modal v_[3];
};

}  // namespace

std::string formatSinumerik(const Plan& plan, const NcOptions& o) { return SinumerikFormatter(plan, o).run(); }

}  // namespace aeronc::post
