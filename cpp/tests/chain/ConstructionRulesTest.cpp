// The construction rules on the small part of Fixtures.h: the chain fused from it follows them
// all (the units worked out by hand), and each edit that breaks one is reported, naming the
// node at fault.
#include "ErrorOf.h"
#include "Fixtures.h"

#include <aeronc/chain/ChainJson.h>
#include <aeronc/chain/ConstructionRules.h>
#include <aeronc/core/Error.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>

using namespace aeronc;
using namespace aeronc::chain;
using aeronc::test::inputErrorOf;
using aeronc::test::smallChain;

namespace {

const MachiningUnit& unitOf(const MachiningChain& c, int element, StepCode step) {
    for (const MachiningUnit& u : c.units)
        if (u.element == element && u.step == step) return u;
    ADD_FAILURE() << "no unit of element " << element << " step " << toString(step);
    return c.units.front();
}

std::vector<RuleCheck> failures(const MachiningChain& c, const std::string& rule) {
    std::vector<RuleCheck> out;
    for (const RuleCheck& r : c.checks)
        if (r.rule == rule && !r.ok) out.push_back(r);
    return out;
}

int failureCount(const MachiningChain& c) {
    int n = 0;
    for (const RuleCheck& r : c.checks) n += !r.ok;
    return n;
}

// Moves unit `id` to position `at` of the order.
void moveTo(MachiningChain& c, int id, std::size_t at) {
    c.order.erase(std::find(c.order.begin(), c.order.end(), id));
    c.order.insert(c.order.begin() + static_cast<long>(at), id);
}

}  // namespace

