// Verification figures: meshing and rasterising real parts (with the dexel volume against
// OCCT's), simulating generated paths of 1,000 to 100,000 moves on the sample panel, and
// plates of 10 to 1,000 machined pockets.
// Usage: aeronc_verify_bench [--quick]   (--quick: fewer sizes, for a smoke run)
#include <aeronc/brep/PartIO.h>
#include <aeronc/brep/ShapeMesh.h>
#include <aeronc/verify/Simulation.h>

#include "../tests/verify/Fixtures.h"

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

using namespace aeronc;
using namespace aeronc::verify;
using namespace aeronc::verify::test;

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// The thinnest extent along Z, as a setup frame would put a plate (a rotation: the axes cycle).
TriangleMesh thinnestAlongZ(TriangleMesh m) {
    const auto b = bounds(m);
    const double ex = b[3] - b[0], ey = b[4] - b[1], ez = b[5] - b[2];
    if (ez <= ex && ez <= ey) return m;
    for (auto& v : m.vertices) v = ey <= ex ? Point3{v[2], v[0], v[1]} : Point3{v[1], v[2], v[0]};
    return m;
}

void realParts() {
    std::vector<std::string> files = {std::string(AERONC_RESOURCES) + "/samples/sample_panel.step"};
    const std::filesystem::path nist = std::filesystem::path(AERONC_SHARED_DATA) / "nist";
    std::vector<std::string> more;
    if (std::filesystem::exists(nist))
        for (const auto& e : std::filesystem::directory_iterator(nist))
            if (e.path().extension() == ".stp") more.push_back(e.path().string());
    std::sort(more.begin(), more.end());
    files.insert(files.end(), more.begin(), more.end());

    std::printf("# real parts: mesh (deflection 0.01 mm), rasterise; dexel volume against OCCT's (GProp)\n");
    std::printf("%-28s %9s %8s %11s %10s %9s %10s %9s %10s\n", "part", "triangles", "mesh_s", "grid@0.5", "raster_s",
                "err@0.5%", "grid@0.25", "raster_s", "err@0.25%");
    for (const auto& f : files) {
        const auto shape = aeronc::loadPart(f);
        GProp_GProps p;
        BRepGProp::VolumeProperties(shape, p);
        auto t = Clock::now();
        const TriangleMesh mesh = thinnestAlongZ(meshShape(shape, 0.01));
        const double meshS = since(t);
        const auto b = bounds(mesh);
        std::printf("%-28s %9zu %8.3f", std::filesystem::path(f).stem().string().substr(0, 28).c_str(),
                    mesh.triangles.size(), meshS);
        for (double cell : {0.5, 0.25}) {
            const Grid g = gridCovering(b[0], b[1], b[3], b[4], cell);
            t = Clock::now();
            const PartDexels d = rasterise(mesh, g);
            const double s = since(t);
            char grid[32];
            std::snprintf(grid, sizeof grid, "%dx%d", g.nx, g.ny);
            std::printf(" %11s %10.3f %9.3f", grid, s, 100 * (d.volume() / p.Mass() - 1));
        }
        std::printf("\n");
    }
}

// Zig-zag passes of `segment`-long moves over the panel, stepping down `stepDown` per layer;
// with `ramp`, every move also changes height (a 3-D move).
std::vector<Move> rasterPath(std::size_t moves, double x0, double y0, double x1, double y1, double top, double step,
                             double segment, double stepDown, bool ramp) {
    std::vector<Move> out;
    out.push_back(move(MoveKind::Rapid, x0, y0, top + 5));
    double z = top - stepDown;
    out.push_back(move(MoveKind::Plunge, x0, y0, z));
    double y = y0;
    bool forward = true;
    while (out.size() < moves) {
        const int n = std::max(1, int((x1 - x0) / segment));
        for (int k = 1; k <= n && out.size() < moves; ++k) {
            const double x = forward ? x0 + (x1 - x0) * k / n : x1 - (x1 - x0) * k / n;
            const double zz = ramp ? z - 0.2 * (k % 2) : z;
            out.push_back(move(MoveKind::Feed, x, y, zz));
        }
        forward = !forward;
        y += step;
        if (y > y1) {
            y = y0;
            z -= stepDown;
        }
        if (out.size() < moves) out.push_back(move(MoveKind::Feed, forward ? x0 : x1, y, z));
    }
    return out;
}

