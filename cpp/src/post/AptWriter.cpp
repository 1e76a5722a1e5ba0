// CL program -> APT CL file (see Apt.h).
//
// Drilling: the GOTO of a hole is its R point (bottom + retract along the axis), and the
// CYCLE distances are measured from it along the tool axis: FEDTO below it to the bottom,
// RAPTO above it where the rapid approach stops (0 here), RTRCTO above it where the tool
// returns.
#include <aeronc/post/Apt.h>
#include <aeronc/post/NcFormat.h>

namespace aeronc::post {

using namespace kinematics;

namespace {

class AptWriter {
public:
    AptWriter(const ClProgram& p, int decimals) : prog_(p), d_(decimals) {}

    std::string run() {
        out_ += "$$ AeroNC CL file: tool tip and tool axis in the workpiece frame, mm\n";
        out_ += "PARTNO/" + clean(prog_.name) + "\n";
        out_ += "UNITS/MM\nMULTAX/ON\n";
        for (const auto& r : prog_.records) record(r);
        if (inCycle_) out_ += "CYCLE/OFF\n";
        out_ += "FINI\n";
        return std::move(out_);
    }

private:
    static std::string clean(std::string s) {
        for (char& c : s)
            if (c == '\n' || c == '\r' || c == '$') c = ' ';
        return s;
    }

    void num(double v, int decimals) { appendNumber(out_, v, decimals); }

    void gotoPoint(const Vec3& p, const Vec3& u) {
        out_ += "GOTO/";
        for (int k = 0; k < 3; ++k) num(p[k], d_), out_ += ',';
        for (int k = 0; k < 3; ++k) num(u[k], d_), out_ += k < 2 ? "," : "\n";
    }

    void feed(double f) {
        if (f == feed_) return;
        out_ += "FEDRAT/";
        num(f, 4);
        out_ += ",MMPM\n";
        feed_ = f;
    }

    void endCycle() {
        if (!inCycle_) return;
        out_ += "CYCLE/OFF\n";
        inCycle_ = false;
    }

    void record(const ClRecord& r) {
        if (r.kind != ClKind::Cycle) endCycle();
        switch (r.kind) {
            case ClKind::Comment:
                if (!r.text.empty()) out_ += "PPRINT/" + clean(r.text) + "\n";
                break;
            case ClKind::Operation: out_ += "PPRINT/OPERATION " + clean(r.text) + "\n"; break;
            case ClKind::WorkOffset: out_ += "PPRINT/WORK OFFSET " + clean(r.text) + "\n"; break;
            case ClKind::LoadTool:
                out_ += "LOADTL/" + std::to_string(r.tool.number);
                if (r.tool.length > 0) out_ += ",LENGTH,", num(r.tool.length, 4);
                out_ += "\nPPRINT/TOOL NAME " + clean(r.tool.name) + "\n";
                if (r.tool.diameter > 0) {
                    out_ += "CUTTER/";
                    num(r.tool.diameter, 4);
                    if (r.tool.cornerRadius > 0) out_ += ',', num(r.tool.cornerRadius, 4);
                    out_ += '\n';
                }
                break;
            case ClKind::Spindle:
                if (r.spindleDir == 0 || r.rpm <= 0) {
                    out_ += "SPINDL/OFF\n";
                } else {
                    out_ += "SPINDL/";
                    num(r.rpm, 4);
                    out_ += r.spindleDir > 0 ? ",CLW\n" : ",CCLW\n";
                }
                break;
            case ClKind::Coolant:
                out_ += r.text == "flood" ? "COOLNT/FLOOD\n" : r.text == "mist" ? "COOLNT/MIST\n" : "COOLNT/OFF\n";
                break;
            case ClKind::Dwell:
                out_ += "DELAY/";
                num(r.seconds, 4);
                out_ += '\n';
                break;
            case ClKind::Stop: out_ += r.text == "M1" ? "OPSTOP\n" : "STOP\n"; break;
            case ClKind::Move: move(r); break;
            case ClKind::Cycle: cycle(r); break;
        }
    }

    void move(const ClRecord& r) {
        if (!r.tipKnown()) {
            out_ += "$$ no GOTO for a move that gives only";
            const char* n = "XYZ";
            for (int k = 0; k < 3; ++k)
                if (r.known[k]) out_ += ' ', out_ += n[k], num(r.tip[k], d_);
            out_ += '\n';
            return;
        }
        if (r.motion == Motion::Rapid) {
            out_ += "RAPID\n";
        } else {
            feed(r.feed);
        }
        if (r.motion == Motion::ArcCW || r.motion == Motion::ArcCCW) {
            // CIRCLE's axis is the one the motion turns counter-clockwise about.
            const Vec3 n = r.motion == Motion::ArcCCW ? r.axis : Vec3(-r.axis);
            out_ += "CIRCLE/";
            for (int k = 0; k < 3; ++k) num(r.centre[k], d_), out_ += ',';
            for (int k = 0; k < 3; ++k) num(n[k], d_), out_ += ',';
            Vec3 toEnd = r.tip - r.centre;
            toEnd -= r.axis * toEnd.dot(r.axis);
            num(toEnd.norm(), d_);
            out_ += '\n';
        }
        gotoPoint(r.tip, r.axis);
    }

    void cycle(const ClRecord& r) {
        const char* kind = r.cycle == CycleKind::Peck ? "DEEP" : r.cycle == CycleKind::ChipBreak ? "BRKCHP" : "DRILL";
        std::string head = std::string("CYCLE/") + kind + ",FEDTO,";
        appendNumber(head, r.retract, d_);
        head += ",RAPTO,0,RTRCTO,";
        appendNumber(head, r.clearance - r.retract, d_);
        if (r.cycle == CycleKind::Peck || r.cycle == CycleKind::ChipBreak) head += ",STEP,", appendNumber(head, r.peck, d_);
        if (r.seconds > 0) head += ",DWELL,", appendNumber(head, r.seconds, 4);
        head += ",MMPM,";
        appendNumber(head, r.feed, 4);
        if (!inCycle_ || head != cycleHead_) {
            endCycle();
            out_ += head + "\n";
            cycleHead_ = head;
            inCycle_ = true;
        }
        gotoPoint(r.tip + r.retract * r.axis, r.axis);
    }

    const ClProgram& prog_;
    int d_;
    std::string out_;
    double feed_ = -1;
    bool inCycle_ = false;
    std::string cycleHead_;
};

}  // namespace

std::string writeApt(const ClProgram& program, int decimals) { return AptWriter(program, decimals).run(); }

}  // namespace aeronc::post
