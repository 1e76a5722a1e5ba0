// Toolpath core figures: generated panel pockets (rounded rectangles, 8 mm corners, one or two
// islands, 20 mm deep), cleared with a 16 mm end mill at 50 % step-over and 4 mm step-down;
// the scaling over 10, 100 and 1,000 pockets; the other operations once each.
// Usage: aeronc_toolpath_bench [--pockets N]
#include <aeronc/toolpath/Drilling.h>
#include <aeronc/toolpath/HelicalHole.h>
#include <aeronc/toolpath/PocketClearing.h>
#include <aeronc/toolpath/Profile.h>
#include <aeronc/toolpath/RestCorners.h>
#include <aeronc/toolpath/ToolpathJson.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

using namespace aeronc::toolpath;

namespace {

using Clock = std::chrono::steady_clock;
double secs(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }
// Processor time of this process: on a shared machine it varies less than the wall clock.
double cpu() { return double(std::clock()) / CLOCKS_PER_SEC; }

Loop roundedRectangle(double u0, double v0, double u1, double v1, double r) {
    Loop l;
    const Point c[4] = {{u1 - r, v0 + r}, {u1 - r, v1 - r}, {u0 + r, v1 - r}, {u0 + r, v0 + r}};
    for (int k = 0; k < 4; ++k)
        for (int i = 0; i <= 16; ++i) {
            const double a = (k - 1) * M_PI / 2 + i * M_PI / 32;
            l.push_back({c[k][0] + r * std::cos(a), c[k][1] + r * std::sin(a)});
        }
    return l;
}

Loop circle(const Point& c, double r) {
    Loop l;
    for (int i = 0; i < 64; ++i) l.push_back({c[0] + r * std::cos(i * M_PI / 32), c[1] + r * std::sin(i * M_PI / 32)});
    return l;
}

// Pocket i of a panel: 70..90 mm square-ish cells on a 100 mm pitch, a boss and sometimes a rib stub.
PocketUnit pocket(int i, std::mt19937& rng) {
    std::uniform_real_distribution<double> size(70, 90), shift(-4, 4);
    const double ox = (i % 40) * 100.0, oy = (i / 40) * 100.0, w = size(rng), h = size(rng);
    PocketUnit u;
    u.contour = roundedRectangle(ox, oy, ox + w, oy + h, 8);
    u.islands.push_back(circle({ox + w * 0.35 + shift(rng), oy + h * 0.5 + shift(rng)}, 6));
    if (i % 2) u.islands.push_back(roundedRectangle(ox + w * 0.6, oy + h * 0.3, ox + w * 0.75, oy + h * 0.7, 3));
    u.top = 0, u.bottom = -20;
    return u;
}

PocketParameters roughing() {
    PocketParameters p;
    p.stepOver = 8;
    p.stepDown = 4;
    p.radialAllowance = 0.5;
    p.axialAllowance = 0.2;
    return p;
}

}  // namespace