TEST(ConstructionRules, TheFusedChainIsTheOneWorkedOutByHand) {
    const MachiningChain c = smallChain();
    // r, w, c, ss, fs for element 0; r, w, ss, fs for element 1 (roughed with its finishing tool,
    // so no rest); the drill for the hole; r, w, c, ss, fs for element 3 on -Z.
    EXPECT_EQ(c.units.size(), 15u);
    const MachiningUnit& r0 = unitOf(c, 0, StepCode::Rough);
    EXPECT_EQ(r0.operation, Operation::Pocket);
    EXPECT_EQ(r0.tool, "R20");
    EXPECT_DOUBLE_EQ(r0.top, 20);
    EXPECT_DOUBLE_EQ(r0.bottom, 5);
    EXPECT_DOUBLE_EQ(r0.radialAllowance, 1.0);
    EXPECT_DOUBLE_EQ(r0.axialAllowance, 0.5);
    EXPECT_DOUBLE_EQ(r0.stepDown, 5);   // the tool's a_p
    EXPECT_DOUBLE_EQ(r0.stepOver, 10);  // its a_e
    EXPECT_NEAR(r0.at[0], 50, 1e-9);
    EXPECT_NEAR(r0.at[1], 30, 1e-9);
    // The child pocket starts at its parent's floor plus the allowance left on it.
    const MachiningUnit& r1 = unitOf(c, 1, StepCode::Rough);
    EXPECT_EQ(r1.tool, "F10");
    EXPECT_DOUBLE_EQ(r1.top, 5.5);
    EXPECT_DOUBLE_EQ(r1.bottom, 0);
    // The web pass takes the floor layer the roughing left.
    const MachiningUnit& w0 = unitOf(c, 0, StepCode::Web);
    EXPECT_EQ(w0.tool, "F10");
    EXPECT_DOUBLE_EQ(w0.top, 5.5);
    EXPECT_DOUBLE_EQ(w0.bottom, 5);
    EXPECT_DOUBLE_EQ(w0.stepOver, 5);  // clearing: the roughing a_e of F10
    // The corners of the 100 x 60 pocket: R20 + 0.5 mm cannot follow the 6 mm corner radius.
    const MachiningUnit& c0 = unitOf(c, 0, StepCode::Corner);
    EXPECT_EQ(c0.operation, Operation::Rest);
    EXPECT_EQ(c0.tool, "F10");
    ASSERT_TRUE(c0.previousCutter.has_value());
    EXPECT_DOUBLE_EQ(c0.previousCutter->diameter, 20);
    // What that cutter left on the walls: the rest toolpath takes the band between it and its
    // own allowance as material (toolpath::restCorners).
    ASSERT_TRUE(c0.previousAllowance.has_value());
    EXPECT_DOUBLE_EQ(*c0.previousAllowance, r0.radialAllowance);
    for (const MachiningUnit& u : c.units) EXPECT_FALSE(u.element == 1 && u.step == StepCode::Corner);
    const MachiningUnit& fs0 = unitOf(c, 0, StepCode::FinishWall);
    EXPECT_EQ(fs0.operation, Operation::Profile);
    EXPECT_DOUBLE_EQ(fs0.radialAllowance, 0);
    EXPECT_DOUBLE_EQ(fs0.top, 20);
    // The drill: a through hole from its top, past the bottom by the breakthrough.
    const MachiningUnit& d2 = unitOf(c, 2, StepCode::Drill);
    EXPECT_EQ(d2.operation, Operation::Drill);
    EXPECT_EQ(d2.tool, "DR-6.6");
    ASSERT_EQ(d2.holes.size(), 1u);
    EXPECT_DOUBLE_EQ(d2.holes[0].u, 80);
    EXPECT_DOUBLE_EQ(d2.holes[0].top, 5);
    EXPECT_DOUBLE_EQ(d2.holes[0].bottom, -1);
    EXPECT_TRUE(d2.holes[0].through);
    // The -Z pocket in its own frame: heights along -Z, v mirrored.
    const MachiningUnit& r3 = unitOf(c, 3, StepCode::Rough);
    EXPECT_DOUBLE_EQ(r3.top, 0);
    EXPECT_DOUBLE_EQ(r3.bottom, -4);
    EXPECT_NEAR(r3.at[0], 45, 1e-9);
    EXPECT_NEAR(r3.at[1], -25, 1e-9);
    EXPECT_TRUE(c.unmachined.empty());

    // The tree: in +Z, R20 roughs, F10 does the rest of the milling, then the drill.
    ASSERT_EQ(c.setups.size(), 2u);
    const auto& plus = c.setups[0].processes;
    ASSERT_EQ(plus.size(), 3u);
    EXPECT_EQ(plus[0].tool, "R20");
    EXPECT_EQ(plus[1].tool, "F10");
    EXPECT_EQ(plus[2].tool, "DR-6.6");
    std::vector<std::string> steps;
    for (const auto& s : plus[1].steps) steps.push_back(toString(s.code));
    EXPECT_EQ(steps, (std::vector<std::string>{"r", "w", "c", "ss", "fs"}));
    EXPECT_EQ(c.tool("R20")->number, 1);
    EXPECT_EQ(c.tool("F10")->number, 2);
    EXPECT_EQ(c.tool("DR-6.6")->number, 3);

    // Every rule holds: one "ok" entry per rule.
    EXPECT_EQ(failureCount(c), 0);
    std::vector<std::string> rules;
    for (const RuleCheck& r : c.checks) rules.push_back(r.rule);
    EXPECT_EQ(rules, (std::vector<std::string>{"priority", "existence", "validity", "removal", "fit"}));
}

TEST(ConstructionRules, PriorityFailsWhenAStepComesTooEarly) {
    MachiningChain c = smallChain();
    const int fs0 = unitOf(c, 0, StepCode::FinishWall).id;
    moveTo(c, fs0, 0);
    c = checkChain(c);
    const auto f = failures(c, "priority");
    ASSERT_FALSE(f.empty());
    // The roughing unit that now follows the finishing one is at fault.
    const int r0 = unitOf(c, 0, StepCode::Rough).id;
    EXPECT_NE(f[0].node.find("step r / unit " + std::to_string(r0) + " (element 0)"), std::string::npos) << f[0].node;
    EXPECT_NE(f[0].node.find("setup +Z / process 2 (R20)"), std::string::npos) << f[0].node;
    EXPECT_NE(f[0].message.find("comes after unit " + std::to_string(fs0) + " (step fs, F10)"), std::string::npos)
        << f[0].message;
    // The tree follows the order: the moved unit is a process of its own, first.
    EXPECT_EQ(c.setups[0].processes.front().steps.front().programs.front().units.front(), fs0);
}

