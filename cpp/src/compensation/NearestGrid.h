#pragma once
// Nearest neighbours of points spread over a surface or along a line (hole patterns): the rows
// (HoleRows.cpp) and the neighbour check of the corrections (HoleFlags.cpp). Internal header.
#include <aeronc/compensation/Types.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <utility>
#include <vector>

namespace aeronc::compensation {

// Points sorted into a dense grid of cubic cells (compressed: each cell's points are one run
// of `order_`), for nearest-neighbour queries.
class NearestGrid {
public:
    explicit NearestGrid(const std::vector<Vec3>& points) : points_(points) {
        lo_ = hi_ = points.front();
        for (const auto& p : points) lo_ = lo_.cwiseMin(p), hi_ = hi_.cwiseMax(p);
        // About four points per cell for a pattern spread over a surface (or along a line), so
        // that the nearest four are mostly found in the next cells.
        Vec3 e = hi_ - lo_;
        std::sort(e.data(), e.data() + 3, std::greater<double>());
        const double n = static_cast<double>(points.size());
        cell_ = e[1] > 1e-6 * e[0] ? 2.0 * std::sqrt(e[0] * e[1] / n) : 4.0 * e[0] / n;
        if (!(cell_ > 0.0)) cell_ = 1.0;
        // No more cells than a few per point, whatever the spread.
        const double budget = 4.0 * n + 64.0;
        const double cells = (((hi_ - lo_) / cell_).array().floor() + 1.0).prod();
        if (cells > budget) cell_ *= std::cbrt(cells / budget) * 1.01;
        dims_ = (((hi_ - lo_) / cell_).array().floor().cast<int>() + 1).matrix();
        const size_t total = static_cast<size_t>(dims_.x()) * static_cast<size_t>(dims_.y()) * static_cast<size_t>(dims_.z());
        start_.assign(total + 1, 0);
        std::vector<size_t> cellOf(points.size());
        for (size_t i = 0; i < points.size(); ++i) {
            cellOf[i] = flat(index(points[i]));
            ++start_[cellOf[i] + 1];
        }
        for (size_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
        order_.resize(points.size());
        std::vector<size_t> fill(start_.begin(), start_.end() - 1);
        for (size_t i = 0; i < points.size(); ++i) order_[fill[cellOf[i]]++] = static_cast<int>(i);
    }

    // The k nearest other points of point i (fewer when there are fewer), nearest first, as
    // (squared distance, index); `found` is scratch space.
    void nearest(int i, int k, std::vector<std::pair<double, int>>& found) const {
        const Vec3& p = points_[static_cast<size_t>(i)];
        const Eigen::Vector3i c = index(p);
        found.clear();
        const int maxRing = dims_.maxCoeff();
        for (int r = 0; r <= maxRing; ++r) {
            for (int x = std::max(0, c.x() - r); x <= std::min(dims_.x() - 1, c.x() + r); ++x)
                for (int y = std::max(0, c.y() - r); y <= std::min(dims_.y() - 1, c.y() + r); ++y) {
                    const bool side = std::abs(x - c.x()) == r || std::abs(y - c.y()) == r;
                    for (int z = c.z() - r; z <= c.z() + r; z += (side || r == 0) ? 1 : 2 * r) {
                        if (z < 0 || z >= dims_.z()) continue;
                        const size_t cell = flat({x, y, z});
                        for (size_t o = start_[cell]; o < start_[cell + 1]; ++o) {
                            const int j = order_[o];
                            if (j != i) found.emplace_back((points_[static_cast<size_t>(j)] - p).squaredNorm(), j);
                        }
                    }
                }
            // Every point not yet seen is at least r cells away.
            if (static_cast<int>(found.size()) >= k) {
                std::nth_element(found.begin(), found.begin() + (k - 1), found.end());
                const double reach = r * cell_;
                if (found[static_cast<size_t>(k - 1)].first <= reach * reach) break;
            }
        }
        const auto keep = std::min(found.size(), static_cast<size_t>(k));
        std::partial_sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(keep), found.end());
        found.resize(keep);
    }

private:
    Eigen::Vector3i index(const Vec3& p) const {
        const Eigen::Vector3i c = ((p - lo_) / cell_).array().floor().cast<int>();
        return c.cwiseMax(0).cwiseMin(dims_ - Eigen::Vector3i::Ones());
    }
    size_t flat(const Eigen::Vector3i& c) const {
        return (static_cast<size_t>(c.x()) * static_cast<size_t>(dims_.y()) + static_cast<size_t>(c.y())) *
                   static_cast<size_t>(dims_.z()) + static_cast<size_t>(c.z());
    }

    const std::vector<Vec3>& points_;
    Vec3 lo_, hi_;
    double cell_ = 1.0;
    Eigen::Vector3i dims_;
    std::vector<size_t> start_;
    std::vector<int> order_;
};

}  // namespace aeronc::compensation
