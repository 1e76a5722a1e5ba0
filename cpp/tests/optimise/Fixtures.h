#pragma once
// Shared inputs of the optimiser tests: the seed example as shipped, and a way to vary it.
#include <aeronc/optimise/ProblemJson.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace aeronc::optimise::test {

inline nlohmann::json seedJson() {
    const auto path = std::filesystem::path(AERONC_RESOURCES) / "optimise" / "xa5032_face_mill_45_steel.json";
    std::ifstream in(path);
    EXPECT_TRUE(in) << "cannot read " << path;
    return nlohmann::json::parse(in);
}

inline Parameters seedParameters() { return parseParameters(seedJson()); }
inline Problem seedProblem() { return seedParameters().problem; }

// The X5032-type gearbox's 18 speeds (r/min), for the stepped-spindle tests.
inline std::vector<double> x5032Steps() {
    return {30, 37.5, 47.5, 60, 75, 95, 118, 150, 190, 235, 300, 375, 475, 600, 750, 950, 1180, 1500};
}

}  // namespace aeronc::optimise::test