TEST(ConstructionRules, ExistenceFailsWithoutAMustStepOrWithAMustNotStep) {
    MachiningChain c = smallChain();
    c.units[static_cast<std::size_t>(unitOf(c, 1, StepCode::FinishWall).id)].enabled = false;
    c = checkChain(c);
    auto f = failures(c, "existence");
    ASSERT_EQ(f.size(), 1u);
    EXPECT_EQ(f[0].node, "setup +Z / element 1 (closed_pocket)");
    EXPECT_NE(f[0].message.find("must-step fs (finish the walls)"), std::string::npos) << f[0].message;
    EXPECT_EQ(failures(c, "priority").size(), 0u);

    // The element listed as not machinable in that step is no failure: the chain says why.
    c.unmachined.push_back({1, StepCode::FinishWall, "kept for a later operation", {}});
    EXPECT_EQ(failures(checkChain(c), "existence").size(), 0u);

    // A must_not step that has units.
    c = smallChain();
    for (TemplateStep& s : c.processTemplate.steps)
        if (s.code == StepCode::SemiWall) s.existence = Existence::MustNot;
    c = checkChain(c);
    f = failures(c, "existence");
    ASSERT_EQ(f.size(), 3u);  // the ss units of elements 0, 1 and 3
    for (const RuleCheck& r : f) {
        EXPECT_NE(r.node.find("/ step ss / unit"), std::string::npos) << r.node;
        EXPECT_NE(r.message.find("must not exist"), std::string::npos) << r.message;
    }
}

TEST(ConstructionRules, ValidityFailsWhenDiametersOrAllowancesGrow) {
    MachiningChain c = smallChain();
    // Ids, not references: checkChain's result replaces c and its units.
    const int ss0 = unitOf(c, 0, StepCode::SemiWall).id;
    c.units[static_cast<std::size_t>(ss0)].radialAllowance = 0.8;  // after the corner unit at 0.5
    c = checkChain(c);
    auto f = failures(c, "validity");
    ASSERT_EQ(f.size(), 1u);
    EXPECT_NE(f[0].node.find("step ss / unit " + std::to_string(ss0)), std::string::npos) << f[0].node;
    EXPECT_NE(f[0].message.find("larger radial allowance (0.8 mm)"), std::string::npos) << f[0].message;

    // A wider tool after a narrower one (F8 finishing after F10 is fine, F10 after F8 is not).
    c = smallChain();
    c.units[static_cast<std::size_t>(unitOf(c, 3, StepCode::SemiWall).id)].tool = "F8";
    c = checkChain(c);
    f = failures(c, "validity");
    ASSERT_EQ(f.size(), 1u);
    EXPECT_NE(f[0].node.find("step fs"), std::string::npos) << f[0].node;
    EXPECT_NE(f[0].message.find("larger tool diameter (10 mm)"), std::string::npos) << f[0].message;
    // The edited tool's data came from the tool list.
    const MachiningUnit& ss3 = unitOf(c, 3, StepCode::SemiWall);
    EXPECT_DOUBLE_EQ(ss3.cutter.diameter, 8);
    EXPECT_DOUBLE_EQ(ss3.stepOver, 0.8);
    EXPECT_EQ(failures(c, "fit").size(), 0u);
}

