// Simulating programs against a pocketed plate whose truth is known: a correct pocketing path,
// the same path too low or too close to a wall, allowances, rapids through material, the -Z
// tool axis, the cutter shapes and drill cycles.
#include <aeronc/core/Error.h>
#include <aeronc/verify/Simulation.h>

#include "Fixtures.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace aeronc;
using namespace aeronc::verify;
using namespace aeronc::verify::test;

namespace {

const PocketSpec kPocket{10, 10, 50, 30, 4, 8};  // 40 x 20, corners r 4, floor at 8 in a 20 mm plate
const double kR = 3;                              // the end mill's radius
const double kSafe = 25;

Operation pocketing(const std::string& label, const std::vector<Move>& moves, double radial = 0, double axial = 0) {
    Operation op;
    op.label = label;
    op.cutter = Cutter::fromDiameter(2 * kR, 0);
    op.radialAllowance = radial, op.axialAllowance = axial;
    op.moves = moves;
    return op;
}

Program programFor(const Plate& plate, std::vector<Operation> ops) {
    Program p;
    p.cellSize = 0.5;
    p.hasBlank = true;
    p.blank = {0, 0, 0, 60, 40, 20};
    p.operations = std::move(ops);
    const PocketFaces& f = plate.pockets[0];
    p.finishedFaces = {f.floor};
    p.finishedFaces.insert(p.finishedFaces.end(), f.walls.begin(), f.walls.end());
    p.elements = {{"pocket", p.finishedFaces}};
    return p;
}

std::size_t cuttingMoves(const std::vector<Move>& moves) {
    std::size_t n = 0;
    for (const auto& m : moves) n += m.kind != MoveKind::Rapid;
    return n;
}

const FaceCoverage& faceOf(const SimulationReport& r, int face) {
    for (const auto& f : r.coverage.faces)
        if (f.face == face) return f;
    throw std::runtime_error("face not reported");
}

}  // namespace

TEST(Simulation, CorrectPocketingLeavesNoGougeAndNothingOnTheFaces) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    const auto path = pocketPath(kPocket, kR, 2.4, 8, kSafe);
    const SimulationReport r = simulate(plate.mesh, programFor(plate, {pocketing("pocket", path)}));

    EXPECT_EQ(r.gouges.moves, 0u);
    EXPECT_FALSE(r.gouges.worst.has_value());
    EXPECT_EQ(r.collisions.moves, 0u);
    EXPECT_EQ(r.inconsistentColumns, 0u);
    // Down to the cell the stock left is the part.
    EXPECT_NEAR(r.finalStockVolume, r.partVolume, 1e-6);
    const double floorArea = 40 * 20 - (4 - M_PI) * 16;
    EXPECT_NEAR(r.operations[0].removedVolume, floorArea * 12, 0.01 * floorArea * 12);
    EXPECT_NEAR(r.blankVolume - r.operations[0].removedVolume, r.finalStockVolume, 1e-6);

    const FaceCoverage& floor = faceOf(r, plate.pockets[0].floor);
    EXPECT_NEAR(floor.floorArea, floorArea, 0.01 * floorArea);
    EXPECT_DOUBLE_EQ(floor.uncoveredArea, 0);
    EXPECT_LT(floor.maxLeftover, 1e-9);
    double wallArea = 0;
    for (int w : plate.pockets[0].walls) {
        const FaceCoverage& f = faceOf(r, w);
        EXPECT_GT(f.wallArea, 0) << w;
        EXPECT_DOUBLE_EQ(f.uncoveredArea, 0) << w;
        EXPECT_DOUBLE_EQ(f.maxLeftover, 0) << w;
        wallArea += f.wallArea;
    }
    const double perimeter = 2 * (32 + 12) + 2 * M_PI * 4;
    EXPECT_NEAR(wallArea, perimeter * 12, 0.01 * perimeter * 12);
    ASSERT_EQ(r.coverage.elements.size(), 1u);
    EXPECT_NEAR(r.coverage.elements[0].area, floor.floorArea + wallArea, 1e-6);
    EXPECT_DOUBLE_EQ(r.coverage.elements[0].uncoveredArea, 0);
}

