// Process templates and sequencing rules: parsed and checked from the knowledge base's rows;
// a template missing its family's must-steps, out of its step order, or with a broken rule
// is refused with a message naming the template and the row.
#include "ErrorOf.h"
#include "Fixtures.h"

#include <aeronc/chain/ProcessTemplate.h>
#include <aeronc/core/Error.h>
#include <aeronc/kb/ProcessTemplates.h>

#include <gtest/gtest.h>

using namespace aeronc;
using namespace aeronc::chain;
using aeronc::test::inputErrorOf;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(ProcessTemplate, ShippedPanelTemplateParses) {
    const ProcessTemplate t = parseTemplate(test::panelRows());
    EXPECT_EQ(t.name, "integral_panel");
    ASSERT_EQ(t.steps.size(), 9u);
    EXPECT_EQ(t.steps[0].code, StepCode::Rough);
    EXPECT_EQ(t.steps[0].role, ToolRole::Roughing);
    EXPECT_DOUBLE_EQ(t.steps[0].radialAllowance, 1.0);
    EXPECT_TRUE(t.steps[0].machines("opening"));
    EXPECT_FALSE(t.steps[1].machines("opening"));  // w: an opening has no floor
    EXPECT_EQ(t.rank(StepCode::Corner), 2);
    EXPECT_EQ(t.rank(StepCode::FinishWall), 5);
    ASSERT_EQ(t.rules.size(), 5u);
    EXPECT_EQ(t.rules[1].kind, RuleKind::OuterBeforeInner);
    EXPECT_EQ(t.rules[1].featureTypes, (std::vector<std::string>{"open_pocket", "flange"}));
    EXPECT_EQ(t.rules[3].featureTypes.size(), 5u);
}

TEST(ProcessTemplate, MissingMustStepsAreNamed) {
    auto rows = test::panelRows();
    rows.steps.erase(rows.steps.begin() + 1);  // no w
    std::string e = inputErrorOf([&] { parseTemplate(rows); });
    EXPECT_TRUE(has(e, "process template 'integral_panel' lacks the must-step w (finish the webs (floors))")) << e;
    EXPECT_TRUE(has(e, "part family 'integral_panel' requires")) << e;

    rows = test::panelRows();
    rows.steps[5].existence = "may";  // fs no longer a must
    e = inputErrorOf([&] { parseTemplate(rows); });
    EXPECT_TRUE(has(e, "must-step fs")) << e;
    EXPECT_TRUE(has(e, "marked may")) << e;
}

TEST(ProcessTemplate, StepsFollowTheChosenOrder) {
    auto rows = test::panelRows();
    std::swap(rows.steps[2].position, rows.steps[3].position);  // ss before c
    std::string e = inputErrorOf([&] { parseTemplate(rows); });
    EXPECT_TRUE(has(e, "step c comes after step ss, against its step order 'standard'")) << e;
    // ... which the alternative order allows, with c after sf too.
    rows.stepOrderName = "corners_late";
    rows.stepOrder = "r w ss sf c fs ff d h t";
    for (auto& s : rows.steps) {
        if (s.code == "ss") s.position = 3;
        if (s.code == "sf") s.position = 4;
        if (s.code == "c") s.position = 5;
    }
    // c after ss with the same radial allowance (0.5 > 0.2 would grow): give c the smaller one.
    for (auto& s : rows.steps)
        if (s.code == "c") s.radialAllowance = 0.2;
    EXPECT_NO_THROW(parseTemplate(rows));

    rows = test::panelRows();
    rows.stepOrder = "r w c ss sf fs ff h t";  // no d
    e = inputErrorOf([&] { parseTemplate(rows); });
    EXPECT_TRUE(has(e, "step d is not in its step order 'standard'")) << e;
}

TEST(ProcessTemplate, BadStepRowsAreNamed) {
    auto rows = test::panelRows();
    rows.steps[3].code = "xx";
    std::string e = inputErrorOf([&] { parseTemplate(rows); });
    EXPECT_TRUE(has(e, "step at position 4: unknown step code 'xx'")) << e;

    rows = test::panelRows();
    rows.steps[0].features = "closed_pocket slot";
    e = inputErrorOf([&] { parseTemplate(rows); });
    EXPECT_TRUE(has(e, "unknown feature type 'slot'")) << e;

    rows = test::panelRows();
    rows.steps[7].role = "finishing";  // d with a milling role
    e = inputErrorOf([&] { parseTemplate(rows); });
    EXPECT_TRUE(has(e, "step d: tool role 'finishing' cannot drill")) << e;

    rows = test::panelRows();
    rows.steps[1].features = "";  // w, a must-step, machining nothing
    e = inputErrorOf([&] { parseTemplate(rows); });
    EXPECT_TRUE(has(e, "step w is 'must' but names no feature type")) << e;

    rows = test::panelRows();
    rows.steps[5].radialAllowance = 0.4;  // fs leaves more than ss (0.2)
    e = inputErrorOf([&] { parseTemplate(rows); });
    EXPECT_TRUE(has(e, "step fs: on closed_pocket it leaves 0.4 mm radial")) << e;
    EXPECT_TRUE(has(e, "more than step ss before it")) << e;
}

