#pragma once
// NC program text from a plan, in one of two dialects:
//   Sinumerik 840D: CYCLE800 planes for 3+2 (and 3-axis) segments, TRAORI ... TRAFOOF around
//     simultaneous segments with machine A/C words or A3= B3= C3= vectors, CYCLE81/82/83,
//     CYCLE832 smoothing, M30.
//   LinuxCNC: machine coordinates X Y Z A C for a table-table machine (trivkins), G93
//     inverse-time feeds on moves that turn a rotary axis, G81/G82/G83/G73.
#include <aeronc/kinematics/Planner.h>

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

// The largest magnitude an NC word takes: the 840D's value range is +-999 999 999.9999, and no
// length, angle, feed, speed or time of a real program comes near it.
constexpr double kMaxNcValue = 1e9;

// Appends v with `decimals` decimals (0 to 15), trailing zeros dropped ("12.5", "-3", "0").
// Throws inputError for a value no NC word can take (NaN, infinite, |v| >= kMaxNcValue); `out`
// is then unchanged. Up to 9 decimals the scaled value is rounded to an integer and its digits
// written, several times faster than general floating-point formatting; the result differs
// from correctly rounded decimal output at most in a tie of the last digit.
void appendNumber(std::string& out, double v, int decimals);

}  // namespace aeronc::post