TEST(Simulation, PathTooLowGougesTheFloorByThatMuch) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    const auto path = pocketPath(kPocket, kR, 2.4, 8 - 0.1, kSafe);
    const SimulationReport r = simulate(plate.mesh, programFor(plate, {pocketing("pocket", path)}));

    ASSERT_TRUE(r.gouges.worst.has_value());
    EXPECT_NEAR(r.gouges.worst->depth, 0.1, 1e-9);
    EXPECT_FALSE(r.gouges.worst->wall);
    EXPECT_EQ(r.gouges.worst->face, plate.pockets[0].floor);
    EXPECT_EQ(r.gouges.worst->label, "pocket");
    EXPECT_NEAR(r.gouges.worst->position[2], 8, 1e-12);
    EXPECT_EQ(r.gouges.moves, cuttingMoves(path));  // every move at the floor
    EXPECT_EQ(r.operations[0].gougingMoves, cuttingMoves(path));
    EXPECT_NEAR(r.operations[0].worstGouge, 0.1, 1e-9);  // the operation's own worst, for the gate
    EXPECT_EQ(r.operations[0].worstCollision, 0);
    EXPECT_EQ(r.collisions.moves, 0u);
    // The leftover map shows the floor 0.1 below where it belongs.
    const Grid& g = r.leftover.grid;
    EXPECT_NEAR(r.leftover.top[g.index(60, 40)], -0.1, 1e-6);
    EXPECT_NEAR(r.leftover.top[g.index(5, 5)], 0, 1e-6);
}

TEST(Simulation, ToolTooCloseToAWallGougesItSideways) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    // Along the right wall (x = 50) with the tool's side 0.4 beyond it.
    const double x = 50 - kR + 0.4;
    const std::vector<Move> path = {move(MoveKind::Rapid, x, 16, kSafe), move(MoveKind::Plunge, x, 16, 8),
                                    move(MoveKind::Feed, x, 24, 8), move(MoveKind::Rapid, x, 24, kSafe)};
    const SimulationReport r = simulate(plate.mesh, programFor(plate, {pocketing("wall", path)}));

    ASSERT_TRUE(r.gouges.worst.has_value());
    EXPECT_TRUE(r.gouges.worst->wall);
    // Seen at cell centres: the depth is found to within half a cell.
    EXPECT_LE(r.gouges.worst->depth, 0.4 + 1e-9);
    EXPECT_GE(r.gouges.worst->depth, 0.4 - 0.25 - 1e-9);
    EXPECT_EQ(r.gouges.worst->face, plate.pockets[0].walls[2]);  // the right wall
    ASSERT_TRUE(r.operations[0].worstGougeAt.has_value());  // the operation's own, named alike
    EXPECT_TRUE(r.operations[0].worstGougeAt->wall);
    EXPECT_EQ(r.operations[0].worstGougeAt->face, plate.pockets[0].walls[2]);
    EXPECT_EQ(r.gouges.moves, 2u);
    EXPECT_EQ(r.collisions.moves, 0u);  // the retract rises through what the feed cut
}

