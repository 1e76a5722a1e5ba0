#include <aeronc/compensation/RowInterpolation.h>

namespace aeronc::compensation {

Vec3 rowCorrection(const Vec3& deviationFirst, const Vec3& deviationLast, double S, double Si) {
    if (!(S > 0.0)) throw compensationError("row interpolation: the datum holes of a row must be apart (S > 0)");
    return deviationFirst * ((S - Si) / S) + deviationLast * (Si / S);
}

}  // namespace aeronc::compensation
