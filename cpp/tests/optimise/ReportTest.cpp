// The comparison report: the rows it promises, the baseline correction, and JSON that a
// program can read back.
#include "Fixtures.h"

#include <aeronc/optimise/Report.h>

using namespace aeronc::optimise;

TEST(Report, SeedComparisonHasEveryRow) {
    const Comparison c = compare(test::seedParameters(), Method::Both);
    ASSERT_TRUE(c.deterministic);
    ASSERT_TRUE(c.genetic);
    ASSERT_EQ(c.references.size(), 2u);
    const std::string text = toText(c);
    for (const char* part : {"paper: MATLAB GA", "paper: UG module", "ours: scan+SLSQP", "ours: genetic algorithm",
                             "handbook (T = 180 min)", "speed corrected to limits", "printed fitness 0.148",
                             "active at the optimum (scan+SLSQP): cutting power P_max, roughness R_a R_a,max"})
        EXPECT_NE(text.find(part), std::string::npos) << part << "\n" << text;
}

// The handbook speed at T = 180 min overloads the 7.5 kW spindle; kept at its f_z, the
// corrected speed runs the spindle at exactly its power limit.
TEST(Report, HandbookBaselineIsCorrectedToThePowerLimit) {
    const Comparison c = compare(test::seedParameters(), Method::Deterministic);
    ASSERT_TRUE(c.baseline);
    const auto& b = *c.baseline;
    EXPECT_NEAR(b.asGiven.at.toolLife, 180, 1e-6);
    EXPECT_FALSE(b.asGiven.feasible);
    EXPECT_GT(b.asGiven.at.power, 7.5);
    ASSERT_TRUE(b.corrected);
    EXPECT_TRUE(b.corrected->feasible);
    EXPECT_NEAR(b.corrected->at.power, 7.5, 1e-6);
    EXPECT_EQ(b.corrected->fz, 0.15);
    // The optimum is no worse than the corrected handbook point on either objective.
    EXPECT_LE(c.deterministic->combined.at.time, b.corrected->at.time);
    EXPECT_LE(c.deterministic->combined.at.cost, b.corrected->at.cost);
}

TEST(Report, JsonCarriesTheOptimumAndItsActiveLimits) {
    const Comparison c = compare(test::seedParameters(), Method::Deterministic);
    const nlohmann::json j = nlohmann::json::parse(toJson(c).dump());
    const auto& o = j.at("deterministic").at("optimum");
    EXPECT_DOUBLE_EQ(o.at("n_rpm").get<double>(), c.deterministic->combined.n);
    EXPECT_DOUBLE_EQ(o.at("f_z_mm").get<double>(), c.deterministic->combined.fz);
    EXPECT_EQ(o.at("active").size(), 2u);
    EXPECT_EQ(o.at("constraints").size(), 8u);
    EXPECT_FALSE(j.contains("genetic"));
    EXPECT_EQ(j.at("references").size(), 2u);
    EXPECT_TRUE(j.at("baseline").contains("speed_corrected"));
}
