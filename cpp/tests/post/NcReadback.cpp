// Test-only NC readback (see NcReadback.h). Deliberately shares nothing with the formatters.
#include "NcReadback.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace readback {

using aeronc::kinematics::Joints;
using aeronc::kinematics::Kinematics;
using aeronc::kinematics::Mat3;

namespace {

[[noreturn]] void fail(int line, const std::string& m) {
    throw std::runtime_error("NC line " + std::to_string(line) + ": " + m);
}

double num(const std::string& s, int line) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !std::isfinite(v)) fail(line, "bad number '" + s + "'");
    return v;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string l;
    while (std::getline(in, l)) out.push_back(l);
    return out;
}

std::string dropBlockNumber(const std::string& l) {
    if (l.size() > 1 && l[0] == 'N' && std::isdigit(static_cast<unsigned char>(l[1]))) {
        const size_t sp = l.find(' ');
        return sp == std::string::npos ? "" : l.substr(sp + 1);
    }
    return l;
}

std::vector<std::string> callArgs(const std::string& l, int line) {
    const size_t a = l.find('('), b = l.rfind(')');
    if (a == std::string::npos || b == std::string::npos || b < a) fail(line, "bad call " + l);
    std::vector<std::string> args;
    std::string cur;
    for (size_t i = a + 1; i < b; ++i) {
        if (l[i] == ',') args.push_back(cur), cur.clear();
        else cur += l[i];
    }
    if (b > a + 1) args.push_back(cur);
    return args;
}

// Rotations written out by hand (right-handed, angle in degrees).
Mat3 rx(double d) {
    const double c = std::cos(d * M_PI / 180), s = std::sin(d * M_PI / 180);
    Mat3 m;
    m << 1, 0, 0, 0, c, -s, 0, s, c;
    return m;
}
Mat3 ry(double d) {
    const double c = std::cos(d * M_PI / 180), s = std::sin(d * M_PI / 180);
    Mat3 m;
    m << c, 0, s, 0, 1, 0, -s, 0, c;
    return m;
}
Mat3 rz(double d) {
    const double c = std::cos(d * M_PI / 180), s = std::sin(d * M_PI / 180);
    Mat3 m;
    m << c, -s, 0, s, c, 0, 0, 0, 1;
    return m;
}

Vec3 axisOf(const Kinematics& kin, double r0, double r1) {
    Joints j;
    j.rotary = {r0, r1};
    return kin.forward(j).axis;
}

}  // namespace