TEST(Simulation, AllowancesAreMaterialLeftNotGouges) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    const double ar = 0.5, aa = 0.3;
    const PocketSpec inner{kPocket.x0 + ar, kPocket.y0 + ar, kPocket.x1 - ar, kPocket.y1 - ar, kPocket.cornerRadius - ar,
                           kPocket.floorZ};
    const auto path = pocketPath(inner, kR, 2.4, 8 + aa, kSafe);

    const SimulationReport rough = simulate(plate.mesh, programFor(plate, {pocketing("rough", path, ar, aa)}));
    EXPECT_EQ(rough.gouges.moves, 0u);
    const FaceCoverage& floor = faceOf(rough, plate.pockets[0].floor);
    EXPECT_NEAR(floor.uncoveredArea, floor.floorArea, 1e-9);  // 0.3 left everywhere, above 0.2
    const FaceCoverage& right = faceOf(rough, plate.pockets[0].walls[2]);
    EXPECT_NEAR(right.uncoveredArea, right.wallArea, 1e-9);
    EXPECT_GE(right.maxLeftover, ar - 0.25);
    EXPECT_LE(right.maxLeftover, ar + 0.25 + 1e-9);

    // Declared allowances larger than the material the path leaves are gouges.
    const SimulationReport axial = simulate(plate.mesh, programFor(plate, {pocketing("rough", path, ar, 0.5)}));
    ASSERT_TRUE(axial.gouges.worst.has_value());
    EXPECT_NEAR(axial.gouges.worst->depth, 0.2, 1e-9);
    EXPECT_FALSE(axial.gouges.worst->wall);
    const SimulationReport radial = simulate(plate.mesh, programFor(plate, {pocketing("rough", path, 1.0, aa)}));
    ASSERT_TRUE(radial.gouges.worst.has_value());
    EXPECT_TRUE(radial.gouges.worst->wall);
    EXPECT_LE(radial.gouges.worst->depth, 0.5 + 1e-9);
    EXPECT_GE(radial.gouges.worst->depth, 0.5 - 0.25 - 1e-9);
}

TEST(Simulation, RapidThroughMaterialCollides) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    const auto path = pocketPath(kPocket, kR, 2.4, 8, kSafe);
    // Over the top at a safe height, then down into the plate's border without cutting.
    const std::vector<Move> moves = {move(MoveKind::Rapid, 2, 20, kSafe), move(MoveKind::Rapid, 58, 20, kSafe),
                                     move(MoveKind::Rapid, 58, 20, 15)};
    const SimulationReport r =
        simulate(plate.mesh, programFor(plate, {pocketing("pocket", path), pocketing("crash", moves)}));
    EXPECT_EQ(r.gouges.moves, 0u);
    EXPECT_EQ(r.collisions.moves, 1u);
    ASSERT_TRUE(r.collisions.worst.has_value());
    EXPECT_EQ(r.collisions.worst->label, "crash");
    EXPECT_EQ(r.collisions.worst->operation, 1);
    EXPECT_EQ(r.collisions.worst->move, 2);
    // 5 mm down into the plate; sideways, the nearest cell centre is 0.25 * sqrt(2) from the axis.
    EXPECT_NEAR(r.collisions.worst->depth, kR - 0.25 * std::sqrt(2.0), 1e-9);
    EXPECT_EQ(r.operations[1].collidingMoves, 1u);
    EXPECT_EQ(r.operations[0].collidingMoves, 0u);
    EXPECT_DOUBLE_EQ(r.operations[1].worstCollision, r.collisions.worst->depth);
    EXPECT_EQ(r.operations[0].worstCollision, 0);
}

TEST(Simulation, MinusZToolAxisMachinesFromBelow) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    const TriangleMesh flipped = mirroredInZ(plate.mesh, 20);
    for (double offset : {0.0, -0.1}) {
        auto path = pocketPath(kPocket, kR, 2.4, 8 + offset, kSafe);
        const SimulationReport up = simulate(plate.mesh, programFor(plate, {pocketing("pocket", path)}));
        for (auto& m : path) m.z = 20 - m.z;
        Operation below = pocketing("pocket", path);
        below.axis = -1;
        const SimulationReport down = simulate(flipped, programFor(plate, {below}));
        EXPECT_EQ(down.gouges.moves, up.gouges.moves) << offset;
        EXPECT_EQ(down.collisions.moves, 0u) << offset;
        if (offset < 0) {
            ASSERT_TRUE(down.gouges.worst.has_value());
            EXPECT_NEAR(down.gouges.worst->depth, 0.1, 1e-9);
            EXPECT_NEAR(down.gouges.worst->position[2], 12, 1e-12);  // the floor, looking down
            EXPECT_EQ(down.gouges.worst->face, plate.pockets[0].floor);
        }
        EXPECT_NEAR(down.finalStockVolume, up.finalStockVolume, 1e-6) << offset;
        ASSERT_EQ(down.coverage.faces.size(), up.coverage.faces.size());
        for (std::size_t k = 0; k < up.coverage.faces.size(); ++k) {
            EXPECT_NEAR(down.coverage.faces[k].uncoveredArea, up.coverage.faces[k].uncoveredArea, 1e-9);
            EXPECT_NEAR(down.coverage.faces[k].maxLeftover, up.coverage.faces[k].maxLeftover, 1e-9);
        }
    }
}

