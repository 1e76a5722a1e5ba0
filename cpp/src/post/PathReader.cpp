// FreeCAD Path commands (Path.toGCode() text) -> CL program. See PathReader.h for the convention.
#include <aeronc/post/PathReader.h>

#include <aeronc/core/Error.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace aeronc::post {

using namespace kinematics;

namespace {

constexpr double kNotANumberInPath = 922337203685.0;
// The S word is an integer; LinuxCNC and the 840D read it into 32 bits.
constexpr double kMaxSpindleSpeed = 2147483647.0;

// The character at line[i] whole: all bytes of a UTF-8 sequence, so that a message never ends
// inside one.
std::string_view character(std::string_view line, size_t i) {
    size_t n = 1;
    while (i + n < line.size() && n < 4 && (static_cast<unsigned char>(line[i + n]) & 0xC0) == 0x80) ++n;
    return line.substr(i, n);
}

// Parses a decimal number as FreeCAD writes it ("-12.345678"): the digits as an integer, then
// one division by a power of ten. Exact integers below 2^53 divided by an exact power of ten
// give the correctly rounded double, as from_chars would; anything else (exponents, NaN,
// long mantissas) goes to from_chars.
std::from_chars_result parseNumber(const char* first, const char* last, double& value) {
    static constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10,
                                        1e11, 1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18};
    const char* p = first;
    const bool negative = p < last && *p == '-';
    if (negative || (p < last && *p == '+')) ++p;
    unsigned long long mantissa = 0;
    int digits = 0, decimals = 0;
    bool point = false;
    for (; p < last; ++p) {
        const char c = *p;
        if (c >= '0' && c <= '9') {
            mantissa = mantissa * 10 + static_cast<unsigned>(c - '0');
            ++digits;
            decimals += point;
        } else if (c == '.' && !point) {
            point = true;
        } else {
            break;
        }
    }
    const bool stop = p == last || *p == ' ' || *p == '\t' || *p == '\r';
    if (digits == 0 || digits > 15 || decimals > 18 || !stop) {
        const char* b = first + (first < last && *first == '+');
        return std::from_chars(b, last, value);
    }
    value = static_cast<double>(mantissa) / kPow10[decimals];
    if (negative) value = -value;
    return {p, std::errc()};
}

// The words of one command line: a letter and a number each (FreeCAD writes "G1 F10.000000 X1.000000").
struct Command {
    char letter = 0;       // 'G', 'M', or 0 for a comment
    double code = 0;       // 0, 1, 81, 54, 59.1 ...
    int code10 = 0;        // code * 10: 0, 10, 810, 540, 591 ...
    std::string_view text;  // the whole line, for messages
    std::string_view comment;
    double value[26];
    unsigned present = 0;  // bit per letter
    bool has(char c) const { return present & (1u << (c - 'A')); }
    double get(char c) const { return value[c - 'A']; }
};

class Reader {
public:
    Reader(ClProgram& program) : prog_(program) {}

    void section(const PathSection& s) {
        const int op = static_cast<int>(prog_.operations.size());
        if (s.kind == PathSection::Kind::ToolChange) {
            const std::string who = "tool controller '" + s.label + "': ";
            if (s.tool.number < 0) throw inputError(who + "tool number " + std::to_string(s.tool.number) + " is negative");
            char rpm[32];
            std::snprintf(rpm, sizeof rpm, "%g", s.rpm);
            if (!std::isfinite(s.rpm) || s.rpm < 0)
                throw inputError(who + "spindle speed " + rpm + " r/min must be 0 or more");
            if (s.rpm > kMaxSpindleSpeed) throw inputError(who + "spindle speed " + rpm + " r/min does not fit the S word");
            // Held back so that the operation it belongs to is announced before the tool call.
            ClRecord r = base(ClKind::LoadTool, op, 0);
            r.tool = s.tool;
            r.text = s.label;
            toolLoaded_ = true;
            pendingTool_.push_back(r);
            ClRecord sp = base(ClKind::Spindle, op, 0);
            sp.rpm = s.rpm;
            sp.spindleDir = s.rpm > 0 ? s.spindleDir : 0;
            sp.text = s.label;  // a message about this speed names the tool controller
            pendingTool_.push_back(sp);
            return;
        }
        label_ = s.kind == PathSection::Kind::Operation ? "operation '" + s.label + "'" : "work offset '" + s.label + "'";
        prog_.operations.push_back({label_});
        op_ = op;
        axis_ = Vec3::UnitZ();  // FreeCAD's own operations carry no axis: vertical
        plane_ = 17;
        returnToInitial_ = true;
        const bool isOp = s.kind == PathSection::Kind::Operation;
        if (isOp) {
            if (!s.hasToolController) fail(1, "", "the operation has no tool controller; add one to post it");
            ClRecord r = base(ClKind::Operation, op, 0);
            r.text = s.label;
            prog_.records.push_back(r);
        }
        flushTool();
        const bool coolant = isOp && !s.coolant.empty() && s.coolant != "none";
        if (coolant) {
            ClRecord c = base(ClKind::Coolant, op, 0);
            c.text = s.coolant;
            prog_.records.push_back(c);
        }
        const char* p = s.gcode.data();
        const char* end = p + s.gcode.size();
        int number = 0;
        while (p < end) {
            // Lines end in LF, CR LF or CR alone.
            const char* eol = p;
            while (eol < end && *eol != '\n' && *eol != '\r') ++eol;
            std::string_view line(p, eol - p);
            p = eol + (eol + 1 < end && eol[0] == '\r' && eol[1] == '\n' ? 2 : 1);
            while (!line.empty() && line.back() == ' ') line.remove_suffix(1);
            if (line.empty()) continue;
            ++number;
            command(parse(line, number), number, isOp);
        }
        if (coolant) {
            ClRecord c = base(ClKind::Coolant, op, number);
            c.text = "off";
            prog_.records.push_back(c);
        }
    }