std::vector<Pose> readSinumerik(const std::string& text, const Kinematics& kin, bool vectors) {
    const auto& m = kin.model();
    std::vector<Pose> out;
    Mat3 frame = Mat3::Identity();
    Vec3 origin = Vec3::Zero();  // CYCLE800 _X0 _Y0 _Z0: the point the plane turns about
    bool traori = false, inverse = false;
    double p[3] = {0, 0, 0};
    bool known[3] = {false, false, false};
    double rot[2] = {0, 0};
    double vec[3] = {0, 0, 1};
    int motion = 0;
    int n = 0;
    for (const std::string& raw : lines(text)) {
        ++n;
        std::string l = dropBlockNumber(raw);
        if (l.empty() || l[0] == '%' || l[0] == ';') continue;
        if (const size_t c = l.find(';'); c != std::string::npos) l = l.substr(0, c);
        while (!l.empty() && l.back() == ' ') l.pop_back();
        if (l == "TRAORI") {
            traori = true;
            continue;
        }
        if (l == "TRAFOOF") {
            traori = false;
            continue;
        }
        if (l.rfind("CYCLE800(", 0) == 0) {
            const auto a = callArgs(l, n);
            if (a.empty()) {
                frame = Mat3::Identity();
                origin = Vec3::Zero();
            } else {
                if (a.size() != 16 || num(a[3], n) != 57) fail(n, "CYCLE800 form not understood");
                frame = rx(num(a[7], n)) * ry(num(a[8], n)) * rz(num(a[9], n));
                origin = Vec3(num(a[4], n), num(a[5], n), num(a[6], n));
                if (num(a[10], n) != 0 || num(a[11], n) != 0 || num(a[12], n) != 0) fail(n, "CYCLE800 X1 Y1 Z1 not read");
            }
            known[0] = known[1] = known[2] = false;
            continue;
        }
        if (l.rfind("CYCLE832(", 0) == 0) continue;
        if (l.rfind("CYCLE81(", 0) == 0 || l.rfind("CYCLE82(", 0) == 0 || l.rfind("CYCLE83(", 0) == 0) {
            if (traori) fail(n, "drilling cycle under TRAORI");
            if (!known[0] || !known[1]) fail(n, "drilling cycle without a position");
            const auto a = callArgs(l, n);
            const double rtp = num(a[0], n), rfp = num(a[1], n), dp = num(a[3], n);
            if (!(rtp >= rfp && rfp > dp)) fail(n, "cycle levels out of order");
            out.push_back({origin + frame * Vec3(p[0], p[1], dp), frame * Vec3::UnitZ(), Kind::HoleBottom, n});
            p[2] = rtp, known[2] = true;
            continue;
        }
        std::istringstream words(l);
        std::string w;
        bool moved = false;
        double ij[2] = {0, 0};
        double f = 0;
        while (words >> w) {
            if (w == "G0" || w == "G1" || w == "G2" || w == "G3") motion = w[1] - '0';
            else if (w == "G93") inverse = true;
            else if (w == "G94") inverse = false;
            else if (w[0] == 'G' || w[0] == 'M' || w[0] == 'S' || w[0] == 'T' || w[0] == 'D') continue;
            else if (w.size() > 3 && w[1] == '3' && w[2] == '=') {
                const int k = w[0] - 'A';
                if (k < 0 || k > 2) fail(n, "bad vector word " + w);
                vec[k] = num(w.substr(3), n), moved = true;
            } else if (w[0] == 'X' || w[0] == 'Y' || w[0] == 'Z') {
                const int k = w[0] - 'X';
                p[k] = num(w.substr(1), n), known[k] = true, moved = true;
            } else if (w[0] == 'I' || w[0] == 'J') {
                ij[w[0] - 'I'] = num(w.substr(1), n);
            } else if (w[0] == 'F') {
                f = num(w.substr(1), n);
            } else if (std::string(1, w[0]) == m.rotary[0].name || std::string(1, w[0]) == m.rotary[1].name) {
                rot[std::string(1, w[0]) == m.rotary[0].name ? 0 : 1] = num(w.substr(1), n), moved = true;
            } else {
                fail(n, "unknown word " + w);
            }
        }
        if (!moved) continue;
        Pose pose;
        pose.line = n;
        pose.full = known[0] && known[1] && known[2];
        pose.kind = motion == 0 ? Kind::Rapid : motion == 1 ? Kind::Feed : Kind::Arc;
        pose.inverseTimeF = inverse && motion != 0 ? f : 0;
        if (traori) {
            pose.tip = Vec3(p[0], p[1], p[2]);
            pose.axis = vectors ? Vec3(vec[0], vec[1], vec[2]).normalized() : axisOf(kin, rot[0], rot[1]);
            if (motion >= 2) fail(n, "arc under TRAORI");
        } else {
            if (motion >= 2 && !out.empty()) {
                // The end must lie on the circle about start + (I, J) in the plane.
                const Vec3 start = frame.transpose() * (out.back().tip - origin);
                const Vec3 centre(start.x() + ij[0], start.y() + ij[1], 0);
                const double r0 = std::hypot(start.x() - centre.x(), start.y() - centre.y());
                const double r1 = std::hypot(p[0] - centre.x(), p[1] - centre.y());
                if (std::abs(r0 - r1) > 1e-6 + 1e-9 * r0) fail(n, "arc end off its circle");
            }
            pose.tip = origin + frame * Vec3(p[0], p[1], p[2]);
            pose.axis = frame * Vec3::UnitZ();
        }
        out.push_back(pose);
    }
    return out;
}

