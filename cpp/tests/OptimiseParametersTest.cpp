// The knowledge base as the optimiser's source: the cutting condition's coefficients, the
// machine's limits and the tool reach the optimiser unchanged, the file's own values win,
// and bad names are refused clearly.
#include "ErrorOf.h"

#include <aeronc/core/Error.h>
#include <aeronc/core/TextFile.h>
#include <aeronc/kb/OptimiseParameters.h>
#include <aeronc/optimise/Report.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <unistd.h>

namespace fs = std::filesystem;
using aeronc::kb::KnowledgeBase;
using namespace aeronc::optimise;
using aeronc::readTextFile;
using aeronc::test::errorOf;

namespace {

class OptimiseParametersTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("aeronc-optkb-" + std::to_string(getpid()));
        fs::create_directories(dir_);
        const std::string res = AERONC_RESOURCES;
        kb_.emplace(KnowledgeBase::open((dir_ / "kb.sqlite").string(), readTextFile(res + "/kb/schema.sql", "schema"),
                                        readTextFile(res + "/kb/default_data.sql", "default data")));
        params_ = nlohmann::json::parse(readTextFile(res + "/optimise/kb_45_steel_face_mill.json", "parameter file"));
    }
    void TearDown() override {
        kb_.reset();
        fs::remove_all(dir_);
    }
    fs::path dir_;
    std::optional<KnowledgeBase> kb_;
    nlohmann::json params_;
};

}  // namespace

TEST_F(OptimiseParametersTest, CoefficientsComeFromTheKnowledgeBase) {
    const auto cc = kb_->cuttingCondition("45 steel", "carbide", "roughing");
    const auto m = kb_->machine("XA5032");
    const Parameters p = parseParameters(aeronc::kb::withKnowledgeBase(*kb_, params_));
    const Problem& q = p.problem;
    EXPECT_EQ(q.force.cF, cc.cF);
    EXPECT_EQ(q.force.yF, cc.yF);
    EXPECT_EQ(q.force.wF, cc.wF);
    EXPECT_EQ(q.force.kFc, cc.kFc);
    EXPECT_EQ(q.toolLife.cV, cc.taylorC);
    EXPECT_EQ(q.toolLife.m, cc.taylorM);
    EXPECT_EQ(q.toolLife.yV, 0.0);  // the plain Taylor law
    EXPECT_EQ(q.machine.power, m.powerKw);
    EXPECT_EQ(q.machine.maxSpindle, m.maxSpindleRpm);
    EXPECT_EQ(q.machine.maxFeed, m.maxFeedMmMin);
    EXPECT_EQ(q.machine.maxForce, m.maxForceN);
    EXPECT_EQ(q.machine.efficiency, m.efficiency);
    EXPECT_EQ(q.economics.toolChangeTime, m.toolChangeS / 60);
    EXPECT_EQ(q.cutter.diameter, 125);  // tool FM-125
    EXPECT_EQ(q.cutter.teeth, 4);
    EXPECT_EQ(q.cutter.cornerRadius, 1);
    EXPECT_EQ(q.cut.depth, cc.ap);
    EXPECT_EQ(q.cut.width, cc.aeRatio * 125);
    EXPECT_EQ(q.cut.length, 640);  // from the file
    EXPECT_EQ(q.quality.raMax, kb_->threshold("ra_max_um"));
    ASSERT_TRUE(p.baseline);
    EXPECT_EQ(*p.baseline->cuttingSpeed, cc.vc);
    EXPECT_EQ(p.baseline->fz, cc.fz);

    const Solution s = solve(q);
    EXPECT_TRUE(s.combined.feasible);
    EXPECT_FALSE(s.combined.activeConstraints().empty());
}

TEST_F(OptimiseParametersTest, TheFilesValuesWin) {
    params_["force"] = {{"K_Fc", 0.935}};
    params_["machine"]["power_kw"] = 5.5;
    params_["baseline"] = {{"label", "mine"}, {"f_z_mm", 0.1}, {"n_rpm", 300}};
    const Parameters p = parseParameters(aeronc::kb::withKnowledgeBase(*kb_, params_));
    EXPECT_EQ(p.problem.force.kFc, 0.935);
    EXPECT_EQ(p.problem.force.cF, 825);  // the rest of the section still from the knowledge base
    EXPECT_EQ(p.problem.machine.power, 5.5);
    EXPECT_EQ(*p.baseline->n, 300);
    EXPECT_FALSE(p.baseline->cuttingSpeed);
}

TEST_F(OptimiseParametersTest, BadNamesAreRefused) {
    auto with = [&](const char* key, const char* value) {
        nlohmann::json j = params_;
        j["kb"][key] = value;
        return errorOf([&] { aeronc::kb::withKnowledgeBase(*kb_, j); });
    };
    EXPECT_NE(with("workpiece_material", "unobtainium").find("unobtainium"), std::string::npos);
    EXPECT_NE(with("machine", "XB9999").find("XB9999"), std::string::npos);
    EXPECT_NE(with("tool", "NOPE").find("unknown tool 'NOPE'"), std::string::npos);
    EXPECT_NE(with("tool_material", "HSS").find("is carbide, not HSS"), std::string::npos);
    nlohmann::json j = params_;
    j.erase("kb");
    EXPECT_NE(errorOf([&] { aeronc::kb::withKnowledgeBase(*kb_, j); }).find("\"kb\" section"), std::string::npos);
}

TEST_F(OptimiseParametersTest, CuttingDataByDiameterFollowsTheCutter) {
    // Aluminium roughing data is given by diameter range: a 12 mm and a 32 mm cutter get
    // different a_p (and baseline f_z), each the row its diameter falls in.
    nlohmann::json j = {{"kb", {{"workpiece_material", "7050-T7451"}, {"tool_material", "carbide"},
                                {"operation", "roughing"}, {"machine", "XA5032"}}}};
    for (double d : {12.0, 32.0}) {
        j["cutter"] = {{"diameter_mm", d}, {"teeth", 3}, {"corner_radius_mm", 1}};
        const auto cc = kb_->cuttingCondition("7050-T7451", "carbide", "roughing", d);
        const auto out = aeronc::kb::withKnowledgeBase(*kb_, j);
        EXPECT_EQ(out["cut"]["a_p_mm"].get<double>(), cc.ap) << d;
        EXPECT_EQ(out["baseline"]["f_z_mm"].get<double>(), cc.fz) << d;
    }
    EXPECT_NE(kb_->cuttingCondition("7050-T7451", "carbide", "roughing", 12.0).ap,
              kb_->cuttingCondition("7050-T7451", "carbide", "roughing", 32.0).ap);
    // Without any diameter, ranged data cannot be chosen, and the message says what is missing.
    j.erase("cutter");
    EXPECT_FALSE(errorOf([&] { aeronc::kb::withKnowledgeBase(*kb_, j); }).empty());
}