    void flushTool() {
        for (auto& r : pendingTool_) {
            r.op = op_;
            prog_.records.push_back(r);
        }
        pendingTool_.clear();
    }

private:
    ClRecord base(ClKind k, int op, int line) const {
        ClRecord r;
        r.kind = k;
        r.op = op;
        r.line = line;
        return r;
    }

    [[noreturn]] void fail(int number, std::string_view text, const std::string& msg) const {
        std::string m = label_ + ", move " + std::to_string(number);
        if (!text.empty()) m += " (" + std::string(text) + ")";
        throw inputError(m + ": " + msg);
    }

    Command parse(std::string_view line, int number) const {
        Command c;
        c.text = line;
        size_t i = 0;
        while (i < line.size() && line[i] == ' ') ++i;
        if (line[i] == '(' || line[i] == ';') {
            std::string_view body = line.substr(i + 1);
            if (line[i] == '(' && !body.empty() && body.back() == ')') body.remove_suffix(1);
            c.comment = body;
            return c;
        }
        bool first = true;
        while (i < line.size()) {
            while (i < line.size() && line[i] == ' ') ++i;
            if (i >= line.size()) break;
            const size_t start = i;
            char letter = line[i];
            if (letter >= 'a' && letter <= 'z') letter = static_cast<char>(letter - 'a' + 'A');
            if (letter < 'A' || letter > 'Z') fail(number, line, "cannot read '" + std::string(character(line, i)) + "'");
            ++i;
            double v = 0;
            const auto res = parseNumber(line.data() + i, line.data() + line.size(), v);
            if (res.ec != std::errc())
                fail(number, line, std::string("parameter ") + letter + " has no number (a parameter name must be one letter)");
            i = res.ptr - line.data();
            if (first) {
                c.letter = letter;
                c.code = v;
                // G and M numbers: 0 to 999 with at most one decimal (G59.1). NaN, infinities and
                // 1e308 once fell through to G1 and M0.
                const double tenths = v * 10;
                if (!(v >= 0 && v < 1000) || std::abs(tenths - std::round(tenths)) > 1e-6)
                    fail(number, line, "'" + std::string(line.substr(start, i - start)) +
                                           "' is no command: the code must be a number from 0 to 999 with at most one decimal");
                c.code10 = static_cast<int>(std::lround(tenths));
                first = false;
                continue;
            }
            // Path.toGCode() writes NaN, infinities and anything beyond ~9.2e11 as -922337203685.477581.
            if (!std::isfinite(v) || std::abs(v) >= kNotANumberInPath)
                fail(number, line, std::string("parameter ") + letter + " is not a finite number (NaN or infinite)");
            if (c.has(letter)) fail(number, line, std::string("parameter ") + letter + " given twice");
            c.present |= 1u << (letter - 'A');
            c.value[letter - 'A'] = v;
        }
        return c;
    }

    // The position after a move: given coordinates replace the current ones.
    void moveTo(const Command& c, Vec3& tip, std::array<bool, 3>& known) const {
        tip = pos_;
        known = known_;
        const char xyz[3] = {'X', 'Y', 'Z'};
        for (int k = 0; k < 3; ++k)
            if (c.has(xyz[k])) tip[k] = c.get(xyz[k]), known[k] = true;
    }

    void readAxis(const Command& c, int number) {
        const int n = c.has('U') + c.has('V') + c.has('W');
        if (n == 0) return;
        if (n != 3) fail(number, c.text, "a tool axis needs all of U, V and W");
        const Vec3 u(c.get('U'), c.get('V'), c.get('W'));
        const double len = u.norm();
        if (std::abs(len - 1.0) > kUnitTolerance)
            fail(number, c.text, "the tool axis (U, V, W) has length " + std::to_string(len) + ", not 1");
        axis_ = u / len;
    }

