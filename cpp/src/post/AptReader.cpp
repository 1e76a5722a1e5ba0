// APT CL file -> CL program (see Apt.h and AptWriter.cpp for the drilling distances).
#include <aeronc/post/Apt.h>
#include <aeronc/post/PathReader.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <regex>

namespace aeronc::post {

using namespace kinematics;

namespace {

std::string trim(std::string_view s) {
    size_t a = 0, b = s.size();
    while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
    while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
    return std::string(s.substr(a, b - a));
}

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

struct Statement {
    int line = 0;
    std::string major;  // upper case
    std::string rest;   // after '/', as written
    std::vector<std::string> args;
};

class AptReader {
public:
    explicit AptReader(const std::string& text) : text_(text) { prog_.fromApt = true; }

    ClProgram run() {
        size_t pos = 0;
        int line = 0;
        std::string pending;
        int pendingLine = 0;
        while (pos <= text_.size()) {
            // Lines end in LF, CR LF or CR alone.
            size_t eol = text_.find_first_of("\r\n", pos);
            if (eol == std::string::npos) eol = text_.size();
            std::string_view l(text_.data() + pos, eol - pos);
            pos = eol + (eol + 1 < text_.size() && text_[eol] == '\r' && text_[eol + 1] == '\n' ? 2 : 1);
            ++line;
            if (const size_t c = l.find("$$"); c != std::string_view::npos) l = l.substr(0, c);
            std::string t = trim(l);
            if (pending.empty()) pendingLine = line;
            if (!t.empty() && t.back() == '$') {  // continued on the next line
                t.pop_back();
                pending += t;
                continue;
            }
            pending += t;
            if (!pending.empty()) {
                Statement s = split(pending, pendingLine);
                pending.clear();
                if (!statement(s)) break;
            }
            if (eol == text_.size()) break;
        }
        if (!pending.empty()) fail(pendingLine, "the file ends inside a continued statement");
        return std::move(prog_);
    }

private:
    [[noreturn]] void fail(int line, const std::string& msg) const {
        throw inputError("APT line " + std::to_string(line) + ": " + msg);
    }

    Statement split(const std::string& text, int line) const {
        Statement s;
        s.line = line;
        const size_t slash = text.find('/');
        s.major = upper(trim(text.substr(0, slash)));
        if (slash != std::string::npos) {
            s.rest = trim(text.substr(slash + 1));
            size_t a = 0;
            while (a <= s.rest.size()) {
                size_t b = s.rest.find(',', a);
                if (b == std::string::npos) b = s.rest.size();
                s.args.push_back(trim(std::string_view(s.rest).substr(a, b - a)));
                a = b + 1;
            }
        }
        return s;
    }

    std::optional<double> number(const std::string& s, int line) const {
        double v = 0;
        const char* b = s.data();
        const char* e = b + s.size();
        if (b != e && *b == '+') ++b;
        const auto r = std::from_chars(b, e, v);
        if (r.ec != std::errc() || r.ptr != e) return std::nullopt;
        if (!std::isfinite(v)) fail(line, "'" + s + "' is not a finite number");
        return v;
    }

    // A whole number in [0, 2^31): tool numbers.
    int whole(const Statement& s, size_t i, const char* what) const {
        const double v = need(s, i, what);
        if (v != std::floor(v) || v < 0 || v > 2147483647.0)
            fail(s.line, s.major + ": " + what + " '" + s.args[i] + "' must be a whole number from 0 to 2147483647");
        return static_cast<int>(v);
    }

    double need(const Statement& s, size_t i, const char* what) const {
        if (i >= s.args.size()) fail(s.line, s.major + " lacks its " + what);
        const auto v = number(s.args[i], s.line);
        if (!v) fail(s.line, s.major + ": '" + s.args[i] + "' is not a number (" + what + ")");
        return *v;
    }

    ClRecord base(ClKind k, int line) const {
        ClRecord r;
        r.kind = k;
        r.op = op_;
        r.line = line;
        return r;
    }

    Vec3 unit(const Vec3& v, int line) const {
        const double n = v.norm();
        if (std::abs(n - 1.0) > kUnitTolerance) fail(line, "the tool axis (i, j, k) has length " + std::to_string(n) + ", not 1");
        return v / n;
    }

