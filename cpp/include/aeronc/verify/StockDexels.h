#pragma once
// The material still there while the program runs, as Z-dexels over the part's grid. A cutter
// along +Z or -Z only ever removes one end of a cell's column (everything at and above, or at
// and below, its envelope), so spans shrink or vanish but never split: the spans of a cell stay
// in the slots they started in.
#include <aeronc/verify/Grid.h>

#include <array>
#include <cstdint>
#include <vector>

namespace aeronc::verify {

struct StockSpan {
    double z0 = 0, z1 = 0;
};

class StockDexels {
public:
    // A box blank {xmin, ymin, zmin, xmax, ymax, zmax}: one span in every cell whose centre lies
    // inside it. Throws aeronc::Error (input) for an empty or inverted box.
    static StockDexels box(const Grid& grid, const std::array<double, 6>& blank);

    const Grid& grid() const { return grid_; }
    const StockSpan* begin(std::size_t c) const { return spans_.data() + first_[c]; }
    const StockSpan* end(std::size_t c) const { return spans_.data() + last_[c]; }
    bool empty(std::size_t c) const { return first_[c] == last_[c]; }
    double top(std::size_t c) const { return spans_[last_[c] - 1].z1; }      // not empty
    double bottom(std::size_t c) const { return spans_[first_[c]].z0; }      // not empty

    // Removes the material at and above z; returns the length removed.
    double removeAbove(std::size_t c, double z);
    // Removes the material at and below z; returns the length removed.
    double removeBelow(std::size_t c, double z);

    double volume() const;
    // Whether material is left at (x, y, z): false outside the grid.
    bool contains(double x, double y, double z) const;

private:
    Grid grid_;
    std::vector<StockSpan> spans_;
    std::vector<std::uint32_t> first_, last_;
};

}  // namespace aeronc::verify