    void readFeed(const Command& c, int number) {
        if (!c.has('F')) return;
        if (c.get('F') < 0) fail(number, c.text, "negative feed rate");
        feed_ = c.get('F') * 60.0;  // FreeCAD's mm/s -> mm/min
    }

    void needTool(const Command& c, int number) const {
        if (!toolLoaded_) fail(number, c.text, "no tool is loaded: the operation comes before any tool controller");
    }

    void command(const Command& c, int number, bool isOp) {
        if (c.letter == 0) {
            ClRecord r = base(ClKind::Comment, op_, number);
            r.text = std::string(c.comment);
            prog_.records.push_back(r);
            return;
        }
        const int code10 = c.code10;
        if (c.letter == 'G') {
            switch (code10) {
                case 0: case 10: motion(c, number, isOp); return;
                case 20: case 30: arc(c, number, isOp); return;
                case 810: case 820: case 830: case 730: drill(c, number, code10 / 10); return;
                case 40: {
                    ClRecord r = base(ClKind::Dwell, op_, number);
                    r.seconds = c.has('P') ? c.get('P') : 0.0;
                    if (r.seconds < 0) fail(number, c.text, "negative dwell");
                    prog_.records.push_back(r);
                    return;
                }
                case 170: case 180: case 190: plane_ = code10 / 10; return;
                case 210: case 900: case 400: case 430: case 490: case 610: case 611: case 640: case 800: return;
                case 980: returnToInitial_ = true; return;
                case 990: returnToInitial_ = false; return;
                case 200: fail(number, c.text, "inch input (G20) is not supported; FreeCAD's Path is in mm");
                case 910: fail(number, c.text, "incremental moves (G91) are not supported");
                case 410: case 420: fail(number, c.text, "cutter radius compensation is not supported by the 5-axis post");
                default:
                    if (code10 >= 540 && code10 <= 599) {
                        ClRecord r = base(ClKind::WorkOffset, op_, number);
                        // Written from the code, not copied from the line: "G54", "G59.1".
                        r.text = "G" + std::to_string(code10 / 10) + (code10 % 10 ? "." + std::to_string(code10 % 10) : "");
                        prog_.records.push_back(r);
                        return;
                    }
            }
        } else if (c.letter == 'M') {
            switch (code10) {
                case 0: case 10: {
                    ClRecord r = base(ClKind::Stop, op_, number);
                    r.text = code10 == 0 ? "M0" : "M1";
                    prog_.records.push_back(r);
                    return;
                }
                case 20: case 300: return;  // the post writes its own programme end
                case 30: case 40: case 50: {
                    ClRecord r = base(ClKind::Spindle, op_, number);
                    r.spindleDir = code10 == 30 ? 1 : code10 == 40 ? -1 : 0;
                    r.rpm = c.has('S') ? c.get('S') : lastRpm_;
                    if (r.rpm < 0) fail(number, c.text, "negative spindle speed; M4 turns the spindle the other way");
                    if (r.spindleDir == 0) r.rpm = 0;
                    lastRpm_ = r.rpm;
                    prog_.records.push_back(r);
                    return;
                }
                case 60: {
                    if (!c.has('T')) fail(number, c.text, "tool change without T");
                    const double t = c.get('T');
                    if (t != std::floor(t) || t < 0 || t > 2147483647.0)
                        fail(number, c.text, "the tool number must be a whole number from 0 to 2147483647");
                    ClRecord r = base(ClKind::LoadTool, op_, number);
                    r.tool.number = static_cast<int>(t);
                    r.tool.name = "T" + std::to_string(r.tool.number);
                    toolLoaded_ = true;
                    prog_.records.push_back(r);
                    return;
                }
                case 70: case 80: case 90: {
                    ClRecord r = base(ClKind::Coolant, op_, number);
                    r.text = code10 == 70 ? "mist" : code10 == 80 ? "flood" : "off";
                    prog_.records.push_back(r);
                    return;
                }
            }
        }
        fail(number, c.text, "unsupported command for the 5-axis post");
    }

    void motion(const Command& c, int number, bool isOp) {
        readAxis(c, number);
        const bool rapid = c.code < 0.5;
        if (!rapid) readFeed(c, number);
        if (isOp) needTool(c, number);
        ClRecord r = base(ClKind::Move, op_, number);
        r.motion = rapid ? Motion::Rapid : Motion::Linear;
        moveTo(c, r.tip, r.known);
        r.axis = axis_;
        r.feed = rapid ? 0.0 : feed_;
        if (!rapid && r.feed <= 0) fail(number, c.text, "feed move without a feed rate; set the feed rates of the operation's tool controller");
        push(r);
    }

