// The machining chain takes the tool plan Select tools stored (its JSON) as it is: the planner's
// plan gives the chain planning again gives; a plan whose tools were changed gives units with
// those tools; a plan that no longer fits the knowledge base or the tree is refused by name.
#include "ErrorOf.h"
#include "Fixtures.h"

#include <aeronc/brep/PartIO.h>
#include <aeronc/chain/ChainJson.h>
#include <aeronc/kb/ProcessTemplates.h>
#include <aeronc/kb/ToolPlanning.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/toolselect/PlanJson.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <set>

using namespace aeronc;
using namespace aeronc::chain;

namespace {

const std::string kMaterial = "7050-T7451", kMachine = "AC-5AX";

const test::KbDir& kbDir() {
    static const test::KbDir dir("storedplan");
    return dir;
}

const recognition::DomainTree& samplePanel() {
    static const recognition::DomainTree tree =
        recognition::recognise(loadPart(AERONC_RESOURCES "/samples/sample_panel.step"), {});
    return tree;
}

}  // namespace

TEST(StoredToolPlan, ThePlannersPlanGivesTheChainPlanningGives) {
    const auto& tree = samplePanel();
    const auto kb = kbDir().open();
    const std::string text = toolselect::toJson(kb::planTools(tree, kb, kMaterial, kMachine), kMaterial);
    const toolselect::ToolPlan stored = kb::storedToolPlan(kb, text, kMaterial);
    EXPECT_EQ(toolselect::toJson(stored, kMaterial), text);  // read back whole
    const MachiningChain fromStored = kb::planChain(tree, kb, stored, kMaterial, kMachine);
    EXPECT_GT(fromStored.units.size(), 100u);
    EXPECT_EQ(toJson(fromStored), toJson(kb::planChain(tree, kb, kMaterial, kMachine)));
}

// The user's plan, not a new one: an element's finishing tool changed in the stored plan to a
// smaller flat end mill that also finishes it; its wall units are cut with that tool.
TEST(StoredToolPlan, TheChainTakesTheStoredToolsNotAFreshPlan) {
    const auto& tree = samplePanel();
    const auto kb = kbDir().open();
    const toolselect::ToolPlan planned = kb::planTools(tree, kb, kMaterial, kMachine);
    auto j = nlohmann::json::parse(toolselect::toJson(planned, kMaterial));
    const auto tools = kb.tools();
    auto toolOf = [&](const std::string& id) {
        for (const auto& t : tools)
            if (t.id == id) return t;
        ADD_FAILURE() << "no tool " << id;
        return toolselect::Tool{};
    };
    // A closed pocket with both tools, and the largest flat end mill narrower than its finishing
    // tool that reaches its depth and has finishing data.
    int element = -1;
    std::string was, now;
    for (auto& e : j["elements"]) {
        if (e["type"] != "closed_pocket" || e["finishingTool"].is_null() || e["roughingTool"].is_null()) continue;
        const auto f = toolOf(e["finishingTool"].get<std::string>());
        const recognition::DomainElement* de = nullptr;
        for (const auto& x : tree.elements)
            if (x.id == e["id"].get<int>()) de = &x;
        ASSERT_NE(de, nullptr);
        double best = 0;
        for (const auto& t : tools)
            if (t.type == "flat" && t.diameter < f.diameter - 1e-9 && t.diameter > best && t.diameter >= 4 &&
                t.usableLength() > de->depth + 1 &&
                kb.findCuttingCondition(kMaterial, t.material, "finishing", t.diameter))
                best = t.diameter, now = t.id;
        if (best > 0) {
            element = e["id"].get<int>(), was = f.id;
            e["finishingTool"] = now;
            break;
        }
    }
    ASSERT_GE(element, 0) << "no pocket whose finishing tool has a smaller one to take its place";
    auto wallTools = [&](const MachiningChain& c) {
        std::set<std::string> out;
        for (const auto& u : c.units)
            if (u.element == element && u.step == StepCode::FinishWall) out.insert(u.tool);
        return out;
    };
    const MachiningChain fresh = kb::planChain(tree, kb, kMaterial, kMachine);
    const MachiningChain stored = kb::planChain(tree, kb, kb::storedToolPlan(kb, j.dump(), kMaterial), kMaterial, kMachine);
    EXPECT_EQ(wallTools(fresh), (std::set<std::string>{was})) << "element " << element;
    EXPECT_EQ(wallTools(stored), (std::set<std::string>{now})) << "element " << element;
}

TEST(StoredToolPlan, APlanThatNoLongerFitsIsRefusedByName) {
    const auto& tree = samplePanel();
    const auto kb = kbDir().open();
    const toolselect::ToolPlan planned = kb::planTools(tree, kb, kMaterial, kMachine);
    const std::string text = toolselect::toJson(planned, kMaterial);
    auto edited = [&](const std::function<void(nlohmann::json&)>& edit) {
        auto j = nlohmann::json::parse(text);
        edit(j);
        return j.dump();
    };
    using test::inputErrorOf;
    EXPECT_NE(inputErrorOf([&] { kb::storedToolPlan(kb, text, "2024-T3"); })
                  .find("the tool plan was made for '7050-T7451', not '2024-T3'; select tools again"),
              std::string::npos);
    EXPECT_NE(inputErrorOf([&] { kb::storedToolPlan(kb, "{", kMaterial); }).find("tool plan JSON: not valid JSON"),
              std::string::npos);
    std::size_t k = 0;  // an element with both tools
    while (k < planned.elements.size() && (planned.elements[k].finishingTool < 0 || planned.elements[k].roughingTool < 0)) ++k;
    ASSERT_LT(k, planned.elements.size());
    const std::string first = planned.tools.at(static_cast<std::size_t>(planned.elements[k].finishingTool)).id;
    // A tool the knowledge base no longer has, and one whose dimensions changed.
    const std::string gone = edited([&](nlohmann::json& j) {
        j["elements"][k]["finishingTool"] = "NO-SUCH-TOOL";
        j["tools"]["NO-SUCH-TOOL"] = j["tools"][first];
    });
    EXPECT_NE(inputErrorOf([&] { kb::storedToolPlan(kb, gone, kMaterial); })
                  .find("names tool NO-SUCH-TOOL, which the knowledge base no longer has"),
              std::string::npos);
    const std::string changed = edited([&](nlohmann::json& j) { j["tools"][first]["diameter"] = 99.5; });
    EXPECT_NE(inputErrorOf([&] { kb::storedToolPlan(kb, changed, kMaterial); })
                  .find("tool " + first + " changed since the tool plan was made"),
              std::string::npos);
    EXPECT_NE(inputErrorOf([&] { kb::storedToolPlan(kb, edited([&](nlohmann::json& j) { j["elements"][k]["eta"] = "x"; }),
                                                     kMaterial); })
                  .find("tool plan JSON elements[" + std::to_string(k) + "].eta: is not a number"),
              std::string::npos);
    // A plan of another tree.
    const std::string stranger = edited([](nlohmann::json& j) { j["elements"][0]["id"] = 9999; });
    EXPECT_NE(inputErrorOf([&] { kb::planChain(tree, kb, kb::storedToolPlan(kb, stranger, kMaterial), kMaterial); })
                  .find("the tool plan names element 9999, which the recognised tree does not have"),
              std::string::npos);
}
