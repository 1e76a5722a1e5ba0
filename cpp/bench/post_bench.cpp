// Post core figures: FreeCAD Path text of a 5-axis job -> NC text, per dialect, in one run.
// Usage: aeronc_post_bench [--moves N] [--machines <folder>]
#include <aeronc/post/Post.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace aeronc::kinematics;
using namespace aeronc::post;

namespace {

using Clock = std::chrono::steady_clock;
double secs(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

// A swarf-like job: the tool sweeps round a 80 mm wall, tilted 20..40 degrees, 6 decimals as
// FreeCAD writes them, with a rapid every 500 moves.
std::string job(int moves) {
    std::string g;
    g.reserve(static_cast<size_t>(moves) * 110);
    char b[200];
    for (int i = 0; i < moves; ++i) {
        const double t = i * 0.002;
        const double tilt = (30 + 10 * std::sin(t * 0.37)) * M_PI / 180, az = std::fmod(t, 2 * M_PI);
        const double u = std::sin(tilt) * std::cos(az), v = std::sin(tilt) * std::sin(az), w = std::cos(tilt);
        std::snprintf(b, sizeof b, "%s F20.000000 U%.6f V%.6f W%.6f X%.6f Y%.6f Z%.6f\n", i % 500 ? "G1" : "G0", u, v, w,
                      40 * std::cos(az), 40 * std::sin(az), -5 + 3 * std::sin(t));
        g += b;
    }
    return g;
}

}  // namespace

int main(int argc, char** argv) {
    int moves = 200000;
    std::string machines = AERONC_MACHINES;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--moves")) moves = std::atoi(argv[i + 1]);
        if (!std::strcmp(argv[i], "--machines")) machines = argv[i + 1];
    }
    PathSection tc;
    tc.kind = PathSection::Kind::ToolChange;
    tc.label = "TC";
    tc.tool.number = 1;
    tc.tool.name = "EM10";
    tc.rpm = 12000;
    tc.spindleDir = 1;
    PathSection op;
    op.label = "Swarf";
    op.gcode = job(moves);
    const MachineModel m = loadMachineFile(machines + "/AC-5AX.json");
    std::printf("post core, %d five-axis moves (%.1f MB of Path text), machine AC-5AX\n", moves, op.gcode.size() / 1e6);
    for (Dialect d : {Dialect::Sinumerik840D, Dialect::LinuxCnc}) {
        NcOptions o;
        o.dialect = d;
        o.inverseTime = d == Dialect::LinuxCnc;
        const auto t0 = Clock::now();
        const PostSummary s = postFreeCad({tc, op}, m, o, {});
        const double t = secs(t0);
        std::printf("  %-8s %8zu lines in %.3f s: %9.0f lines/s, %.2f us per move (read, kinematics, format)\n",
                    d == Dialect::LinuxCnc ? "LinuxCNC" : "840D", s.lines, t, s.lines / t, 1e6 * t / moves);
    }
    return 0;
}
