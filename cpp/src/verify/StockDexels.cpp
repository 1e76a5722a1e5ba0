#include <aeronc/core/Error.h>
#include <aeronc/verify/StockDexels.h>

#include <cmath>

namespace aeronc::verify {

StockDexels StockDexels::box(const Grid& grid, const std::array<double, 6>& b) {
    for (double v : b)
        if (!std::isfinite(v)) throw inputError("the blank must be six finite numbers");
    if (!(b[3] > b[0] && b[4] > b[1] && b[5] > b[2]))
        throw inputError("the blank [xmin, ymin, zmin, xmax, ymax, zmax] must have xmin < xmax, ymin < ymax and "
                         "zmin < zmax");
    StockDexels s;
    s.grid_ = grid;
    s.first_.assign(grid.cells(), 0);
    s.last_.assign(grid.cells(), 0);
    const auto cols = grid.columns(b[0], b[3]);
    const auto rows = grid.rows(b[1], b[4]);
    for (int j = rows.first; j <= rows.second; ++j)
        for (int i = cols.first; i <= cols.second; ++i) {
            const std::size_t c = grid.index(i, j);
            s.first_[c] = std::uint32_t(s.spans_.size());
            s.spans_.push_back({b[2], b[5]});
            s.last_[c] = std::uint32_t(s.spans_.size());
        }
    return s;
}

bool StockDexels::contains(double x, double y, double z) const {
    int i = 0, j = 0;
    if (!grid_.cellAt(x, y, i, j)) return false;
    const std::size_t c = grid_.index(i, j);
    for (const StockSpan* s = begin(c); s != end(c); ++s)
        if (s->z0 <= z && z <= s->z1) return true;
    return false;
}

double StockDexels::removeAbove(std::size_t c, double z) {
    double removed = 0;
    std::uint32_t& last = last_[c];
    while (last > first_[c]) {
        StockSpan& s = spans_[last - 1];
        if (s.z1 <= z) break;
        if (s.z0 >= z) {
            removed += s.z1 - s.z0;
            --last;
        } else {
            removed += s.z1 - z;
            s.z1 = z;
            break;
        }
    }
    return removed;
}

double StockDexels::removeBelow(std::size_t c, double z) {
    double removed = 0;
    std::uint32_t& first = first_[c];
    while (first < last_[c]) {
        StockSpan& s = spans_[first];
        if (s.z0 >= z) break;
        if (s.z1 <= z) {
            removed += s.z1 - s.z0;
            ++first;
        } else {
            removed += z - s.z0;
            s.z0 = z;
            break;
        }
    }
    return removed;
}

double StockDexels::volume() const {
    double v = 0;
    for (std::size_t c = 0; c < first_.size(); ++c)
        for (auto* s = begin(c); s != end(c); ++s) v += s->z1 - s->z0;
    return v * grid_.cellArea();
}

}  // namespace aeronc::verify