void panelMoves(bool quick) {
    const auto shape = aeronc::loadPart(std::string(AERONC_RESOURCES) + "/samples/sample_panel.step");
    const TriangleMesh mesh = meshShape(shape, 0.01);
    const auto b = bounds(mesh);
    const Grid grid = gridCovering(b[0], b[1], b[3], b[4], 0.5);
    auto t = Clock::now();
    const PartDexels part = rasterise(mesh, grid);
    std::printf("\n# sample panel %.0f x %.0f x %.0f mm, %zu triangles, grid %d x %d at 0.5 mm: rasterised in %.3f s\n",
                b[3] - b[0], b[4] - b[1], b[5] - b[2], mesh.triangles.size(), grid.nx, grid.ny, since(t));
    std::printf("# facing passes over the panel with a 10 mm cutter, 2 mm moves, 8 mm step-over, 0.5 mm steps "
                "down into a blank 3 mm above the part\n");
    std::printf("%8s %-14s %10s %12s %14s\n", "moves", "cutter", "simulate_s", "moves_per_s", "removed_mm3");
    const std::vector<std::size_t> sizes = quick ? std::vector<std::size_t>{1000, 10000}
                                                 : std::vector<std::size_t>{1000, 10000, 100000};
    for (std::size_t n : sizes)
        for (int kind = 0; kind < 4; ++kind) {
            Program p;
            p.hasBlank = true;
            p.blank = {b[0], b[1], b[2], b[3], b[4], b[5] + 3};
            Operation op;
            op.label = "facing";
            op.cutter = Cutter::fromDiameter(10, kind == 0 ? 0 : kind == 3 ? 1 : 5);
            op.moves = rasterPath(n, b[0], b[1], b[3], b[4], b[5] + 3, 8, 2, 0.5, kind >= 2);
            p.operations = {op};
            SimulationOptions o;
            o.leftoverMap = false;
            const SimulationReport r = simulate(part, mesh, p, o);
            const char* name = kind == 0 ? "flat" : kind == 1 ? "ball" : kind == 2 ? "ball, 3-D" : "bull r1, 3-D";
            std::printf("%8zu %-14s %10.3f %12.0f %14.0f\n", n, name, r.simulateSeconds, n / r.simulateSeconds,
                        r.operations[0].removedVolume);
        }
}

void pocketScaling(bool quick) {
    std::printf("\n# plates of n pockets (40 x 24 mm, corner radius 4, 12 deep), each cleared by a 6 mm end mill "
                "(zig-zag and a pass round the outline), every floor and wall finished; cell 0.5 mm\n");
    std::printf("%6s %9s %9s %11s %8s %10s %10s %10s %8s %8s\n", "pockets", "triangles", "moves", "grid", "raster_s",
                "simulate_s", "coverage_s", "total_s", "gouges", "uncov");
    const std::vector<int> sizes = quick ? std::vector<int>{10, 100} : std::vector<int>{10, 100, 1000};
    for (int n : sizes) {
        const int cols = int(std::ceil(std::sqrt(n * 1.6))), rows = (n + cols - 1) / cols;
        std::vector<PocketSpec> pockets;
        for (int k = 0; k < n; ++k) {
            const double x = 6 + (k % cols) * 46.0, y = 6 + (k / cols) * 30.0;
            pockets.push_back({x, y, x + 40, y + 24, 4, 8});
        }
        const double W = 6 + cols * 46.0, H = 6 + rows * 30.0;
        const Plate plate = makePlate(W, H, 20, pockets);
        Program p;
        p.hasBlank = true;
        p.blank = {0, 0, 0, W, H, 20};
        Operation op;
        op.label = "pockets";
        op.cutter = Cutter::fromDiameter(6, 0);
        for (const auto& s : pockets) {
            const auto path = pocketPath(s, 3, 2.4, 8, 25);
            op.moves.insert(op.moves.end(), path.begin(), path.end());
        }
        p.operations = {op};
        for (const auto& f : plate.pockets) {
            p.finishedFaces.push_back(f.floor);
            p.finishedFaces.insert(p.finishedFaces.end(), f.walls.begin(), f.walls.end());
        }
        SimulationOptions o;
        o.leftoverMap = false;
        const auto t = Clock::now();
        const SimulationReport r = simulate(plate.mesh, p, o);
        const double total = since(t);
        double uncovered = 0;
        for (const auto& f : r.coverage.faces) uncovered += f.uncoveredArea;
        char grid[32];
        std::snprintf(grid, sizeof grid, "%dx%d", r.grid.nx, r.grid.ny);
        std::printf("%6d %9zu %9zu %11s %8.3f %10.3f %10.3f %10.3f %8zu %8.1f\n", n, plate.mesh.triangles.size(),
                    op.moves.size(), grid,
                    r.rasteriseSeconds, r.simulateSeconds, r.coverageSeconds, total, r.gouges.moves, uncovered);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && !std::strcmp(argv[1], "--quick");
    realParts();
    panelMoves(quick);
    pocketScaling(quick);
    return 0;
}
