#pragma once
// The cutting levels of a unit: from top down to the floor in equal steps of at most stepDown,
// the last one exactly at the floor.
#include <vector>

namespace aeronc::toolpath {

// Throws aeronc::inputError when floor is not below top, stepDown is not positive, or the
// levels would number more than 10,000.
std::vector<double> cuttingLevels(double top, double floor, double stepDown);

}  // namespace aeronc::toolpath
