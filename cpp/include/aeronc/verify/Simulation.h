#pragma once
// Runs a program against the blank on the part's dexel grid and checks it: gouges (a cutting
// move into the part beyond its allowance), collisions (a rapid through material) and coverage
// (what is left on the finished faces).
#include <aeronc/verify/Coverage.h>
#include <aeronc/verify/PartDexels.h>
#include <aeronc/verify/Program.h>
#include <aeronc/verify/StockDexels.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace aeronc::verify {

struct SimulationOptions {
    double gougeTolerance = 0.01;      // mm beyond the allowance
    double collisionTolerance = 0.01;  // mm into the material
    CoverageOptions coverage;
    bool leftoverMap = true;           // export the per-cell leftover
    int maxListed = 100;               // moves listed per check (the counts are complete)
};

// One offending move: where it went deepest.
struct MoveEvent {
    int operation = 0;      // index in Program::operations
    std::string label;
    int move = 0;           // index in the operation's moves
    double depth = 0;       // mm: beyond the allowance for a gouge, into the material for a collision
    bool wall = false;      // met from the side (horizontal depth) rather than from above
    int face = 0;           // gouge: the part face met (0 when unknown)
    std::array<double, 3> position{};  // the cell centre and the height of the material met
    std::array<double, 3> tip{};       // the end of the segment
};

struct CheckResult {
    double tolerance = 0;
    std::size_t moves = 0;  // moves with at least one offending cell
    std::size_t cells = 0;  // offending (move, cell) pairs
    std::optional<MoveEvent> worst;
    std::vector<MoveEvent> listed;  // the first maxListed moves, each at its deepest cell
};

struct OperationSummary {
    std::string label;
    std::size_t moves = 0, segments = 0;
    double removedVolume = 0;  // mm^3
    std::size_t gougingMoves = 0, collidingMoves = 0;
    double worstGouge = 0, worstCollision = 0;  // mm, the deepest of the operation's (0: none)
    std::optional<MoveEvent> worstGougeAt, worstCollisionAt;  // where they are
};

// Per cell: the stock minus the part at the top (stock top - part top) and at the bottom (part
// bottom - stock bottom); positive is material left, negative is part cut away. Where the part
// has no material, both are the stock left there; where the stock is gone, both are minus the
// part's length.
struct LeftoverMap {
    Grid grid;
    std::vector<float> top, bottom;  // grid.index(i, j)
};

struct SimulationReport {
    Grid grid;
    double partVolume = 0, blankVolume = 0, finalStockVolume = 0;
    std::size_t triangles = 0, inconsistentColumns = 0;
    std::vector<OperationSummary> operations;
    CheckResult gouges, collisions;
    CoverageReport coverage;
    LeftoverMap leftover;
    double rasteriseSeconds = 0, simulateSeconds = 0, coverageSeconds = 0;
};

// A rigid motion p -> rotation p + translation (rotation row by row).
struct Rigid {
    std::array<double, 9> rotation{1, 0, 0, 0, 1, 0, 0, 0, 1};
    std::array<double, 3> translation{};
    std::array<double, 3> operator()(const std::array<double, 3>& p) const;
    Rigid inverse() const;
    Rigid then(const Rigid& next) const;  // this first, then next
};

// The stock one setup left, simulated from the whole blank in its own frame, and the motion
// from the frame of the setup being simulated into that one. Material is still there at a
// point only where every setup before left it.
struct PriorStock {
    const StockDexels* stock = nullptr;
    Rigid toStock;
};

// Rasterises the part on a grid over the part and the blank (the part's bounding box when the
// program has none), then runs every operation in order. Throws aeronc::Error (input) for a
// program that does not fit the part.
SimulationReport simulate(const TriangleMesh& part, const Program& program, const SimulationOptions& options = {});

// The same on an already rasterised part; its grid must cover the blank. With priors, a rapid
// collides only with material that the setups before also left (checked at points every half
// cell through the material it meets); finalStock, when given, receives the stock at the end.
SimulationReport simulate(const PartDexels& part, const TriangleMesh& mesh, const Program& program,
                          const SimulationOptions& options = {}, const std::vector<PriorStock>& priors = {},
                          StockDexels* finalStock = nullptr);

// One setup of a part: its program in its own frame (its tool axis along +-Z) and the motion
// from that frame to the part's.
struct SetupProgram {
    std::string name;
    Rigid toPart;
    Program program;
};

// The setups in the order given, each in its own frame from the whole blank (partMesh is in the
// part's frame); the rapids of each are checked against what the setups before left too.
std::vector<SimulationReport> simulateSetups(const TriangleMesh& partMesh, const std::vector<SetupProgram>& setups,
                                             const SimulationOptions& options = {});

}  // namespace aeronc::verify