TEST(Simulation, CuttersLeaveTheirOwnShape) {
    // A bare 10 mm slab under a 20 mm blank: what the cutters leave is the stock above 10.
    const Plate slab = makePlate(60, 40, 10, {});
    for (double corner : {0.0, 1.0, 3.0}) {
        const Cutter c = Cutter::fromDiameter(6, corner);
        Operation op;
        op.label = "shape";
        op.cutter = c;
        op.moves = {move(MoveKind::Rapid, 10.1, 20.1, 25), move(MoveKind::Plunge, 10.1, 20.1, 15),
                    move(MoveKind::Rapid, 10.1, 20.1, 25), move(MoveKind::Rapid, 30, 20.1, 25),
                    move(MoveKind::Plunge, 30, 20.1, 16), move(MoveKind::Feed, 45, 20.1, 16),
                    move(MoveKind::Rapid, 45, 20.1, 25)};
        Program p;
        p.hasBlank = true;
        p.blank = {0, 0, 0, 60, 40, 20};
        p.operations = {op};
        const SimulationReport r = simulate(slab.mesh, p);
        EXPECT_EQ(r.gouges.moves, 0u);
        EXPECT_EQ(r.collisions.moves, 0u);
        const Grid& g = r.leftover.grid;
        for (int j = 0; j < g.ny; ++j)
            for (int i = 0; i < g.nx; ++i) {
                const double x = g.centreX(i), y = g.centreY(j);
                double top = 20;
                const double dPlunge = std::hypot(x - 10.1, y - 20.1);
                if (dPlunge <= 3) top = std::min(top, 15 + c.height(dPlunge));
                const double along = std::clamp(x, 30.0, 45.0);
                const double dLine = std::hypot(x - along, y - 20.1);
                if (dLine <= 3) top = std::min(top, 16 + c.height(dLine));
                ASSERT_NEAR(r.leftover.top[g.index(i, j)], top - 10, 1e-5) << corner << " " << x << " " << y;
            }
    }
}

TEST(Simulation, DrillCycleCutsTheHoleAndRetracts) {
    const Plate slab = makePlate(60, 40, 10, {});
    Operation op;
    op.label = "drill";
    op.cutter = Cutter::fromDiameter(6, 0);
    Move a;
    a.kind = MoveKind::DrillCycle, a.x = 20, a.y = 20, a.z = 12, a.retract = 22, a.peck = 2;
    Move b = a;
    b.x = 40;
    op.moves = {a, b};
    Program p;
    p.hasBlank = true;
    p.blank = {0, 0, 0, 60, 40, 20};
    p.operations = {op};
    const SimulationReport r = simulate(slab.mesh, p);
    EXPECT_EQ(r.operations[0].segments, 3u + 4u);  // the first cycle starts at its R plane
    EXPECT_EQ(r.collisions.moves, 0u);
    EXPECT_EQ(r.gouges.moves, 0u);
    std::size_t cells = 0;
    const Grid& g = r.grid;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i)
            for (double hx : {20.0, 40.0}) cells += std::hypot(g.centreX(i) - hx, g.centreY(j) - 20) <= 3;
    EXPECT_NEAR(r.operations[0].removedVolume, cells * g.cellArea() * 8, 1e-6);
    EXPECT_NEAR(r.operations[0].removedVolume, 2 * M_PI * 9 * 8, 0.05 * 2 * M_PI * 9 * 8);
}

