// Sequencing: the path optimiser never lengthens a path nor breaks a precedence (random
// instances), finds the obvious optimum where there is one, and the rules order the units
// as the template says (checked on a chain built by hand).
#include "Fixtures.h"

#include <aeronc/chain/ConstructionRules.h>
#include <aeronc/chain/Sequencing.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace aeronc;
using namespace aeronc::chain;

namespace {

// n random points; each point after the first third gets, with probability 1/2, one random
// predecessor among the points before it (a forest, as parent -> child precedences are).
PathProblem randomProblem(std::mt19937& rng, int n, bool withStart) {
    std::uniform_real_distribution<double> x(0, 500);
    PathProblem p;
    p.predecessors.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        p.points.push_back({x(rng), x(rng)});
        if (i > n / 3 && (rng() & 1)) p.predecessors[static_cast<std::size_t>(i)].push_back(static_cast<int>(rng() % static_cast<unsigned>(i)));
    }
    if (withStart) p.start = Point2{x(rng), x(rng)};
    return p;
}

// A random order that respects the precedences.
std::vector<int> randomTopological(std::mt19937& rng, const PathProblem& p) {
    std::vector<int> waiting(p.points.size()), path, ready;
    std::vector<std::vector<int>> next(p.points.size());
    for (std::size_t i = 0; i < p.points.size(); ++i) {
        waiting[i] = static_cast<int>(p.predecessors[i].size());
        for (int q : p.predecessors[i]) next[static_cast<std::size_t>(q)].push_back(static_cast<int>(i));
        if (!waiting[i]) ready.push_back(static_cast<int>(i));
    }
    while (!ready.empty()) {
        const std::size_t k = rng() % ready.size();
        const int i = ready[k];
        ready.erase(ready.begin() + static_cast<long>(k));
        path.push_back(i);
        for (int s : next[static_cast<std::size_t>(i)])
            if (--waiting[static_cast<std::size_t>(s)] == 0) ready.push_back(s);
    }
    return path;
}

}  // namespace

TEST(Sequencing, ImprovingNeverLengthensAPathNorBreaksAPrecedence) {
    std::mt19937 rng(11);
    int shortened = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const PathProblem p = randomProblem(rng, 10 + trial * 3, trial % 2 == 0);
        for (int start = 0; start < 2; ++start) {
            std::vector<int> path = start ? nearestNeighbour(p) : randomTopological(rng, p);
            ASSERT_TRUE(respectsPrecedence(p, path));
            const double before = pathLength(p, path);
            improvePath(p, path);
            const double after = pathLength(p, path);
            EXPECT_LE(after, before + 1e-9) << "trial " << trial;
            EXPECT_TRUE(respectsPrecedence(p, path)) << "trial " << trial;
            shortened += after < before - 1e-6;
        }
    }
    EXPECT_GT(shortened, 40);  // it does something
}

TEST(Sequencing, PointsOnALineAreVisitedInTurn) {
    PathProblem p;
    const int xs[] = {7, 2, 9, 0, 5, 3, 8, 1, 6, 4};
    for (int x : xs) p.points.push_back({static_cast<double>(x), 0});
    p.predecessors.resize(10);
    p.start = Point2{-1, 0};
    std::vector<int> path = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};  // 7, 2, 9, 0, ... : long
    improvePath(p, path);
    EXPECT_NEAR(pathLength(p, path), 10, 1e-9);
    // A precedence against the line's order costs the detour and is kept.
    p.predecessors[3].push_back(2);  // x = 0 only after x = 9
    path = nearestNeighbour(p);
    improvePath(p, path);
    EXPECT_TRUE(respectsPrecedence(p, path));
    EXPECT_NEAR(pathLength(p, path), 1 + 9 + 9, 1e-9);  // -1 -> 1..8 -> 9 -> 0: 9 + 1 + 9 ... at best 19
}

TEST(Sequencing, NearestNeighbourTakesTheClosestReadyPoint) {
    PathProblem p;
    p.points = {{10, 0}, {1, 0}, {2, 0}};
    p.predecessors = {{}, {0}, {}};
    p.start = Point2{0, 0};
    // (1, 0) is closest but waits for (10, 0): (2, 0), then (10, 0), then (1, 0).
    EXPECT_EQ(nearestNeighbour(p), (std::vector<int>{2, 0, 1}));
}

TEST(Sequencing, RulesOrderTheSmallPart) {
    const MachiningChain c = test::smallChain();
    // Step order within each setup; the drill last.
    std::map<int, int> pos;
    for (std::size_t i = 0; i < c.order.size(); ++i) pos[c.order[i]] = static_cast<int>(i);
    const auto& t = c.processTemplate;
    for (const MachiningUnit& a : c.units)
        for (const MachiningUnit& b : c.units) {
            if (a.setup != b.setup) continue;
            if (t.rank(a.step) < t.rank(b.step)) EXPECT_LT(pos[a.id], pos[b.id]) << a.id << " " << b.id;
            // Rule 1: within a step the larger tool first.
            if (a.step == b.step && a.cutter.diameter > b.cutter.diameter) EXPECT_LT(pos[a.id], pos[b.id]);
            // Rule 3: the parent's unit before the child's.
            if (a.step == b.step && a.element == 0 && b.element == 1) EXPECT_LT(pos[a.id], pos[b.id]);
        }
    // +Z first, then -Z.
    EXPECT_EQ(c.units[static_cast<std::size_t>(c.order.front())].setup, 0);
    EXPECT_EQ(c.units[static_cast<std::size_t>(c.order.back())].setup, 1);
    EXPECT_LE(c.travel.optimised, c.travel.rulesOnly + 1e-9);

    // Smaller tools first reverses the roughing processes of +Z where no parent is in the way:
    // with element 1 a pocket of its own, F10 (element 1) before R20.
    recognition::DomainTree loose = test::smallTree();
    loose.elements[1].parent = -1;
    loose.elements[0].children = {2};
    TemplateRows rows = test::panelRows();
    rows.rules[0].parameters = "order=smaller_tool_first";
    MachiningChain small = buildChain(loose, test::smallPlan(), parseTemplate(rows), test::smallOptions());
    ASSERT_EQ(small.processTemplate.rules[0].largerToolFirst, false);
    EXPECT_EQ(small.setups[0].processes[0].tool, "F10");
}