    // Keyword/value pairs of a CYCLE statement.
    double keyword(const Statement& s, const char* key, std::optional<double> fallback) const {
        for (size_t i = 1; i < s.args.size(); ++i)
            if (upper(s.args[i]) == key) return need(s, i + 1, key);
        if (!fallback) fail(s.line, std::string("CYCLE lacks ") + key);
        return *fallback;
    }

    bool statement(const Statement& s) {
        const std::string& m = s.major;
        if (m == "FINI" || m == "END") return false;
        if (m == "PARTNO") {
            prog_.name = s.rest;
        } else if (m == "UNITS") {
            const std::string u = s.args.empty() ? "" : upper(s.args[0]);
            if (u != "MM") fail(s.line, "units " + u + " are not supported; the post reads UNITS/MM");
        } else if (m == "MULTAX" || m == "MACHIN" || m == "TPRINT" || m == "INTOL" || m == "OUTTOL" || m == "CLRSRF" ||
                   m == "NOPOST" || m == "SELCTL") {
            // Settings without effect on the cutter locations.
        } else if (m == "PPRINT") {
            pprint(s);
        } else if (m == "LOADTL") {
            ClRecord r = base(ClKind::LoadTool, s.line);
            r.tool.number = whole(s, 0, "tool number");
            r.tool.name = "T" + std::to_string(r.tool.number);
            for (size_t i = 1; i + 1 < s.args.size(); ++i)
                if (upper(s.args[i]) == "LENGTH") r.tool.length = need(s, i + 1, "tool length");
            if (cutter_) r.tool.diameter = (*cutter_)[0], r.tool.cornerRadius = (*cutter_)[1];
            cutter_.reset();
            prog_.records.push_back(r);
            lastTool_ = static_cast<int>(prog_.records.size()) - 1;
        } else if (m == "CUTTER") {
            const double d = need(s, 0, "diameter");
            const double r = s.args.size() > 1 ? need(s, 1, "corner radius") : 0.0;
            if (lastTool_ >= 0 && prog_.records[lastTool_].tool.diameter == 0)
                prog_.records[lastTool_].tool.diameter = d, prog_.records[lastTool_].tool.cornerRadius = r;
            else
                cutter_ = std::array<double, 2>{d, r};
        } else if (m == "SPINDL") {
            spindle(s);
        } else if (m == "COOLNT") {
            const std::string c = s.args.empty() ? "ON" : upper(s.args[0]);
            ClRecord r = base(ClKind::Coolant, s.line);
            r.text = c == "OFF" ? "off" : c == "MIST" ? "mist" : c == "FLOOD" || c == "ON" ? "flood" : "";
            if (r.text.empty()) fail(s.line, "unknown coolant " + c);
            prog_.records.push_back(r);
        } else if (m == "FEDRAT") {
            feedrate(s);
        } else if (m == "RAPID") {
            rapid_ = true;
        } else if (m == "TLAXIS") {
            axis_ = unit(Vec3(need(s, 0, "i"), need(s, 1, "j"), need(s, 2, "k")), s.line);
        } else if (m == "FROM") {
            tip_ = Vec3(need(s, 0, "x"), need(s, 1, "y"), need(s, 2, "z"));
            if (s.args.size() >= 6) axis_ = unit(Vec3(need(s, 3, "i"), need(s, 4, "j"), need(s, 5, "k")), s.line);
            known_ = true;
        } else if (m == "GOTO") {
            gotoPoint(s);
        } else if (m == "CIRCLE") {
            Circle c;
            c.centre = Vec3(need(s, 0, "centre x"), need(s, 1, "centre y"), need(s, 2, "centre z"));
            c.normal = Vec3(need(s, 3, "axis i"), need(s, 4, "axis j"), need(s, 5, "axis k"));
            if (c.normal.norm() < 1e-9) fail(s.line, "CIRCLE with a zero axis");
            c.normal.normalize();
            c.line = s.line;
            circle_ = c;
        } else if (m == "CYCLE") {
            cycleStatement(s);
        } else if (m == "DELAY") {
            ClRecord r = base(ClKind::Dwell, s.line);
            r.seconds = need(s, 0, "seconds");
            if (r.seconds < 0) fail(s.line, "DELAY needs a dwell of 0 s or more, not " + s.args[0]);
            prog_.records.push_back(r);
        } else if (m == "STOP" || m == "OPSTOP") {
            ClRecord r = base(ClKind::Stop, s.line);
            r.text = m == "STOP" ? "M0" : "M1";
            prog_.records.push_back(r);
        } else {
            fail(s.line, "unsupported statement " + m);
        }
        return true;
    }