namespace {

// A wedge 20 mm long, 40 wide, whose top rises at 45 degrees from z = 0 at x = 0 to z = 20 at
// x = 20. Faces: 1 slope, 2 bottom, 3 the wall at x = 20, 4 and 5 the ends.
TriangleMesh wedge() {
    TriangleMesh m;
    const int a = m.addVertex(0, 0, 0), b = m.addVertex(20, 0, 0), c = m.addVertex(20, 40, 0),
              d = m.addVertex(0, 40, 0), e = m.addVertex(20, 0, 20), f = m.addVertex(20, 40, 20);
    m.addTriangle(a, e, f, 1), m.addTriangle(a, f, d, 1);
    m.addTriangle(a, c, b, 2), m.addTriangle(a, d, c, 2);
    m.addTriangle(b, c, f, 3), m.addTriangle(b, f, e, 3);
    m.addTriangle(a, b, e, 4), m.addTriangle(d, f, c, 5);
    return m;
}

// A ball of radius 3 fed along the slope at `clearance` from it, measured along its normal.
SimulationReport ballAlongSlope(double clearance) {
    const double R = 3, s = std::sqrt(0.5);
    // Ball centre on the line x = 10 - (R + clearance) s, z = 10 + (R + clearance) s: the tip is R below it.
    const double x = 10 - (R + clearance) * s, z = 10 + (R + clearance) * s - R;
    Operation op;
    op.label = "slope";
    op.cutter = Cutter::fromDiameter(2 * R, R);
    op.moves = {move(MoveKind::Rapid, x, 5, 30), move(MoveKind::Feed, x, 5, z), move(MoveKind::Feed, x, 35, z),
                move(MoveKind::Rapid, x, 35, 30)};
    Program p;
    p.cellSize = 0.25;
    p.hasBlank = true;
    p.blank = {0, 0, 0, 20, 40, 20};
    p.operations = {op};
    p.finishedFaces = {1};
    p.elements = {{"slope", {1}}};
    return simulate(wedge(), p);
}

}  // namespace

// On a slope the cutter's depth is measured along the part's normal, not vertically: 0.05 into
// a 45 degree face is 0.05 deep (0.071 vertically), and 0.008 is within the tolerance (0.011
// vertically would not be).
TEST(Simulation, GougeDepthOnASlopeIsAlongItsNormal) {
    const SimulationReport deep = ballAlongSlope(-0.05);
    ASSERT_TRUE(deep.gouges.worst.has_value());
    EXPECT_FALSE(deep.gouges.worst->wall);
    EXPECT_EQ(deep.gouges.worst->face, 1);
    EXPECT_NEAR(deep.gouges.worst->depth, 0.05, 0.005);

    const SimulationReport shallow = ballAlongSlope(-0.008);
    EXPECT_FALSE(shallow.gouges.worst.has_value()) << shallow.gouges.worst->depth;
    EXPECT_EQ(shallow.gouges.moves, 0u);

    const SimulationReport clear = ballAlongSlope(0.1);
    EXPECT_FALSE(clear.gouges.worst.has_value());
}