TEST(ProcessTemplate, BrokenRulesAreNamed) {
    struct Case {
        std::string key, parameters, expected;
    };
    const Case cases[] = {
        {"lowest_first", "", "unknown rule 'lowest_first'"},
        {"process_order", "order=random", "order='random' is neither larger_tool_first nor smaller_tool_first"},
        {"feature_type_order", "order=closed_pocket,slot", "unknown feature type 'slot'"},
        {"feature_type_order", "", "needs order=<feature types>"},
        {"feature_type_order", "order=hole,hole", "feature type 'hole' is listed twice"},
        {"outer_before_inner", "outer", "parameter 'outer' is not name=value"},
        {"higher_z_first", "by=level", "rule higher_z_first takes no parameter 'by'"},
    };
    for (const Case& c : cases) {
        auto rows = test::panelRows();
        rows.rules[3] = {4, c.key, c.parameters, true};
        const std::string e = inputErrorOf([&] { parseTemplate(rows); });
        EXPECT_TRUE(has(e, "process template 'integral_panel', sequencing rule 4 (" + c.key + ")")) << e;
        EXPECT_TRUE(has(e, c.expected)) << c.key << " " << c.parameters << ": " << e;
        // Disabled, the same row is only kept for review.
        rows.rules[3].enabled = false;
        EXPECT_NO_THROW(parseTemplate(rows)) << c.key;
    }
    auto rows = test::panelRows();
    rows.rules.push_back({4, "centre_out", "", true});
    EXPECT_TRUE(has(inputErrorOf([&] { parseTemplate(rows); }), "two sequencing rules have priority 4"));
}

TEST(ProcessTemplate, KnowledgeBaseTemplatesLoadAndValidate) {
    const test::KbDir dir("templates");
    const auto kb = dir.open();
    EXPECT_EQ(kb::processTemplateNames(kb), (std::vector<std::string>{"frame_beam", "integral_panel", "rib"}));
    const ProcessTemplate panel = kb::loadProcessTemplate(kb, "integral_panel");
    const ProcessTemplate fromRows = parseTemplate(test::panelRows());
    ASSERT_EQ(panel.steps.size(), fromRows.steps.size());
    for (std::size_t i = 0; i < panel.steps.size(); ++i) {
        EXPECT_EQ(panel.steps[i].code, fromRows.steps[i].code);
        EXPECT_EQ(panel.steps[i].existence, fromRows.steps[i].existence);
        EXPECT_EQ(panel.steps[i].features, fromRows.steps[i].features);
        EXPECT_EQ(panel.steps[i].role, fromRows.steps[i].role);
        EXPECT_DOUBLE_EQ(panel.steps[i].radialAllowance, fromRows.steps[i].radialAllowance);
        EXPECT_DOUBLE_EQ(panel.steps[i].axialAllowance, fromRows.steps[i].axialAllowance);
    }
    EXPECT_EQ(panel.rules.size(), 5u);

    const ProcessTemplate frame = kb::loadProcessTemplate(kb, "frame_beam");
    EXPECT_EQ(frame.stepOrderName, "corners_late");
    EXPECT_LT(frame.rank(StepCode::SemiWall), frame.rank(StepCode::Corner));
    const ProcessTemplate rib = kb::loadProcessTemplate(kb, "rib");
    ASSERT_NE(rib.step(StepCode::SemiFlange), nullptr);
    EXPECT_EQ(rib.step(StepCode::SemiFlange)->existence, Existence::MustNot);

    const std::string e = inputErrorOf([&] { kb::loadProcessTemplate(kb, "impeller"); });
    EXPECT_TRUE(has(e, "no process template or part family 'impeller'")) << e;
    EXPECT_TRUE(has(e, "'frame_beam', 'integral_panel', 'rib'")) << e;
}

TEST(ProcessTemplate, KnowledgeBaseEditsThatBreakATemplateAreNamed) {
    const test::KbDir dir("broken");
    auto kb = dir.open();
    auto rowOf = [&](const std::string& table, const std::string& templateName, const std::string& column,
                     const std::string& value) {
        const auto t = kb.table(table);
        std::size_t tc = 0, vc = 0;
        for (std::size_t c = 0; c < t.columns.size(); ++c) {
            if (t.columns[c].name == "template") tc = c;
            if (t.columns[c].name == column) vc = c;
        }
        for (std::size_t i = 0; i < t.rows.size(); ++i)
            if (t.rows[i][tc] == templateName && t.rows[i][vc] == value) return t.rowIds[i];
        ADD_FAILURE() << "no row " << value;
        return -1LL;
    };
    // A broken rule, written through the editor.
    kb.editTable("sequencing_rule", {{rowOf("sequencing_rule", "rib", "priority", "4"), "parameters", std::string("order=pocket")}});
    std::string e = inputErrorOf([&] { kb::loadProcessTemplate(kb, "rib"); });
    EXPECT_TRUE(has(e, "process template 'rib', sequencing rule 4 (feature_type_order)")) << e;
    EXPECT_TRUE(has(e, "unknown feature type 'pocket'")) << e;
    EXPECT_NO_THROW(kb::loadProcessTemplate(kb, "integral_panel"));  // the others are untouched

    // A must-step deleted.
    kb.editTable("template_step", {}, {}, {rowOf("template_step", "frame_beam", "code", "ss")});
    e = inputErrorOf([&] { kb::loadProcessTemplate(kb, "frame_beam"); });
    EXPECT_TRUE(has(e, "process template 'frame_beam' lacks the must-step ss")) << e;

    // The database itself refuses an unknown step code or existence.
    e = inputErrorOf([&] {
        kb.editTable("template_step", {{rowOf("template_step", "integral_panel", "code", "c"), "code", std::string("q")}});
    });
    EXPECT_TRUE(has(e, "nothing was changed")) << e;
}
