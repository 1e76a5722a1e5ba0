// Coverage against geometry: a pocketing path that skips a corner leaves exactly the floor area
// that no tool position reaches, and the walls there keep the thickness the tool never took.
#include <aeronc/verify/Simulation.h>

#include "Fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace aeronc::verify;
using namespace aeronc::verify::test;

namespace {

const PocketSpec kPocket{10, 10, 50, 30, 4, 8};
const double kR = 3;

// The correct path with the top-right corner cut short: the last zig-zag line stops at x 42
// and the pass round the outline takes a chord from (47, 22) to (42, 27).
std::vector<Move> missingCornerPath() {
    const std::vector<Move> path = pocketPath(kPocket, kR, 2.4, 8, 25);
    std::vector<Move> out;
    bool outline = false, skipped = false;
    for (const Move& m : path) {
        if (!outline && m.kind == MoveKind::Feed && m.y == 26 && m.x == 46) {
            out.push_back(move(MoveKind::Feed, 42, 26, 8));
            continue;
        }
        outline = outline || (m.kind == MoveKind::Feed && m.y == kPocket.y0 + kR);
        if (outline && m.kind == MoveKind::Feed && m.x > 42 + 1e-9 && m.y > 22 + 1e-9) {
            if (!skipped) out.push_back(move(MoveKind::Feed, 47, 22, 8)), out.push_back(move(MoveKind::Feed, 42, 27, 8));
            skipped = true;
            continue;
        }
        out.push_back(m);
    }
    return out;
}

double pointSegment(double x, double y, const Move& a, const Move& b) {
    const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((x - a.x) * dx + (y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(x - a.x - t * dx, y - a.y - t * dy);
}

// Is (x, y) on the floor out of reach of every tool position at the floor?
bool uncovered(const std::vector<Move>& path, double x, double y) {
    for (std::size_t k = 1; k < path.size(); ++k) {
        const Move& a = path[k - 1];
        const Move& b = path[k];
        if (std::min(a.z, b.z) > 8 + 1e-9) continue;
        if (pointSegment(x, y, a, b) <= kR) return false;
    }
    return true;
}

bool insidePolygon(const std::vector<std::array<double, 2>>& poly, double x, double y) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i][1] > y) != (poly[j][1] > y) &&
            x < (poly[j][0] - poly[i][0]) * (y - poly[i][1]) / (poly[j][1] - poly[i][1]) + poly[i][0])
            in = !in;
    return in;
}

SimulationReport run(const Plate& plate, const std::vector<Move>& path, double cell) {
    Program p;
    p.cellSize = cell;
    p.hasBlank = true;
    p.blank = {0, 0, 0, 60, 40, 20};
    Operation op;
    op.label = "pocket";
    op.cutter = Cutter::fromDiameter(2 * kR, 0);
    op.moves = path;
    p.operations = {op};
    p.finishedFaces = {plate.pockets[0].floor};
    for (int w : plate.pockets[0].walls) p.finishedFaces.push_back(w);
    p.elements = {{"pocket", p.finishedFaces}, {"floor", {plate.pockets[0].floor}}};
    return simulate(plate.mesh, p);
}

}  // namespace

TEST(Coverage, MissedCornerLeavesTheAreaNoToolPositionReaches) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    const auto path = missingCornerPath();
    const auto& outline = plate.outlines[0];

    // The area out of reach, integrated on a fine lattice, and the length of its boundary.
    const double fine = 0.02;
    double area = 0, boundary = 0;
    for (double y = 20 + fine / 2; y < 30; y += fine)
        for (double x = 38 + fine / 2; x < 50; x += fine) {
            const bool here = insidePolygon(outline, x, y) && uncovered(path, x, y);
            area += here * fine * fine;
            const bool right = insidePolygon(outline, x + fine, y) && uncovered(path, x + fine, y);
            const bool up = insidePolygon(outline, x, y + fine) && uncovered(path, x, y + fine);
            boundary += (here != right) * fine + (here != up) * fine;
        }
    ASSERT_GT(area, 3.0);  // the test means something

    for (double cell : {0.5, 0.1}) {
        const SimulationReport r = run(plate, path, cell);
        EXPECT_EQ(r.gouges.moves, 0u);
        const FaceCoverage* floor = nullptr;
        for (const auto& f : r.coverage.faces)
            if (f.face == plate.pockets[0].floor) floor = &f;
        ASSERT_NE(floor, nullptr);
        // Exactly the cells whose centre is out of reach...
        std::size_t cells = 0;
        const Grid& g = r.grid;
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const double x = g.centreX(i), y = g.centreY(j);
                cells += insidePolygon(outline, x, y) && uncovered(path, x, y);
            }
        EXPECT_NEAR(floor->uncoveredArea, cells * g.cellArea(), 1e-9) << cell;
        // ... which is the true area to within half a cell along its boundary.
        EXPECT_NEAR(floor->uncoveredArea, area, 0.5 * cell * boundary) << cell;
        EXPECT_NEAR(floor->maxLeftover, 12, 1e-9);

        // The walls by the corner keep material, the others none.
        const auto& walls = plate.pockets[0].walls;  // bottom, c0, right, c1, top, c2, left, c3
        for (const auto& f : r.coverage.faces) {
            if (f.face == plate.pockets[0].floor) continue;
            const bool nearCorner = f.face == walls[2] || f.face == walls[3] || f.face == walls[4];
            if (nearCorner) EXPECT_GT(f.uncoveredArea, 0) << cell << " face " << f.face;
            else EXPECT_DOUBLE_EQ(f.uncoveredArea, 0) << cell << " face " << f.face;
        }
        // The corner wall: the deepest material, along the normal from the arc, to within a cell.
        double deepest = 0;
        for (int k = 0; k <= 400; ++k) {
            const double a = M_PI / 2 * k / 400, nx = -std::cos(a), ny = -std::sin(a);
            const double wx = 46 + 4 * std::cos(a), wy = 26 + 4 * std::sin(a);
            double t = 0;
            while (t < 4 && uncovered(path, wx + t * nx, wy + t * ny)) t += 0.001;
            deepest = std::max(deepest, t);
        }
        double cornerLeft = 0;
        for (const auto& f : r.coverage.faces)
            if (f.face == walls[3]) cornerLeft = f.maxLeftover;
        EXPECT_NEAR(cornerLeft, deepest, cell) << cell;

        ASSERT_EQ(r.coverage.elements.size(), 2u);
        EXPECT_EQ(r.coverage.elements[1].id, "floor");
        EXPECT_NEAR(r.coverage.elements[1].uncoveredArea, floor->uncoveredArea, 1e-9);
        EXPECT_GT(r.coverage.elements[0].uncoveredArea, floor->uncoveredArea);
    }
}