// Two setups of the pocketed plate: the first clears the pocket along +Z; the second, turned 90
// degrees about Z, drops rapids into the pocket (gone: no collision) and into the border (still
// there: a collision). Alone, the second setup collides twice.
TEST(Simulation, SetupsSeeWhatTheSetupsBeforeRemoved) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    SetupProgram a{"+Z", {}, programFor(plate, {pocketing("pocket", pocketPath(kPocket, kR, 2.4, 8, kSafe))})};
    // Turned: part (x, y, z) = (40 - yB, xB, z); the pocket's middle (30, 20) is (20, 10) here,
    // the border at (58, 20) is (20, -18).
    Rigid turned;
    turned.rotation = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    turned.translation = {40, 0, 0};
    Program p;
    p.hasBlank = true;
    p.blank = {0, -20, 0, 40, 40, 20};
    p.operations = {pocketing("into pocket", {move(MoveKind::Rapid, 20, 10, kSafe), move(MoveKind::Rapid, 20, 10, 15)}),
                    pocketing("into border", {move(MoveKind::Rapid, 20, -18, kSafe), move(MoveKind::Rapid, 20, -18, 15)})};
    SetupProgram b{"turned", turned, p};
    const auto both = simulateSetups(plate.mesh, {a, b});
    ASSERT_EQ(both.size(), 2u);
    EXPECT_EQ(both[0].collisions.moves, 0u);
    EXPECT_EQ(both[1].collisions.moves, 1u);
    ASSERT_TRUE(both[1].collisions.worst.has_value());
    EXPECT_EQ(both[1].collisions.worst->label, "into border");
    EXPECT_NEAR(both[1].collisions.worst->depth, kR - 0.25 * std::sqrt(2.0), 1e-9);
    EXPECT_EQ(both[1].gouges.moves, 0u);
    const auto alone = simulateSetups(plate.mesh, {b});
    EXPECT_EQ(alone[0].collisions.moves, 2u);
    // A motion that is no rotation is refused.
    b.toPart.rotation[0] = 2;
    EXPECT_THROW(simulateSetups(plate.mesh, {b}), aeronc::Error);
}

TEST(Simulation, ChamferMillLeavesItsConeAndGougesTheEdgeItsConeReaches) {
    // A 90 degree chamfer mill D10, tip D1, along the pocket's lower wall (y = 10) with its tip 2 mm
    // below the plate's top (20). Its cone is 0.5 + h wide at h above the tip.
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    const Cutter cone = Cutter::cone(10, 1, 90);
    auto pass = [&](double y) {
        Operation op;
        op.label = "chamfer";
        op.cutter = cone;
        op.moves = {move(MoveKind::Rapid, 20, y, kSafe), move(MoveKind::Plunge, 20, y, 18),
                    move(MoveKind::Feed, 40, y, 18), move(MoveKind::Rapid, 40, y, kSafe)};
        return simulate(plate.mesh, programFor(plate, {op}));
    };
    // 2.5 mm from the wall the cone meets the top at 20.5: clear of the edge. As a flat D10 the
    // same pass would cut 2.5 mm into the wall.
    const SimulationReport clear = pass(12.6);
    EXPECT_EQ(clear.gouges.moves, 0u);
    EXPECT_EQ(clear.collisions.moves, 0u);
    // 1.5 mm from it the cone meets the wall 1 mm below the top and is 2.5 mm in radius at the
    // top: it cuts a 45 degree chamfer 1 mm x 1 mm into the edge, a gouge up to 1 mm deep.
    const SimulationReport cut = pass(11.5);
    ASSERT_TRUE(cut.gouges.worst.has_value());
    EXPECT_LE(cut.gouges.worst->depth, 1.0 + 1e-9);
    EXPECT_GE(cut.gouges.worst->depth, 0.5);
    // Over a bare 10 mm slab under the 20 mm blank, what the pass leaves is the cone's profile.
    const Plate slab = makePlate(60, 40, 10, {});
    Operation op;
    op.label = "cone";
    op.cutter = cone;
    op.moves = {move(MoveKind::Rapid, 30, 20.1, 25), move(MoveKind::Plunge, 30, 20.1, 16),
                move(MoveKind::Feed, 45, 20.1, 16), move(MoveKind::Rapid, 45, 20.1, 25)};
    Program p;
    p.hasBlank = true;
    p.blank = {0, 0, 0, 60, 40, 20};
    p.operations = {op};
    const SimulationReport r = simulate(slab.mesh, p);
    EXPECT_EQ(r.gouges.moves, 0u);
    const Grid& g = r.leftover.grid;
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            const double x = g.centreX(i), y = g.centreY(j);
            const double d = std::hypot(x - std::clamp(x, 30.0, 45.0), y - 20.1);
            const double top = d <= 5 ? std::min(20.0, 16 + cone.height(d)) : 20.0;
            ASSERT_NEAR(r.leftover.top[g.index(i, j)], top - 10, 1e-5) << x << " " << y;
        }
}

