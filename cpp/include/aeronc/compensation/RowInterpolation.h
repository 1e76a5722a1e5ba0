#pragma once
// The seed's compensation along a row of holes (drilling paper, formula 2): a hole between the
// datum holes P_1 and P_n of its row, at distance S_i from P_1 along the row where S is the
// distance from P_1 to P_n, gets
//     dP_i = dP_1 * (S - S_i) / S + dP_n * S_i / S.
#include <aeronc/compensation/Types.h>

namespace aeronc::compensation {

// Formula 2 exactly as the seed writes it. S must be positive; S_i is not clamped (a caller
// that extrapolates decides so itself).
Vec3 rowCorrection(const Vec3& deviationFirst, const Vec3& deviationLast, double S, double Si);

}  // namespace aeronc::compensation