TEST(Coverage, UnfacedTopIsReportedAsItsThickness) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    Program p;
    p.hasBlank = true;
    p.blank = {0, 0, 0, 60, 40, 21.5};  // 1.5 mm above the part, never faced
    Operation op;
    op.label = "pocket";
    op.cutter = Cutter::fromDiameter(2 * kR, 0);
    op.moves = pocketPath(kPocket, kR, 2.4, 8, 25);
    p.operations = {op};
    p.finishedFaces = {plate.top, plate.pockets[0].floor};
    const SimulationReport r = simulate(plate.mesh, p);
    ASSERT_EQ(r.coverage.faces.size(), 2u);
    const FaceCoverage& top = r.coverage.faces[0];
    EXPECT_NEAR(top.maxLeftover, 1.5, 1e-9);
    EXPECT_NEAR(top.uncoveredArea, top.floorArea, 1e-9);
    EXPECT_NEAR(top.floorArea, 60 * 40 - (40 * 20 - (4 - M_PI) * 16), 0.01 * 1600);
    EXPECT_DOUBLE_EQ(r.coverage.faces[1].uncoveredArea, 0);
    // The raised blank holds the tool's plunge and the retract clear of it.
    EXPECT_EQ(r.collisions.moves, 0u);
}

// A sharp-cornered pocket roughed with a 0.5 mm radial allowance: each wall keeps the allowance
// and, by the corners, what the round tool cannot reach (at most its radius plus the allowance).
// A wall sample right by a corner once walked down the neighbouring wall's allowance and read
// that wall's length (up to the search limit) as its thickness.
TEST(Coverage, SampleByASharpCornerDoesNotReadTheNeighbouringWallsAllowance) {
    const PocketSpec sharp{10, 10, 50, 30, 0, 8};
    const Plate plate = makePlate(60, 40, 20, {sharp});
    const double allowance = 0.5;
    const PocketSpec inner{sharp.x0 + allowance, sharp.y0 + allowance, sharp.x1 - allowance, sharp.y1 - allowance,
                           kR, sharp.floorZ};
    Program p;
    p.cellSize = 0.5;
    p.hasBlank = true;
    p.blank = {0, 0, 0, 60, 40, 20};
    Operation op;
    op.label = "rough";
    op.cutter = Cutter::fromDiameter(2 * kR, 0);
    op.radialAllowance = allowance;
    op.moves = pocketPath(inner, kR, 2.4, 8, 25);
    p.operations = {op};
    for (int w : plate.pockets[0].walls) p.finishedFaces.push_back(w);
    const SimulationReport r = simulate(plate.mesh, p);
    EXPECT_EQ(r.gouges.moves, 0u);
    ASSERT_EQ(r.coverage.faces.size(), plate.pockets[0].walls.size());
    for (const auto& f : r.coverage.faces) {
        EXPECT_NEAR(f.uncoveredArea, f.wallArea, 1e-9) << "face " << f.face;  // the allowance everywhere
        EXPECT_GE(f.maxLeftover, allowance - p.cellSize) << "face " << f.face;
        EXPECT_LE(f.maxLeftover, kR + allowance + p.cellSize) << "face " << f.face;
    }
}
