#pragma once
// NC program text from a plan, in one of two dialects:
//   Sinumerik 840D: CYCLE800 planes for 3+2 (and 3-axis) segments, TRAORI ... TRAFOOF around
//     simultaneous segments with machine A/C words or A3= B3= C3= vectors, CYCLE81/82/83,
//     CYCLE832 smoothing, M30.
//   LinuxCNC: machine coordinates X Y Z A C for a table-table machine (trivkins), G93
//     inverse-time feeds on moves that turn a rotary axis, G81/G82/G83/G73.
#include <aeronc/kinematics/Planner.h>

#include <charconv>
#include <cmath>
#include <string>

namespace aeronc::post {

enum class Dialect { Sinumerik840D, LinuxCnc };

struct NcOptions {
    Dialect dialect = Dialect::Sinumerik840D;
    bool vectors = false;        // 840D: orientation as A3= B3= C3= instead of machine axis words
    int precision = 3;           // decimals of lengths (mm)
    int anglePrecision = 3;      // decimals of angles (degrees)
    int vectorPrecision = 7;     // decimals of A3/B3/C3
    bool comments = true;
    bool lineNumbers = false;
    bool inverseTime = false;    // G93 on feed moves that turn a rotary axis
    bool toolByName = false;     // 840D: T="name" instead of T<n>
    std::string smoothing = "finish";  // 840D CYCLE832: finish, semifinish, rough, off
    double smoothingTolerance = 0.01;  // mm
    std::string programName = "AERONC";
};

std::string formatNc(const kinematics::Plan& plan, const NcOptions& options);

// Appends v with `decimals` decimals, trailing zeros dropped ("12.5", "-3", "0"). The common
// case (up to 9 decimals, |v| below 1e9) rounds the scaled value to an integer and writes its
// digits, several times faster than general floating-point formatting; the result differs from
// correctly rounded decimal output at most in a tie of the last digit.
inline void appendNumber(std::string& out, double v, int decimals) {
    static constexpr double kScale[10] = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
    if (decimals >= 0 && decimals <= 9 && std::abs(v) < 1e9) {
        const long long q = std::llround(v * kScale[decimals]);
        if (q == 0) {
            out += '0';
            return;
        }
        unsigned long long a = q < 0 ? static_cast<unsigned long long>(-q) : static_cast<unsigned long long>(q);
        char buf[32];
        char* end = buf + sizeof buf;
        char* p = end;
        int d = decimals;
        while (d > 0 && a % 10 == 0) a /= 10, --d;  // trailing zeros of the fraction
        for (int k = 0; k < d; ++k) *--p = static_cast<char>('0' + a % 10), a /= 10;
        if (d > 0) *--p = '.';
        do {
            *--p = static_cast<char>('0' + a % 10);
            a /= 10;
        } while (a);
        if (q < 0) *--p = '-';
        out.append(p, end);
        return;
    }
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
    char* end = res.ptr;
    if (decimals > 0) {
        while (end[-1] == '0') --end;
        if (end[-1] == '.') --end;
    }
    if (end - buf == 2 && buf[0] == '-' && buf[1] == '0') {
        out += '0';
        return;
    }
    out.append(buf, end);
}

}  // namespace aeronc::post