    void arc(const Command& c, int number, bool isOp) {
        if (isOp) needTool(c, number);
        if (plane_ != 17) fail(number, c.text, "arcs in G18/G19 are not supported; use G17 (the plane normal to the tool axis)");
        if (c.has('U') || c.has('V') || c.has('W')) {
            const Vec3 before = axis_;
            readAxis(c, number);
            if ((axis_ - before).norm() > 1e-9) fail(number, c.text, "an arc cannot change the tool axis");
        }
        if (!(known_[0] && known_[1] && known_[2])) fail(number, c.text, "an arc needs a known start point");
        readFeed(c, number);
        ClRecord r = base(ClKind::Move, op_, number);
        r.motion = c.code < 2.5 ? Motion::ArcCW : Motion::ArcCCW;
        moveTo(c, r.tip, r.known);
        r.axis = axis_;
        r.feed = feed_;
        if (r.feed <= 0) fail(number, c.text, "feed move without a feed rate; set the feed rates of the operation's tool controller");
        const Vec3 offset(c.has('I') ? c.get('I') : 0.0, c.has('J') ? c.get('J') : 0.0, c.has('K') ? c.get('K') : 0.0);
        if (std::abs(offset.dot(axis_)) > 1e-4)
            fail(number, c.text, "the arc centre offset (I, J, K) is not in the plane normal to the tool axis");
        const Vec3 inPlane = offset - axis_ * offset.dot(axis_);
        r.centre = pos_ + inPlane;
        const double r0 = inPlane.norm();
        if (r0 < 1e-6) fail(number, c.text, "arc of zero radius");
        const Vec3 toEnd = r.tip - r.centre;
        const double r1 = (toEnd - axis_ * toEnd.dot(axis_)).norm();
        if (std::abs(r1 - r0) > 1e-3 + 1e-5 * r0)
            fail(number, c.text, "the arc's end is not on its circle (radius " + std::to_string(r0) + " at the start, " +
                                     std::to_string(r1) + " at the end)");
        push(r);
    }

    void drill(const Command& c, int number, int code) {
        needTool(c, number);
        readAxis(c, number);
        readFeed(c, number);
        if (!c.has('Z')) fail(number, c.text, "drilling without Z (the hole bottom)");
        if (!c.has('R')) fail(number, c.text, "drilling without R (the retract level)");
        ClRecord r = base(ClKind::Cycle, op_, number);
        moveTo(c, r.tip, r.known);
        if (!r.tipKnown()) fail(number, c.text, "drilling needs a known X and Y");
        r.axis = axis_;
        r.feed = feed_;
        if (r.feed <= 0) fail(number, c.text, "drilling without a feed rate");
        r.cycle = code == 81 ? CycleKind::Drill : code == 82 ? CycleKind::DrillDwell : code == 83 ? CycleKind::Peck : CycleKind::ChipBreak;
        r.retract = c.get('R') - c.get('Z');
        if (r.retract <= 1e-9) fail(number, c.text, "the R level is not above the hole bottom Z");
        double initial = r.retract;
        if (known_[0] && known_[1] && known_[2]) initial = (pos_ - r.tip).dot(r.axis);
        r.clearance = returnToInitial_ ? std::max(r.retract, initial) : r.retract;
        if (r.cycle == CycleKind::Peck || r.cycle == CycleKind::ChipBreak) {
            if (!c.has('Q') || c.get('Q') <= 0) fail(number, c.text, "peck drilling needs a positive Q");
            r.peck = c.get('Q');
        }
        r.seconds = c.has('P') ? c.get('P') : 0.0;
        if (r.seconds < 0) fail(number, c.text, "negative dwell");
        prog_.records.push_back(r);
        pos_ = r.tip + r.clearance * r.axis;
        known_ = {true, true, true};
    }

    void push(const ClRecord& r) {
        prog_.records.push_back(r);
        pos_ = r.tip;
        known_ = r.known;
    }

    ClProgram& prog_;
    std::string label_;
    int op_ = -1;
    Vec3 pos_ = Vec3::Zero();
    std::array<bool, 3> known_{false, false, false};
    Vec3 axis_ = Vec3::UnitZ();
    double feed_ = 0.0;
    double lastRpm_ = 0.0;
    int plane_ = 17;
    bool returnToInitial_ = true;
    bool toolLoaded_ = false;
    std::vector<ClRecord> pendingTool_;
};

}  // namespace

ClProgram readFreeCadPath(const std::vector<PathSection>& sections, const std::string& programName) {
    ClProgram prog;
    prog.name = programName;
    size_t commands = 0;
    for (const auto& s : sections) commands += static_cast<size_t>(std::count(s.gcode.begin(), s.gcode.end(), '\n')) + 2;
    prog.records.reserve(commands + 4);
    Reader reader(prog);
    for (const auto& s : sections) reader.section(s);
    reader.flushTool();
    return prog;
}

}  // namespace aeronc::post