    void pprint(const Statement& s) {
        const std::string u = upper(s.rest);
        if (u.rfind("OPERATION ", 0) == 0) {
            op_ = static_cast<int>(prog_.operations.size());
            prog_.operations.push_back({"operation '" + s.rest.substr(10) + "'"});
            ClRecord r = base(ClKind::Operation, s.line);
            r.text = s.rest.substr(10);
            prog_.records.push_back(r);
        } else if (u.rfind("TOOL NAME ", 0) == 0 && lastTool_ >= 0) {
            prog_.records[lastTool_].tool.name = s.rest.substr(10);
        } else if (u.rfind("WORK OFFSET ", 0) == 0) {
            ClRecord r = base(ClKind::WorkOffset, s.line);
            r.text = upper(trim(s.rest.substr(12)));
            // The dialects write it as a block of its own: nothing but the offset's G code.
            static const std::regex offset("G5[4-9](\\.[1-9])?");
            if (!std::regex_match(r.text, offset)) fail(s.line, "WORK OFFSET names G54 to G59.9, not '" + r.text + "'");
            prog_.records.push_back(r);
        } else {
            ClRecord r = base(ClKind::Comment, s.line);
            r.text = s.rest;
            prog_.records.push_back(r);
        }
    }

    void spindle(const Statement& s) {
        ClRecord r = base(ClKind::Spindle, s.line);
        const std::string first = s.args.empty() ? "" : upper(s.args[0]);
        if (first == "OFF") {
            r.spindleDir = 0;
        } else if (first == "ON") {
            r.rpm = rpm_, r.spindleDir = rpm_ > 0 ? dir_ : 0;
        } else {
            r.rpm = need(s, 0, "speed");
            if (!(r.rpm > 0))
                fail(s.line, "SPINDL: spindle speed " + s.args[0] + " must be positive (SPINDL/OFF stops the spindle)");
            r.spindleDir = 1;
            for (size_t i = 1; i < s.args.size(); ++i) {
                const std::string k = upper(s.args[i]);
                if (k == "CCLW") r.spindleDir = -1;
                else if (k == "CLW" || k == "RPM") continue;
                else fail(s.line, "unsupported spindle word " + k);
            }
            rpm_ = r.rpm, dir_ = r.spindleDir;
        }
        prog_.records.push_back(r);
    }

    void feedrate(const Statement& s) {
        std::optional<double> f;
        for (const auto& a : s.args) {
            const std::string k = upper(a);
            if (auto v = number(a, s.line)) f = *v;
            else if (k != "MMPM") fail(s.line, "feed unit " + k + " is not supported; the post reads MMPM");
        }
        if (!f || *f <= 0) fail(s.line, "FEDRAT needs a positive feed");
        feed_ = *f;
    }

    void needTool(int line) const {
        if (lastTool_ < 0) fail(line, "motion before any LOADTL (no tool)");
    }

