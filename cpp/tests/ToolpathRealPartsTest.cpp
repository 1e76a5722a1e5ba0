// Toolpaths for what recognition finds on parts nobody here made (NIST CTC/FTC) and on a
// generated double-sided panel: every pocket cleared without touching its
// walls or islands, down to its floor; every hole milled or drilled.
#include "toolpath/Checks.h"

#include <aeronc/core/Error.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>
#include <aeronc/toolpath/Drilling.h>
#include <aeronc/toolpath/HelicalHole.h>
#include <aeronc/toolpath/PocketClearing.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace aeronc;
using namespace aeronc::recognition;
using namespace aeronc::toolpath;
using namespace aeronc::toolpath::test;

namespace {

// The setup frame: h along the setup direction, (u, v, h) right-handed; +Z keeps x and y.
struct Frame {
    Vec3 u, v, d;
    explicit Frame(const Vec3& dir) : d(dir) {
        const Vec3 a = std::abs(d[2]) >= 0.9 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
        const double k = dot(a, d);
        u = {a[0] - k * d[0], a[1] - k * d[1], a[2] - k * d[2]};
        const double n = norm(u);
        u = {u[0] / n, u[1] / n, u[2] / n};
        v = {d[1] * u[2] - d[2] * u[1], d[2] * u[0] - d[0] * u[2], d[0] * u[1] - d[1] * u[0]};
    }
    Point at(const Vec3& p) const { return {dot(p, u), dot(p, v)}; }
    Loop loop(const Polyline& l) const {
        Loop out;
        for (const Vec3& p : l) out.push_back(at(p));
        return out;
    }
};

struct Tally {
    int pockets = 0, cleared = 0, tooNarrow = 0, refused = 0, holes = 0;
};


Tally machineAll(const DomainTree& tree) {
    Tally t;
    for (const DomainElement& e : tree.elements) {
        const Frame f(tree.setups[std::size_t(e.setup)].direction);
        if (e.hole) {
            const HoleInfo& h = *e.hole;
            const Point c = f.at(h.location);
            const double top = dot(h.location, f.d);
            const Hole hole{c, h.diameter, top, top - h.depth, h.through};
            if (std::abs(dot(h.axis, f.d)) < 0.999 || !(h.depth > 0) || !(h.diameter > 1)) continue;
            ++t.holes;
            const Toolpath drilled = drilling({hole}, {h.diameter, 0}, {});
            EXPECT_EQ(std::count_if(drilled.moves.begin(), drilled.moves.end(),
                                    [](const Move& m) { return m.kind == Move::Kind::Drill; }),
                      1);
            const Cutter em{std::min(h.diameter * 0.6, 16.0), 0};
            const Toolpath milled = helicalHole({hole}, em, {});
            for (const Move& m : milled.moves)
                if (m.h < top) EXPECT_LE(dist({m.u, m.v}, c), h.diameter / 2 - em.radius() + 1e-9);
            continue;
        }
        if (e.type != ElementType::ClosedPocket && e.type != ElementType::OpenPocket) continue;
        if (e.contour.size() < 3 || !(e.top > e.level)) continue;
        ++t.pockets;
        PocketUnit unit{f.loop(e.contour), {}, {}, e.top, e.level};
        for (const auto& isl : e.islands) unit.islands.push_back(f.loop(isl));
        for (const auto& [a, b] : e.openEdges) unit.openEdges.push_back({f.at(a), f.at(b)});
        // The largest cutter of a usual series that fits; a cutter too large is refused.
        PocketParameters p;
        p.radialAllowance = 0.3;
        Toolpath path;
        double D = 0;
        for (double d : {20.0, 16.0, 12.0, 10.0, 8.0, 6.0, 4.0, 3.0, 2.0, 1.0}) {
            p.stepOver = d / 2;
            p.stepDown = d / 4;
            try {
                path = pocketClearing(unit, {d, 0}, p);
                D = d;
                break;
            } catch (const Error& err) {
                const std::string m = err.what();
                if (m.find("does not fit") != std::string::npos) continue;
                // A loop that crosses itself is recognition's mistake, refused by name.
                if (m.find("crosses or touches itself") != std::string::npos) {
                    ++t.refused;
                    std::printf("  element %d refused: %s\n", e.id, m.c_str());
                } else {
                    ADD_FAILURE() << "element " << e.id << ": " << m;
                }
                D = -1;
                break;
            }
        }
        if (D <= 0) {
            t.tooNarrow += D == 0;
            continue;
        }
        ++t.cleared;
        // The walls: contour edges (but those along an open edge) and island edges.
        std::vector<std::pair<Point, Point>> walls;
        for (std::size_t i = 0; i < unit.contour.size(); ++i) {
            const Point& a = unit.contour[i];
            const Point& b = unit.contour[(i + 1) % unit.contour.size()];
            bool open = false;
            for (const Segment& s : unit.openEdges) open = open || (pointSegment(a, s.a, s.b) < 0.1 && pointSegment(b, s.a, s.b) < 0.1);
            if (!open) walls.push_back({a, b});
        }
        for (const Loop& isl : unit.islands)
            for (std::size_t i = 0; i < isl.size(); ++i) walls.push_back({isl[i], isl[(i + 1) % isl.size()]});
        const double clear = D / 2 + 0.3 - 0.011;
        EdgeGrid grid(walls, clear);
        double lowest = 1e300;
        std::size_t gouges = 0;
        for (std::size_t i = 1; i < path.moves.size(); ++i) {
            const Move &m0 = path.moves[i - 1], &m1 = path.moves[i];
            lowest = std::min(lowest, m1.h);
            if (std::max(m0.h, m1.h) >= e.top - 1e-9) continue;
            const double wall = grid.nearest({m0.u, m0.v}, {m1.u, m1.v}, clear);
            if (wall < clear && gouges++ == 0)
                ADD_FAILURE() << "element " << e.id << " move " << i << " comes " << wall << " from a wall";
        }
        EXPECT_EQ(gouges, 0u) << "element " << e.id;
        EXPECT_DOUBLE_EQ(lowest, e.level) << "element " << e.id;
    }
    return t;
}

std::vector<std::string> parts() {
    std::vector<std::string> out;
    const std::filesystem::path data(AERONC_SHARED_DATA);
    for (const char* name : {"nist/nist_ctc_01_asme1_ap203.stp", "nist/nist_ctc_02_asme1_ap203.stp",
                             "nist/nist_ftc_06_asme1_rd.stp"})
        if (std::filesystem::exists(data / name)) out.push_back((data / name).string());
    return out;
}

}  // namespace