TEST(ConstructionRules, RemovalFailsForAUnitThatCutsNothing) {
    // A finishing step after a roughing step with the same tool and allowances removes nothing.
    MachiningChain c = smallChain();
    c.units[static_cast<std::size_t>(unitOf(c, 1, StepCode::Web).id)].enabled = false;
    const int ss1 = unitOf(c, 1, StepCode::SemiWall).id;  // an id: c is replaced below
    c.units[static_cast<std::size_t>(ss1)].radialAllowance = 1.0;
    c.units[static_cast<std::size_t>(ss1)].axialAllowance = 0.5;
    c = checkChain(c);
    auto f = failures(c, "removal");
    ASSERT_EQ(f.size(), 1u);
    EXPECT_NE(f[0].node.find("step ss / unit " + std::to_string(ss1) + " (element 1)"), std::string::npos) << f[0].node;
    EXPECT_NE(f[0].message.find("removes no material: unit " + std::to_string(unitOf(c, 1, StepCode::Rough).id) +
                                " (step r, F10) already cut element 1"),
              std::string::npos)
        << f[0].message;
    EXPECT_EQ(failures(c, "validity").size(), 0u);

    // A rest unit whose tool is no smaller than the one before it.
    c = smallChain();
    c.units[static_cast<std::size_t>(unitOf(c, 0, StepCode::Rough).id)].tool = "F10";
    c = checkChain(c);
    f = failures(c, "removal");
    ASSERT_EQ(f.size(), 1u);
    EXPECT_NE(f[0].node.find("step c / unit"), std::string::npos) << f[0].node;
    EXPECT_NE(f[0].message.find("no smaller than the 10 mm tool before it"), std::string::npos) << f[0].message;

    // A rest unit after a tool that already fits the corners.
    c = smallChain();
    c.elements[0].minCornerRadius = 12;
    c = checkChain(c);
    f = failures(c, "removal");
    ASSERT_EQ(f.size(), 1u);
    EXPECT_NE(f[0].message.find("already fits the 12 mm corners"), std::string::npos) << f[0].message;
}

TEST(ConstructionRules, FitFailsForAToolThatDoesNotSuitItsElement) {
    MachiningChain c = smallChain();
    c.units[static_cast<std::size_t>(unitOf(c, 2, StepCode::Drill).id)].tool = "F8";
    c.units[static_cast<std::size_t>(unitOf(c, 0, StepCode::FinishWall).id)].tool = "R20";
    c.units[static_cast<std::size_t>(unitOf(c, 3, StepCode::Rough).id)].tool = "T99";
    c = checkChain(c);
    const auto f = failures(c, "fit");
    ASSERT_EQ(f.size(), 3u);
    std::string all;
    for (const RuleCheck& r : f) all += r.node + ": " + r.message + "\n";
    EXPECT_NE(all.find("tool F8 (D8) is a flat, not a drill"), std::string::npos) << all;
    EXPECT_NE(all.find("tool R20 (D20) is wider than the 6 mm corners of element 0"), std::string::npos) << all;
    EXPECT_NE(all.find("tool 'T99' is not in the chain's tool list"), std::string::npos) << all;
}

// A wall tool wider than the corners is accepted where the chain lists the corners it leaves
// (no tool of the crib fits them), up to the radius listed: a wider tool edited in still fails.
TEST(ConstructionRules, FitAcceptsTheCornersTheChainListsAsLeft) {
    MachiningChain c = smallChain();
    const MachiningUnit& wall = unitOf(c, 0, StepCode::FinishWall);
    const double r = 0.5 * wall.cutter.diameter;
    for (ChainElement& e : c.elements)
        if (e.id == 0) e.minCornerRadius = r - 1;
    c = checkChain(c);
    EXPECT_FALSE(failures(c, "fit").empty());
    Remainder left;
    left.element = 0;
    left.kind = "corners";
    left.tool = wall.tool;
    left.toolRadius = r;
    left.area = 1;
    left.depth = 15;
    left.needs = "an end mill of radius <= " + std::to_string(r - 1) + " mm";
    c.remainders.push_back(left);
    c = checkChain(c);
    for (const RuleCheck& rc : failures(c, "fit")) ADD_FAILURE() << rc.node << ": " << rc.message;
    EXPECT_EQ(toJson(fromJson(toJson(c))), toJson(c));
    c.units[static_cast<std::size_t>(unitOf(c, 0, StepCode::FinishWall).id)].tool = "R20";
    c = checkChain(c);
    bool wider = false;
    for (const RuleCheck& rc : failures(c, "fit")) wider |= rc.message.find("R20 (D20) is wider than") != std::string::npos;
    EXPECT_TRUE(wider);
}