// A finishing pass 0.2 mm below the floor of a pocket cleared to it gouges; run again, it cuts
// nothing (no stock is left under it) but still gouges: the columns skipped for being clear of
// part and stock must not hide it, along +Z nor along -Z (the plate turned over).
TEST(Simulation, AGougeWhereNoStockIsLeftIsStillFound) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    const TriangleMesh flipped = mirroredInZ(plate.mesh, 20);
    for (int axis : {1, -1}) {
        auto rough = pocketPath(kPocket, kR, 2.4, 8, kSafe);
        auto finish = pocketPath(kPocket, kR, 2.4, 7.8, kSafe);
        if (axis < 0)
            for (auto* path : {&rough, &finish})
                for (auto& m : *path) m.z = 20 - m.z;
        Operation a = pocketing("rough", rough), b = pocketing("finish", finish), c = pocketing("again", finish);
        a.axis = b.axis = c.axis = axis;
        const SimulationReport r = simulate(axis > 0 ? plate.mesh : flipped, programFor(plate, {a, b, c}));
        EXPECT_EQ(r.operations[0].gougingMoves, 0u) << axis;
        EXPECT_GT(r.operations[1].gougingMoves, 0u) << axis;
        EXPECT_EQ(r.operations[2].gougingMoves, r.operations[1].gougingMoves) << axis;
        const double floorArea = 40 * 20 - (4 - M_PI) * 16;  // the 0.2 mm under the floor
        EXPECT_NEAR(r.operations[1].removedVolume, 0.2 * floorArea, 0.05 * 0.2 * floorArea) << axis;
        EXPECT_EQ(r.operations[2].removedVolume, 0) << axis;
        EXPECT_NEAR(r.operations[2].worstGouge, 0.2, 1e-9) << axis;
        // Each operation says where its own worst gouge is (the gate names it), also when the
        // program's first listed moves are another operation's.
        EXPECT_FALSE(r.operations[0].worstGougeAt.has_value()) << axis;
        ASSERT_TRUE(r.operations[2].worstGougeAt.has_value()) << axis;
        EXPECT_EQ(r.operations[2].worstGougeAt->label, "again") << axis;
        EXPECT_EQ(r.operations[2].worstGougeAt->operation, 2) << axis;
        EXPECT_NEAR(r.operations[2].worstGougeAt->depth, 0.2, 1e-9) << axis;
        EXPECT_EQ(r.operations[2].worstGougeAt->face, plate.pockets[0].floor) << axis;
        EXPECT_FALSE(r.operations[2].worstGougeAt->wall) << axis;
        ASSERT_TRUE(r.gouges.worst.has_value()) << axis;
        EXPECT_NEAR(r.gouges.worst->depth, 0.2, 1e-9) << axis;
        EXPECT_EQ(r.gouges.worst->face, plate.pockets[0].floor) << axis;
    }
}