class ToolpathRealPart : public ::testing::TestWithParam<std::string> {};

TEST_P(ToolpathRealPart, EveryPocketClearedWithoutTouchingItsWalls) {
    const Tally t = machineAll(recognise(loadPart(GetParam())));
    std::printf("%s: %d pockets: %d cleared, %d too narrow for 1 mm, %d refused; %d holes\n",
                std::filesystem::path(GetParam()).filename().c_str(), t.pockets, t.cleared, t.tooNarrow, t.refused,
                t.holes);
    EXPECT_GT(t.cleared, 0);
    EXPECT_LE(t.refused, t.pockets / 10);
}

INSTANTIATE_TEST_SUITE_P(Parts, ToolpathRealPart, ::testing::ValuesIn(parts()),
                         [](const auto& info) {
                             std::string n = std::filesystem::path(info.param).stem().string();
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

TEST(ToolpathGeneratedPanel, EveryPocketOfBothSidesCleared) {
    testparts::PanelSpec s;
    s.bottomPockets = true;
    const testparts::Panel panel = testparts::makePanel(s);
    const Tally t = machineAll(recognise(panel.shape));
    EXPECT_GE(t.cleared, s.pocketsX * s.pocketsY);
    EXPECT_EQ(t.cleared, t.pockets - t.tooNarrow);
    EXPECT_EQ(t.refused, 0);
}
