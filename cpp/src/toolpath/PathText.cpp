#include <aeronc/toolpath/PathText.h>

#include <charconv>
#include <cmath>

namespace aeronc::toolpath {

namespace {

// Fixed notation always: FreeCAD's G-code reader takes the 'e' of "X-5.4e-16" for a word of its
// own, so the X would be read as -5.4 (a hole's centre on an axis went 5 mm astray that way).
// Below a picometre a value is 0; above it the shortest fixed form that reads back exactly.
void word(std::string& out, char letter, double v) {
    if (std::fabs(v) < 1e-9) v = 0;  // also turns -0 into 0
    char b[400];                     // the longest fixed double (10^308) fits
    b[0] = ' ', b[1] = letter;
    const auto r = std::to_chars(b + 2, b + sizeof b, v, std::chars_format::fixed);
    out.append(b, r.ptr);
}

}  // namespace

std::string pathText(const Toolpath& tp, const PathFeeds& f, const std::string& label) {
    std::string out;
    out.reserve(tp.moves.size() * 40 + label.size() + 4);
    out += '(';
    for (char c : label) out += c == '(' ? '[' : c == ')' ? ']' : (c == '\n' || c == '\r') ? ' ' : c;
    out += ")\n";
    bool inCycle = false, known = false;  // known: the position and feed so far (words are modal)
    double x = 0, y = 0, z = 0, feed = NAN;
    for (const Move& m : tp.moves) {
        if (m.kind == Move::Kind::Drill) {
            if (!inCycle) out += "G99\n", inCycle = true;
            out += m.q > 0 ? "G83" : m.dwell > 0 ? "G82" : "G81";
            word(out, 'X', m.u), word(out, 'Y', m.v), word(out, 'Z', m.h), word(out, 'R', m.r);
            if (m.q > 0) word(out, 'Q', m.q);
            else if (m.dwell > 0) word(out, 'P', m.dwell);
            word(out, 'F', f.vertical);
            out += '\n';
            x = m.u, y = m.v, z = m.r, feed = f.vertical, known = true;  // G99: back at the R plane
            continue;
        }
        if (inCycle) out += "G80\n", inCycle = false;
        out += m.kind == Move::Kind::Rapid ? "G0" : "G1";
        // Only the words that change: FreeCAD's G-code reader and the posts keep the others.
        const bool all = !known || (m.u == x && m.v == y && m.h == z);
        if (all || m.u != x) word(out, 'X', m.u);
        if (all || m.v != y) word(out, 'Y', m.v);
        if (all || m.h != z) word(out, 'Z', m.h);
        if (m.kind != Move::Kind::Rapid) {
            const double rate = m.kind == Move::Kind::Feed ? f.horizontal : f.vertical;
            if (!(rate == feed)) word(out, 'F', rate), feed = rate;
        }
        out += '\n';
        x = m.u, y = m.v, z = m.h, known = true;
    }
    if (inCycle) out += "G80\n";
    return out;
}

double estimatedSeconds(const Toolpath& tp, const PathFeeds& f) {
    double s = 0;
    bool started = false;
    double x = 0, y = 0, z = 0;
    for (const Move& m : tp.moves) {
        if (m.kind == Move::Kind::Drill) {
            const double depth = std::abs(m.r - m.h);
            if (f.vertical > 0) s += depth / f.vertical;
            if (f.verticalRapid > 0) s += depth / f.verticalRapid;
            x = m.u, y = m.v, z = m.r, started = true;
            continue;
        }
        if (started) {
            const double horizontal = std::hypot(m.u - x, m.v - y), vertical = std::abs(m.h - z);
            if (m.kind == Move::Kind::Rapid) {
                if (horizontal > 0 && f.horizontalRapid > 0) s += horizontal / f.horizontalRapid;
                if (vertical > 0 && f.verticalRapid > 0) s += vertical / f.verticalRapid;
            } else {
                const double rate = m.kind == Move::Kind::Plunge ? f.vertical : f.horizontal;
                if (rate > 0) s += std::hypot(horizontal, vertical) / rate;
            }
        }
        x = m.u, y = m.v, z = m.h, started = true;
    }
    return s;
}

}  // namespace aeronc::toolpath
