// Bad input to the chain, each with a clear message: a part with no domain element, a
// template missing must-steps, a broken rule, and an element no tool of the knowledge base
// can machine (listed with the reason, not fatal). A tool that removes nothing is the removal
// rule's failure (ConstructionRulesTest).
#include "ErrorOf.h"
#include "Fixtures.h"

#include <aeronc/brep/PartIO.h>
#include <aeronc/kb/ProcessTemplates.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/PanelGenerator.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <gtest/gtest.h>

using namespace aeronc;
using namespace aeronc::chain;
using aeronc::test::inputErrorOf;

TEST(ChainBadInput, APartWithNoDomainElement) {
    // A plain block: recognition finds nothing and says so; a tree without elements (read from
    // a file, say) stops the chain with its own message.
    std::string e = inputErrorOf([] { recognition::recognise(BRepPrimAPI_MakeBox(100, 50, 20).Solid(), {}); });
    EXPECT_NE(e.find("no machining feature found"), std::string::npos) << e;
    recognition::DomainTree tree;
    tree.setups = {{0, {0, 0, 1}, "+Z", {}}};
    const test::KbDir dir("empty");
    const auto kb = dir.open();
    e = inputErrorOf([&] { kb::planChain(tree, kb, "7050-T7451"); });
    EXPECT_NE(e.find("the part has no domain element"), std::string::npos) << e;
    e = inputErrorOf([&] { buildChain(tree, test::smallPlan(), parseTemplate(test::panelRows()), test::smallOptions()); });
    EXPECT_NE(e.find("no domain element"), std::string::npos) << e;
}

TEST(ChainBadInput, ATemplateMissingMustStepsOrWithABrokenRuleStopsThePlan) {
    const test::KbDir dir("template");
    auto kb = dir.open();
    const auto tree = test::smallTree();
    auto rows = test::panelRows();
    rows.steps.erase(rows.steps.begin() + 5);  // no fs
    ProcessTemplate t;
    t.name = "no walls";
    t.family = "integral_panel";
    t.requiredSteps = {StepCode::Rough, StepCode::Web, StepCode::FinishWall};
    t.stepOrder = parseStepCodes(rows.stepOrder, "order");
    for (const auto& s : parseTemplate(test::panelRows()).steps)
        if (s.code != StepCode::FinishWall) t.steps.push_back(s);
    std::string e = inputErrorOf([&] { buildChain(tree, test::smallPlan(), t, test::smallOptions()); });
    EXPECT_NE(e.find("process template 'no walls' lacks the must-step fs"), std::string::npos) << e;

    // Through the knowledge base: a rule edited into nonsense.
    const auto table = kb.table("sequencing_rule");
    long long row = -1;
    for (std::size_t i = 0; i < table.rows.size(); ++i)
        if (table.rows[i][1] == std::string("integral_panel") && table.rows[i][3] == std::string("outer_before_inner"))
            row = table.rowIds[i];
    kb.editTable("sequencing_rule", {{row, "parameters", std::string("outer=")}});
    e = inputErrorOf([&] { kb::planChain(tree, kb, "7050-T7451"); });
    EXPECT_NE(e.find("sequencing rule 2 (outer_before_inner)"), std::string::npos) << e;
    EXPECT_NE(e.find("names no feature type"), std::string::npos) << e;
}

TEST(ChainBadInput, CornersNoToolFitsAreListedAsWhatTheMachinedPocketKeeps) {
    // Pocket corners of radius 0.2 mm: no shipped end mill (the smallest is 0.5 mm) finishes them.
    // The pockets are roughed and finished with the smallest tool; the corners are listed with
    // the tool they would need, and the pockets are not listed as not machined.
    testparts::PanelSpec s;
    s.pocketsX = 2;
    s.pocketsY = 1;
    s.cornerRadius = 0.2;
    s.lowerRibs = s.islands = s.openings = s.lighteningHoles = s.boltHoles = false;
    s.joggles = s.flange = s.bottomPockets = false;
    recognition::RecogniseOptions o;
    o.directions = {{0, 0, 1}};
    const auto tree = recognition::recognise(validatedSolid(testparts::makePanel(s).shape, "panel"), o);
    const test::KbDir dir("unmachinable");
    const auto kb = dir.open();
    const MachiningChain c = kb::planChain(tree, kb, "7050-T7451");
    int pockets = 0;
    for (const auto& e : tree.elements) {
        if (e.type != recognition::ElementType::ClosedPocket) continue;
        ++pockets;
        bool listed = false, roughed = false, finished = false;
        for (const Unmachined& m : c.unmachined) EXPECT_NE(m.element, e.id) << m.reason;
        for (const Remainder& r : c.remainders)
            if (r.element == e.id && r.kind == "corners") {
                listed = true;
                EXPECT_NE(r.needs.find("radius <= 0.2 mm"), std::string::npos) << r.needs;
                EXPECT_GT(r.area, 0);
            }
        for (const MachiningUnit& u : c.units) {
            roughed |= u.element == e.id && u.step == StepCode::Rough;
            finished |= u.element == e.id && u.step == StepCode::FinishWall;
        }
        EXPECT_TRUE(listed) << "element " << e.id;
        EXPECT_TRUE(roughed) << "element " << e.id;
        EXPECT_TRUE(finished) << "element " << e.id;
    }
    EXPECT_EQ(pockets, 2);
    for (const RuleCheck& r : c.checks) EXPECT_TRUE(r.ok) << r.node << ": " << r.message;
}
