#include <aeronc/core/Error.h>
#include <aeronc/verify/Grid.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace aeronc::verify {

namespace {
std::pair<int, int> indexRange(double origin, double cell, int n, double a, double b) {
    // Centre k is at origin + (k + 0.5) cell.
    const double lo = std::ceil((a - origin) / cell - 0.5);
    const double hi = std::floor((b - origin) / cell - 0.5);
    if (!(lo <= hi) || hi < 0 || lo > n - 1) return {0, -1};
    return {int(std::max(lo, 0.0)), int(std::min(hi, double(n - 1)))};
}
}  // namespace

std::pair<int, int> Grid::columns(double a, double b) const { return indexRange(x0, cell, nx, a, b); }
std::pair<int, int> Grid::rows(double a, double b) const { return indexRange(y0, cell, ny, a, b); }

Grid gridCovering(double xmin, double ymin, double xmax, double ymax, double cell) {
    if (!(cell > 0) || !std::isfinite(cell)) throw inputError("the cell size must be a positive number of mm");
    if (!(xmax > xmin) || !(ymax > ymin) || !std::isfinite(xmax - xmin) || !std::isfinite(ymax - ymin))
        throw inputError("the grid needs a box with some extent in X and Y");
    const double nx = std::ceil((xmax - xmin) / cell), ny = std::ceil((ymax - ymin) / cell);
    if (nx * ny > double(maxGridCells))
        throw inputError("a " + std::to_string(long(nx)) + " x " + std::to_string(long(ny)) + " grid at " +
                         std::to_string(cell) + " mm exceeds " + std::to_string(maxGridCells) +
                         " cells; use a larger cell size");
    Grid g;
    g.cell = cell;
    g.nx = std::max(1, int(nx));
    g.ny = std::max(1, int(ny));
    // Centre the grid on the box so the spare fraction of a cell is shared by both sides.
    g.x0 = 0.5 * (xmin + xmax) - 0.5 * g.nx * cell;
    g.y0 = 0.5 * (ymin + ymax) - 0.5 * g.ny * cell;
    return g;
}

}  // namespace aeronc::verify