std::vector<Pose> readLinuxCnc(const std::string& text, const Kinematics& kin) {
    const auto& m = kin.model();
    std::vector<Pose> out;
    double p[3] = {0, 0, 0};
    bool known[3] = {false, false, false};
    double rot[2] = {0, 0};
    int motion = 0;
    bool inverse = false, oldZ = true;
    int n = 0;
    auto fk = [&](double z) {
        Joints j;
        j.linear = Vec3(p[0], p[1], z);
        j.rotary = {rot[0], rot[1]};
        return kin.forward(j);
    };
    for (const std::string& raw : lines(text)) {
        ++n;
        std::string l = dropBlockNumber(raw);
        std::string clean;
        int depth = 0;
        for (char c : l) {
            if (c == '(') ++depth;
            else if (c == ')') --depth;
            else if (depth == 0) clean += c;
        }
        std::istringstream words(clean);
        std::string w;
        bool moved = false;
        double r = 0, f = 0, ij[2] = {0, 0};
        bool hasR = false;
        const double xBefore = p[0], yBefore = p[1], zBefore = p[2];
        while (words >> w) {
            const char c = w[0];
            const std::string v = w.substr(1);
            if (c == 'G') {
                const double g = num(v, n);
                if (g == 0 || g == 1 || g == 2 || g == 3 || g == 81 || g == 82 || g == 83 || g == 73) motion = static_cast<int>(g);
                else if (g == 80) motion = -1;
                else if (g == 93) inverse = true;
                else if (g == 94) inverse = false;
                else if (g == 98) oldZ = true;
                else if (g == 99) oldZ = false;
            } else if (c == 'X' || c == 'Y' || c == 'Z') {
                p[c - 'X'] = num(v, n), known[c - 'X'] = true, moved = true;
            } else if (std::string(1, c) == m.rotary[0].name || std::string(1, c) == m.rotary[1].name) {
                rot[std::string(1, c) == m.rotary[0].name ? 0 : 1] = num(v, n), moved = true;
            } else if (c == 'R') {
                r = num(v, n), hasR = true;
            } else if (c == 'F') {
                f = num(v, n);
            } else if (c == 'I' || c == 'J') {
                ij[c - 'I'] = num(v, n);
            } else if (c == 'M' || c == 'S' || c == 'T' || c == 'H' || c == 'Q' || c == 'P' || c == 'K') {
                continue;
            } else {
                fail(n, "unknown word " + w);
            }
        }
        if (!moved) continue;
        Pose pose;
        pose.line = n;
        pose.full = known[0] && known[1] && known[2];
        pose.a = rot[0], pose.c = rot[1];
        if (motion >= 73) {
            if (!hasR) fail(n, "cycle without R");
            const auto b = fk(p[2]);
            pose.tip = b.tip, pose.axis = b.axis, pose.kind = Kind::HoleBottom;
            out.push_back(pose);
            p[2] = oldZ ? std::max(zBefore, r) : r;  // where the cycle leaves the tool
            continue;
        }
        if (motion < 0) fail(n, "axis words with no motion mode");
        if (motion >= 2 && !out.empty()) {
            // G17 arc about start + (I, J): the end must lie on the circle.
            const double sx = xBefore, sy = yBefore;  // the start: where the previous block left the tool
            const double cx = sx + ij[0], cy = sy + ij[1];
            const double r0 = std::hypot(sx - cx, sy - cy), r1 = std::hypot(p[0] - cx, p[1] - cy);
            if (std::abs(r0 - r1) > 1e-6 + 1e-9 * r0) fail(n, "arc end off its circle");
        }
        const auto e = fk(p[2]);
        pose.tip = e.tip, pose.axis = e.axis;
        pose.kind = motion == 0 ? Kind::Rapid : motion == 1 ? Kind::Feed : Kind::Arc;
        pose.inverseTimeF = inverse && motion != 0 ? f : 0;
        out.push_back(pose);
    }
    return out;
}

}  // namespace readback
