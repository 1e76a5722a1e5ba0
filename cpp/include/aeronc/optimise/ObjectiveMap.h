#pragma once
// The combined objective sampled over a log grid of (n, f_z), with the feasible region and the
// limit curves, for plotting the optimiser's answer. The grid is for people to look at; the
// solver never uses it.
#include <aeronc/optimise/Solver.h>

#include <nlohmann/json.hpp>

namespace aeronc::optimise {

struct MapBox {
    // Zero: chosen around the optimum, a factor `spread` each way, clipped to the spindle
    // range and the f_z search range.
    double nLow = 0, nHigh = 0, fzLow = 0, fzHigh = 0;
    double spread = 3.0;
    int nCount = 61, fzCount = 61;
};

// JSON: n_rpm[], f_z_mm[] (log-spaced), objective[i_fz][i_n], feasible[i_fz][i_n], the feasible
// polygon's corners in order ("region"), the spindle steps, every limit as a monomial
// ("limits": name, symbol, unit, coefficient, n_exp, fz_exp, limit, upper) and the optimum.
// Throws inputError for a bad box or grid size.
nlohmann::json objectiveMap(const Problem& p, const Solution& s, MapBox box = {});

}  // namespace aeronc::optimise