    void gotoPoint(const Statement& s) {
        needTool(s.line);
        ClRecord r = base(ClKind::Move, s.line);
        r.tip = Vec3(need(s, 0, "x"), need(s, 1, "y"), need(s, 2, "z"));
        if (s.args.size() >= 6) axis_ = unit(Vec3(need(s, 3, "i"), need(s, 4, "j"), need(s, 5, "k")), s.line);
        else if (s.args.size() != 3) fail(s.line, "GOTO takes x,y,z or x,y,z,i,j,k");
        r.axis = axis_;
        if (cycle_) {
            const Cycle& c = *cycle_;
            r.kind = ClKind::Cycle;
            r.cycle = c.kind;
            r.feed = c.feed;
            r.peck = c.step;
            r.seconds = c.dwell;
            r.retract = c.fedto + c.rapto;
            r.clearance = std::max(r.retract, c.fedto + c.rtrcto);
            r.tip = r.tip - c.fedto * axis_;
            prog_.records.push_back(r);
            tip_ = r.tip + r.clearance * axis_;
            known_ = true;
            rapid_ = false;
            return;
        }
        if (circle_) {
            const Circle c = *circle_;
            circle_.reset();
            if (!known_) fail(s.line, "an arc needs a known start point");
            const double along = c.normal.dot(axis_);
            if (std::abs(std::abs(along) - 1.0) > 1e-6) fail(c.line, "the CIRCLE axis is not along the tool axis");
            r.motion = along > 0 ? Motion::ArcCCW : Motion::ArcCW;
            Vec3 off = c.centre - tip_;
            off -= axis_ * off.dot(axis_);
            r.centre = tip_ + off;
            Vec3 toEnd = r.tip - r.centre;
            toEnd -= axis_ * toEnd.dot(axis_);
            if (off.norm() < 1e-6) fail(c.line, "arc of zero radius");
            if (std::abs(toEnd.norm() - off.norm()) > 1e-3 + 1e-5 * off.norm())
                fail(s.line, "the arc's end is not on the CIRCLE (radius " + std::to_string(off.norm()) + " at the start, " +
                                 std::to_string(toEnd.norm()) + " at the end)");
        } else {
            r.motion = rapid_ ? Motion::Rapid : Motion::Linear;
        }
        if (r.motion != Motion::Rapid) {
            if (feed_ <= 0) fail(s.line, "feed move before any FEDRAT");
            r.feed = feed_;
        }
        rapid_ = false;
        prog_.records.push_back(r);
        tip_ = r.tip;
        known_ = true;
    }

    void cycleStatement(const Statement& s) {
        const std::string kind = s.args.empty() ? "" : upper(s.args[0]);
        if (kind == "OFF") {
            cycle_.reset();
            return;
        }
        Cycle c;
        if (kind == "DRILL") c.kind = CycleKind::Drill;
        else if (kind == "DEEP") c.kind = CycleKind::Peck;
        else if (kind == "BRKCHP") c.kind = CycleKind::ChipBreak;
        else fail(s.line, "unsupported cycle " + kind);
        c.fedto = keyword(s, "FEDTO", std::nullopt);
        c.rapto = keyword(s, "RAPTO", 0.0);
        c.rtrcto = keyword(s, "RTRCTO", c.rapto);
        c.dwell = keyword(s, "DWELL", 0.0);
        if (c.dwell < 0) fail(s.line, "the cycle's DWELL must be 0 s or more");
        c.feed = keyword(s, "MMPM", feed_ > 0 ? std::optional<double>(feed_) : std::nullopt);
        if (c.kind != CycleKind::Drill) {
            c.step = keyword(s, "STEP", std::nullopt);
            if (c.step <= 0) fail(s.line, "STEP must be positive");
        } else if (c.dwell > 0) {
            c.kind = CycleKind::DrillDwell;
        }
        if (c.fedto + c.rapto <= 0) fail(s.line, "FEDTO + RAPTO must be positive (the feed depth of the hole)");
        if (c.feed <= 0) fail(s.line, "the cycle needs a positive feed (MMPM)");
        cycle_ = c;
    }

    struct Circle {
        Vec3 centre, normal;
        int line = 0;
    };
    struct Cycle {
        CycleKind kind = CycleKind::Drill;
        double fedto = 0, rapto = 0, rtrcto = 0, step = 0, dwell = 0, feed = 0;
    };

    const std::string& text_;
    ClProgram prog_;
    int op_ = -1;
    int lastTool_ = -1;
    std::optional<std::array<double, 2>> cutter_;
    double feed_ = 0;
    double rpm_ = 0;
    int dir_ = 1;
    bool rapid_ = false;
    Vec3 axis_ = Vec3::UnitZ();
    Vec3 tip_ = Vec3::Zero();
    bool known_ = false;
    std::optional<Circle> circle_;
    std::optional<Cycle> cycle_;
};

}  // namespace

ClProgram readApt(const std::string& text) { return AptReader(text).run(); }

}  // namespace aeronc::post