TEST(ConstructionRules, CheckChainRefusesAnOrderThatIsNoPermutation) {
    MachiningChain c = smallChain();
    c.order.pop_back();
    EXPECT_NE(inputErrorOf([&] { checkChain(c); }).find("each must be listed once"), std::string::npos);
    c = smallChain();
    c.order[1] = c.order[0];
    EXPECT_NE(inputErrorOf([&] { checkChain(c); }).find("is listed twice"), std::string::npos);
}

TEST(ChainJson, RoundTripsAndRechecksAnEditedChain) {
    const MachiningChain c = smallChain();
    const std::string text = toJson(c);
    const MachiningChain back = fromJson(text);
    EXPECT_EQ(toJson(back), text);
    // Checking an unedited chain changes nothing.
    EXPECT_EQ(toJson(checkChain(back)), text);

    // The panel's edits arrive as JSON: disable a unit, re-check.
    auto j = nlohmann::json::parse(text);
    j["units"][unitOf(c, 1, StepCode::FinishWall).id]["enabled"] = false;
    const MachiningChain edited = checkChain(fromJson(j.dump()));
    EXPECT_EQ(failures(edited, "existence").size(), 1u);

    // Bad JSON names the field.
    j = nlohmann::json::parse(text);
    j["units"][3]["contour"][2] = "x";
    std::string e = inputErrorOf([&] { fromJson(j.dump()); });
    EXPECT_NE(e.find("units[3].contour[2]: is not an array"), std::string::npos) << e;
    j = nlohmann::json::parse(text);
    j["units"][0]["step"] = "zz";
    e = inputErrorOf([&] { fromJson(j.dump()); });
    EXPECT_NE(e.find("units[0]: unknown step code 'zz'"), std::string::npos) << e;
    j = nlohmann::json::parse(text);
    j["template"]["rules"][0]["rule"] = "random_order";
    e = inputErrorOf([&] { fromJson(j.dump()); });
    EXPECT_NE(e.find("unknown rule 'random_order'"), std::string::npos) << e;
    j = nlohmann::json::parse(text);
    j.erase("order");
    e = inputErrorOf([&] { fromJson(j.dump()); });
    EXPECT_NE(e.find("missing field 'order'"), std::string::npos) << e;
    EXPECT_NE(inputErrorOf([&] { fromJson("{"); }).find("not valid JSON"), std::string::npos);

    // Lower island tops (null: an island standing through) and the floor unit's facing survive.
    MachiningChain low = smallChain();
    MachiningUnit& u = low.units[0];
    u.islands = {{{1, 1}, {1, 2}, {2, 2}}, {{3, 3}, {3, 4}, {4, 4}}};
    u.islandTops = {std::nan(""), u.bottom + 1};
    u.faceIslandTops = true;
    const std::string lowText = toJson(low);
    const MachiningChain lowBack = fromJson(lowText);
    EXPECT_EQ(toJson(lowBack), lowText);
    ASSERT_EQ(lowBack.units[0].islandTops.size(), 2u);
    EXPECT_TRUE(std::isnan(lowBack.units[0].islandTops[0]));
    EXPECT_EQ(lowBack.units[0].islandTops[1], u.bottom + 1);
    EXPECT_TRUE(lowBack.units[0].faceIslandTops);
    j = nlohmann::json::parse(lowText);
    j["units"][0]["islandTops"].erase(0);
    e = inputErrorOf([&] { fromJson(j.dump()); });
    EXPECT_NE(e.find("units[0].islandTops: needs one height (or null) per island"), std::string::npos) << e;
}