int main(int argc, char** argv) {
    int most = 1000;
    for (int i = 1; i + 1 < argc; i += 2)
        if (!std::strcmp(argv[i], "--pockets")) most = std::max(2, std::atoi(argv[i + 1]));
    std::mt19937 rng(7);
    std::vector<PocketUnit> pockets;
    for (int i = 0; i < most; ++i) pockets.push_back(pocket(i, rng));
    const Cutter em16{16, 0};
    const PocketParameters p = roughing();

    std::printf("toolpath core: pocket clearing, 70-90 mm pockets with 8 mm corners, 1-2 islands, 20 mm deep,\n"
                "  D 16 mm end mill, step-over 8 mm (50 %%), step-down 4 mm, allowances 0.5/0.2 mm\n");
    // One pocket, repeated: the median time, for a pocket with one island and one with two.
    for (std::size_t which : {std::size_t(0), std::size_t(1)}) {
        std::vector<double> times;
        Toolpath one;
        for (int r = 0; r < 51; ++r) {
            const auto t0 = Clock::now();
            one = pocketClearing(pockets[which], em16, p);
            times.push_back(secs(t0));
        }
        std::sort(times.begin(), times.end());
        std::printf("  one pocket with %zu island(s): %.3f ms median, %zu moves, %.0f mm cut\n", pockets[which].islands.size(),
                    1e3 * times[times.size() / 2], one.moves.size(), one.cutLength);
    }
    for (int n : {10, 100, 1000}) {
        if (n > most) break;
        std::size_t moves = 0;
        const auto t0 = Clock::now();
        const double c0 = cpu();
        for (int i = 0; i < n; ++i) moves += pocketClearing(pockets[std::size_t(i)], em16, p).moves.size();
        const double t = secs(t0), c = cpu() - c0;
        std::printf("  %5d pockets: %8.3f s wall, %8.3f s processor, %.3f ms (processor) per pocket, %zu moves\n", n, t,
                    c, 1e3 * c / n, moves);
    }

    // The same pockets with the 5 mm end mill that issue 11's FreeCAD figures use.
    {
        PocketParameters q = p;
        q.stepOver = 2.5;
        q.stepDown = 2.5;
        const int n = std::min(most, 100);
        std::size_t moves = 0;
        const double c0 = cpu();
        for (int i = 0; i < n; ++i) moves += pocketClearing(pockets[std::size_t(i)], {5, 0}, q).moves.size();
        std::printf("  with a D 5 mm end mill (step-over 2.5, step-down 2.5): %.3f ms (processor) per pocket, %zu moves each\n",
                    1e3 * (cpu() - c0) / n, moves / std::size_t(n));
    }

    // The JSON boundary that the Python side calls: parse, compute, write.
    {
        std::string unit = "{\"operation\":\"pocket\",\"contour\":[";
        for (std::size_t k = 0; k < pockets[1].contour.size(); ++k)
            unit += (k ? "," : "") + std::string("[") + std::to_string(pockets[1].contour[k][0]) + "," +
                    std::to_string(pockets[1].contour[k][1]) + "]";
        unit += "],\"islands\":[[";
        for (std::size_t k = 0; k < pockets[1].islands[0].size(); ++k)
            unit += (k ? "," : "") + std::string("[") + std::to_string(pockets[1].islands[0][k][0]) + "," +
                    std::to_string(pockets[1].islands[0][k][1]) + "]";
        unit += "]],\"top\":0,\"bottom\":-20,\"stepDown\":4,\"stepOver\":8,\"radialAllowance\":0.5,"
                "\"axialAllowance\":0.2,\"cutter\":{\"diameter\":16}}";
        const int n = 100;
        std::size_t bytes = 0;
        const auto t0 = Clock::now();
        const double c0 = cpu();
        for (int i = 0; i < n; ++i) bytes += toolpathJson(unit).size();
        std::printf("  through JSON (parse, clear, write): %.3f ms wall, %.3f ms processor per pocket, %.0f kB of moves\n",
                    1e3 * secs(t0) / n, 1e3 * (cpu() - c0) / n, bytes / 1e3 / n);
    }

    std::printf("other operations, once each (median of 21):\n");
    auto time = [](const char* what, auto f) {
        std::vector<double> ts;
        std::size_t moves = 0;
        for (int r = 0; r < 21; ++r) {
            const auto t0 = Clock::now();
            moves = f().moves.size();
            ts.push_back(secs(t0));
        }
        std::sort(ts.begin(), ts.end());
        std::printf("  %-58s %8.3f ms, %6zu moves\n", what, 1e3 * ts[ts.size() / 2], moves);
    };
    time("rest corners, D 6 after D 16, same pocket", [&] {
        PocketParameters q = p;
        q.stepOver = 3;
        return restCorners(pockets[0], em16, {6, 0}, q);
    });
    time("profile round the pocket's contour, inside, D 16, arc leads", [&] {
        ProfileParameters q;
        q.side = ToolSide::Inside;
        return profile({pockets[0].contour, true, {}, {}, 0, -20}, em16, q);
    });
    time("helical milling of 10 holes, 20 mm, D 12, through 15 mm", [&] {
        std::vector<Hole> holes;
        for (int i = 0; i < 10; ++i) holes.push_back({{i * 30.0, 0}, 20, 0, -15, true});
        return helicalHole(holes, {12, 0}, {});
    });
    time("drilling 100 holes, 6.6 mm, pecking", [&] {
        std::vector<Hole> holes;
        for (int i = 0; i < 100; ++i) holes.push_back({{(i % 10) * 20.0, (i / 10) * 20.0}, 6.6, 0, -12, true});
        DrillParameters q;
        q.peck = 3;
        return drilling(holes, {6.6, 0}, q);
    });
    return 0;
}
