#pragma once
// Runs the chosen methods on a parameter set and lays the answers side by side with the
// published points and the handbook baseline: a text table for people, JSON for programs.
#include <aeronc/optimise/Genetic.h>
#include <aeronc/optimise/ProblemJson.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace aeronc::optimise {

enum class Method { Deterministic, Genetic, Both };
// "nlopt", "ga" or "both"; anything else is an inputError.
Method parseMethod(const std::string& s);

// The baseline at its own speed, and (when that breaks a limit) at the nearest speed that
// keeps its f_z and meets every limit, as a handbook user would correct it.
struct BaselineResult {
    BaselineSpec spec;
    Optimum asGiven;
    std::optional<Optimum> corrected;
    std::string note;  // why there is no correction, if there is none
};

struct Comparison {
    Parameters parameters;
    std::optional<Solution> deterministic;
    std::optional<Solution> genetic;
    std::vector<Optimum> references;  // the reference points evaluated in our model
    std::optional<BaselineResult> baseline;

    // The solution the fitness of the other rows is normalised with: deterministic if run.
    const Solution& primary() const { return deterministic ? *deterministic : *genetic; }
};

Comparison compare(const Parameters& params, Method method, const GeneticOptions& ga = {});

std::string toText(const Comparison& c);
nlohmann::json toJson(const Comparison& c);

}  // namespace aeronc::optimise