namespace {

// Position of the unit of `element` in `step` in an order.
int positionOf(const MachiningChain& c, const std::vector<int>& order, int element, StepCode step) {
    for (std::size_t i = 0; i < order.size(); ++i) {
        const MachiningUnit& u = c.units[static_cast<std::size_t>(order[i])];
        if (u.element == element && u.step == step) return static_cast<int>(i);
    }
    return -1;
}

}  // namespace

// Rule 3 over rule 1: a child roughed with a larger tool than its parent (a narrow parent ring
// around a wide deeper pocket) starts below the parent's material, so the parent's unit still
// goes first, in the rules-only order and after the travel optimisation, whichever tool order
// the template asks for.
TEST(Sequencing, ParentFirstEvenWhenTheChildsToolIsLarger) {
    for (bool largerFirst : {true, false}) {
        toolselect::ToolPlan plan = test::smallPlan();
        plan.elements[0].roughingTool = 1;  // parent: F10
        plan.elements[1].roughingTool = 0;  // child: R20
        TemplateRows rows = test::panelRows();
        if (!largerFirst) rows.rules[0].parameters = "order=smaller_tool_first";
        for (bool optimise : {false, true}) {
            ChainOptions o = test::smallOptions();
            o.optimiseTravel = optimise;
            const MachiningChain c = buildChain(test::smallTree(), plan, parseTemplate(rows), o);
            const int parent = positionOf(c, c.order, 0, StepCode::Rough);
            const int child = positionOf(c, c.order, 1, StepCode::Rough);
            ASSERT_GE(parent, 0);
            ASSERT_GE(child, 0);
            EXPECT_LT(parent, child) << "larger first " << largerFirst << ", optimised " << optimise;
            EXPECT_LT(c.units[static_cast<std::size_t>(c.order[static_cast<std::size_t>(child)])].top,
                      c.units[static_cast<std::size_t>(c.order[static_cast<std::size_t>(parent)])].top);
            for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.node << ": " << r.message;
        }
    }
}

// Many pockets of one step and tool, no precedences: the rules-only order goes from the centre
// out (rule 5), and the optimised one is shorter.
TEST(Sequencing, CentreOutThenShorterTravel) {
    recognition::DomainTree tree;
    tree.setups = {{0, {0, 0, 1}, "+Z", {}}};
    toolselect::ToolPlan plan = test::smallPlan();
    plan.elements.clear();
    plan.holes.clear();
    plan.groupsAfter = {{0, {}}};
    int id = 0;
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 5; ++j, ++id) {
            const double x = i * 80.0, y = j * 70.0;
            tree.elements.push_back(test::pocket(id, 0, -1, 5, 20, test::rectangle(x, y, x + 60, y + 50, 5), 50));
            tree.setups[0].elements.push_back(id);
            toolselect::ElementChoice ch;
            ch.element = id;
            ch.finishingTool = 1;
            ch.roughingTool = 0;
            plan.elements.push_back(ch);
            plan.groupsAfter[0].elements.push_back(id);
        }
    ChainOptions o = test::smallOptions();
    o.optimiseTravel = false;
    MachiningChain c = buildChain(tree, plan, parseTemplate(test::panelRows()), o);
    // The first block: the roughing units, from the centre (cell 3, 2) out.
    const Point2 centre{(6 * 80.0 + 60) / 2, (4 * 70.0 + 50) / 2};
    double last = -1;
    int roughs = 0;
    for (int idx : c.order) {
        const MachiningUnit& u = c.units[static_cast<std::size_t>(idx)];
        if (u.step != StepCode::Rough) break;
        const double d = std::hypot(u.at[0] - centre[0], u.at[1] - centre[1]);
        EXPECT_GE(d, last - 1e-3);
        last = d;
        ++roughs;
    }
    EXPECT_EQ(roughs, 35);
    EXPECT_DOUBLE_EQ(c.travel.rulesOnly, c.travel.optimised);

    o.optimiseTravel = true;
    const MachiningChain opt = buildChain(tree, plan, parseTemplate(test::panelRows()), o);
    EXPECT_DOUBLE_EQ(opt.travel.rulesOnly, c.travel.rulesOnly);
    EXPECT_LT(opt.travel.optimised, 0.8 * opt.travel.rulesOnly);
    EXPECT_NEAR(opt.travel.savedPercent, 100 * (1 - opt.travel.optimised / opt.travel.rulesOnly), 1e-9);
    // Five blocks (r, w, c, ss, fs) of 35 cells at least 70 mm apart: 34 moves each at least.
    EXPECT_GE(opt.travel.optimised, 5 * 34 * 70.0);
    for (const RuleCheck& r : opt.checks) EXPECT_TRUE(r.ok) << r.node << ": " << r.message;
}
