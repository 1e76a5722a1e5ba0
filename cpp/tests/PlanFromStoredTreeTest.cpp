// Tool selection from the stored tree plans exactly what it planned from the part: the tree
// written as JSON and read back gives the same plan JSON, on the sample panel (both sides) and
// on a NIST part.
#include <aeronc/brep/PartIO.h>
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/kb/ToolPlanning.h>
#include <aeronc/recognition/DomainTreeJson.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/toolselect/PlanJson.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace aeronc;

namespace {

class PlanFromStoredTree : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("aeronc_stored_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    // The plan of the part as recognised, and the plan of its tree after a trip through JSON.
    void expectSamePlan(const std::string& part, const recognition::RecogniseOptions& options,
                        std::size_t minElements) {
        const auto kb = kb::KnowledgeBase::openWithSqlFolder((dir_ / "kb.sqlite").string(),
                                                             [] { return (fs::path(AERONC_RESOURCES) / "kb").string(); });
        const std::string material = "7050-T7451", machine = "AC-5AX";
        const recognition::DomainTree tree = recognition::recognise(loadPart(part), options);
        const toolselect::ToolPlan direct = kb::planTools(tree, kb, material, machine);
        const recognition::DomainTree stored = recognition::fromJson(recognition::toJson(tree, -1));
        const toolselect::ToolPlan fromStored = kb::planTools(stored, kb, material, machine);
        EXPECT_EQ(toolselect::toJson(fromStored, material), toolselect::toJson(direct, material));

        // The plan is not trivially equal: it has elements and tools.
        EXPECT_GE(direct.elements.size() + direct.holes.size(), minElements);
        int tooled = 0;
        for (const auto& c : direct.elements) tooled += c.roughingTool >= 0;
        EXPECT_GT(tooled, 0);
    }

    fs::path dir_;
};

}  // namespace

TEST_F(PlanFromStoredTree, SamplePanelBothSides) {
    recognition::RecogniseOptions o;
    o.directions = {{0, 0, 1}, {0, 0, -1}};
    expectSamePlan((fs::path(AERONC_RESOURCES) / "samples" / "sample_panel.step").string(), o, 10);
}

TEST_F(PlanFromStoredTree, NistFtc07) {
    const fs::path part = fs::path(AERONC_SHARED_DATA) / "nist" / "nist_ftc_07_asme1_rd.stp";
    if (!fs::exists(part)) GTEST_SKIP() << "no " << part;
    expectSamePlan(part.string(), {}, 10);
}