// Several setups: the reports of simulateSetups (coverage measured on worker threads while the
// next setup is simulated) are those of the setups simulated one after the other, each against
// the stocks the setups before left. The third setup gouges the floor and rapids into the border.
TEST(Simulation, SetupsMeasuredBesideTheNextAreAsOneAfterTheOther) {
    const Plate plate = makePlate(60, 40, 20, {kPocket});
    Rigid turned;
    turned.rotation = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    turned.translation = {40, 0, 0};
    std::vector<SetupProgram> setups;
    setups.push_back({"+Z", {}, programFor(plate, {pocketing("pocket", pocketPath(kPocket, kR, 2.4, 9, kSafe))})});
    Program p;
    p.cellSize = 0.5;
    p.hasBlank = true;
    p.blank = {0, -20, 0, 40, 40, 20};
    p.finishedFaces = setups[0].program.finishedFaces;
    p.elements = setups[0].program.elements;
    // The pocket's middle (30, 20) of the part is (20, 10) here.
    p.operations = {pocketing("floor", {move(MoveKind::Rapid, 20, 10, kSafe), move(MoveKind::Plunge, 20, 10, 8.5),
                                        move(MoveKind::Feed, 20, 20, 8.5), move(MoveKind::Rapid, 20, 20, kSafe)})};
    setups.push_back({"turned", turned, p});
    p.operations = {pocketing("too low", {move(MoveKind::Rapid, 15, 10, kSafe), move(MoveKind::Plunge, 15, 10, 7.6),
                                          move(MoveKind::Feed, 25, 10, 7.6), move(MoveKind::Rapid, 25, 10, kSafe)}),
                    pocketing("into border", {move(MoveKind::Rapid, 20, -18, kSafe), move(MoveKind::Rapid, 20, -18, 15)})};
    setups.push_back({"turned again", turned, p});

    const auto together = simulateSetups(plate.mesh, setups);
    ASSERT_EQ(together.size(), 3u);
    std::vector<StockDexels> stocks(setups.size());
    for (std::size_t k = 0; k < setups.size(); ++k) {
        TriangleMesh mesh = plate.mesh;
        const Rigid toSetup = setups[k].toPart.inverse();
        for (Point3& v : mesh.vertices) v = toSetup(v);
        std::vector<PriorStock> priors;
        for (std::size_t j = 0; j < k; ++j)
            priors.push_back({&stocks[j], setups[k].toPart.then(setups[j].toPart.inverse())});
        const auto b = bounds(mesh);
        const auto& box = setups[k].program.blank;
        const Grid grid = gridCovering(std::min(b[0], box[0]), std::min(b[1], box[1]), std::max(b[3], box[3]),
                                       std::max(b[4], box[4]), setups[k].program.cellSize);
        const SimulationReport alone = simulate(rasterise(mesh, grid), mesh, setups[k].program, {}, priors, &stocks[k]);
        const SimulationReport& got = together[k];
        EXPECT_EQ(got.gouges.moves, alone.gouges.moves) << k;
        EXPECT_EQ(got.gouges.cells, alone.gouges.cells) << k;
        EXPECT_EQ(got.collisions.moves, alone.collisions.moves) << k;
        EXPECT_EQ(got.collisions.cells, alone.collisions.cells) << k;
        EXPECT_EQ(got.finalStockVolume, alone.finalStockVolume) << k;
        ASSERT_EQ(got.coverage.faces.size(), alone.coverage.faces.size()) << k;
        for (std::size_t f = 0; f < got.coverage.faces.size(); ++f) {
            EXPECT_EQ(got.coverage.faces[f].face, alone.coverage.faces[f].face);
            EXPECT_EQ(got.coverage.faces[f].uncoveredArea, alone.coverage.faces[f].uncoveredArea) << k;
            EXPECT_EQ(got.coverage.faces[f].maxLeftover, alone.coverage.faces[f].maxLeftover) << k;
        }
        EXPECT_EQ(got.leftover.top, alone.leftover.top) << k;
    }
    // What the third setup does wrong is found: 0.4 mm into the floor (the first left it at 9,
    // the second at 8.5), and a rapid into the border.
    ASSERT_TRUE(together[2].gouges.worst.has_value());
    EXPECT_EQ(together[2].gouges.worst->label, "too low");
    EXPECT_NEAR(together[2].gouges.worst->depth, 0.4, 1e-9);
    ASSERT_TRUE(together[2].collisions.worst.has_value());
    EXPECT_EQ(together[2].collisions.worst->label, "into border");
    EXPECT_EQ(together[0].gouges.moves + together[1].gouges.moves + together[0].collisions.moves +
                  together[1].collisions.moves, 0u);
}
