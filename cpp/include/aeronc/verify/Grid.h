#pragma once
// The XY grid of the dexel model: square cells, each holding a column of material along Z.
#include <cmath>
#include <cstddef>
#include <utility>

namespace aeronc::verify {

struct Grid {
    double x0 = 0, y0 = 0;  // the lower-left corner of cell (0, 0)
    double cell = 0.5;      // cell size (mm)
    int nx = 0, ny = 0;

    std::size_t cells() const { return std::size_t(nx) * std::size_t(ny); }
    std::size_t index(int i, int j) const { return std::size_t(j) * std::size_t(nx) + std::size_t(i); }
    double centreX(int i) const { return x0 + (i + 0.5) * cell; }
    double centreY(int j) const { return y0 + (j + 0.5) * cell; }
    double cellArea() const { return cell * cell; }

    // The first and last column (row) whose centre lies in [a, b], clamped to the grid; first > last
    // when there is none.
    std::pair<int, int> columns(double a, double b) const;
    std::pair<int, int> rows(double a, double b) const;
    // The cell holding (x, y), or false outside the grid. Inline: the coverage's wall walk calls
    // it for every step.
    bool cellAt(double x, double y, int& i, int& j) const {
        const double fi = std::floor((x - x0) / cell), fj = std::floor((y - y0) / cell);
        if (!(fi >= 0 && fi < nx && fj >= 0 && fj < ny)) return false;
        i = int(fi), j = int(fj);
        return true;
    }
};

// Largest grid the verification accepts (memory is about 70 bytes a cell).
constexpr std::size_t maxGridCells = 25'000'000;

// The grid over [xmin, xmax] x [ymin, ymax] with the given cell size. Throws aeronc::Error
// (input) for a cell size that is not positive, an empty box, or more than maxGridCells cells.
Grid gridCovering(double xmin, double ymin, double xmax, double ymax, double cell);

}  // namespace aeronc::verify
