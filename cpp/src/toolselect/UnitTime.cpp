#include <aeronc/core/Error.h>
#include <aeronc/toolselect/Selection.h>

#include <cmath>
#include <sstream>

namespace aeronc::toolselect {

double unitTime(double area, double depth, const CuttingData& d) {
    if (!(d.ae > 0) || !(d.feedPerMinute > 0) || !(d.ap > 0) || !(d.delta >= 0)) {
        std::ostringstream m;
        m << "cutting data needs positive a_e, feed and a_p and a non-negative delta (got a_e " << d.ae
          << ", feed " << d.feedPerMinute << ", a_p " << d.ap << ", delta " << d.delta << ")";
        throw inputError(m.str());
    }
    if (!(area >= 0) || !(depth >= 0)) throw inputError("a unit's area and depth must not be negative");
    const double t = area / (d.ae * d.feedPerMinute);
    // 1e-9: H = 0.6, a_p = 0.2 must give nn = 3, not 2.999… truncated to 2.
    const double nn = std::floor(depth / d.ap + 1e-9);
    const double layers = depth - d.ap * nn < d.delta ? nn : nn + 1;
    return t * layers;
}

}  // namespace aeronc::toolselect
