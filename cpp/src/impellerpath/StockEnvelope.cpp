#include "StockEnvelope.h"

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>

namespace aeronc::impellerpath {

StockEnvelope::StockEnvelope(impeller::BlankProfile blank, const Frame& frame)
    : blank_(std::move(blank)), frame_(frame) {
    if (blank_.radius.empty() || blank_.axial.size() != blank_.radius.size() + 1)
        throw inputError("impeller toolpaths: the blank profile needs one station more than radii");
}

double StockEnvelope::distance(const Vec3& p) const {
    const double r = frame_.radius(p), z = frame_.axial(p);
    double best = 1e300;
    // The blank is the union of the cylinders r <= radius[i], axial[i] <= z <= axial[i + 1].
    for (size_t i = 0; i < blank_.radius.size(); ++i) {
        const double dr = std::max(r - blank_.radius[i], 0.0);
        const double dz = std::max({blank_.axial[i] - z, z - blank_.axial[i + 1], 0.0});
        best = std::min(best, std::hypot(dr, dz));
    }
    return best;
}

double StockEnvelope::top() const { return *std::max_element(blank_.axial.begin(), blank_.axial.end()); }

double StockEnvelope::clearance(const CutterShape& c, const Vec3& centre, const Vec3& axis) const {
    const double flutes = c.fluteLength - c.tipRadius, top = c.reach - c.tipRadius;
    const int n = std::max(2, static_cast<int>(std::ceil(top / 1.0)));
    double least = 1e300;
    for (int i = 0; i <= n; ++i) {
        const double h = top * i / n;
        const double radius = h <= flutes ? c.radiusAt(h) : c.shankRadius;
        least = std::min(least, distance(centre + h * axis) - radius);
    }
    return least;
}

double rapidClearance(const StockEnvelope& stock, const CutterShape& cutter, const Move& a, const Move& b) {
    const int n = std::max(1, static_cast<int>(std::ceil((b.centre - a.centre).norm() / 0.5)));
    double least = 1e300;
    for (int i = 0; i <= n; ++i) {
        const double t = double(i) / n;
        const Vec3 axis = ((1 - t) * a.axis + t * b.axis).normalized();
        least = std::min(least, stock.clearance(cutter, a.centre + t * (b.centre - a.centre), axis));
    }
    return least;
}

}  // namespace aeronc::impellerpath
