#include <aeronc/compensation/HoleRows.h>

#include "NearestGrid.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

namespace aeronc::compensation {

namespace {

constexpr int kNeighbours = 4;

int findRoot(std::vector<int>& parent, int i) {
    while (parent[static_cast<size_t>(i)] != i) i = parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
    return i;
}

}  // namespace

HoleRows findRows(const std::vector<Vec3>& points, const RowOptions& options) {
    HoleRows rows;
    const size_t n = points.size();
    rows.row.assign(n, -1);
    rows.station.assign(n, 0.0);
    if (n == 0) return rows;
    for (size_t i = 0; i < n; ++i)
        if (!finite(points[i])) throw compensationError("hole rows: hole " + std::to_string(i + 1) + " is not a finite point");

    const NearestGrid grid(points);
    std::vector<double> spacing(n, 0.0);
    struct Link {
        double length;
        int a, b;
    };
    std::vector<Link> links;
    links.reserve(n * kNeighbours);
    std::vector<std::pair<double, int>> near(n * kNeighbours, {INFINITY, -1}), found;
    for (size_t i = 0; i < n; ++i) {
        grid.nearest(static_cast<int>(i), kNeighbours, found);
        for (size_t k = 0; k < found.size(); ++k) near[i * kNeighbours + k] = {std::sqrt(found[k].first), found[k].second};
        spacing[i] = found.empty() ? 0.0 : std::sqrt(found.front().first);
    }
    for (size_t i = 0; i < n; ++i)
        for (size_t k = 0; k < kNeighbours; ++k) {
            const auto [d, j] = near[i * kNeighbours + k];
            if (j < 0) continue;
            const auto a = std::min(static_cast<int>(i), j), b = std::max(static_cast<int>(i), j);
            if (d > 0.0 && d <= options.maxGapFactor * std::min(spacing[static_cast<size_t>(a)], spacing[static_cast<size_t>(b)]))
                links.push_back({d, a, b});
        }
    std::sort(links.begin(), links.end(), [](const Link& x, const Link& y) {
        return std::tie(x.length, x.a, x.b) < std::tie(y.length, y.a, y.b);
    });
    links.erase(std::unique(links.begin(), links.end(), [](const Link& x, const Link& y) { return x.a == y.a && x.b == y.b; }),
                links.end());

    const double cosTurn = std::cos(options.maxTurnDegrees * 3.14159265358979323846 / 180.0);
    std::vector<std::vector<int>> adjacent(n);
    std::vector<int> parent(n);
    std::iota(parent.begin(), parent.end(), 0);
    // Going on from `from` through `at` towards `to` turns by no more than the limit.
    auto straightEnough = [&](int at, int to) {
        for (int from : adjacent[static_cast<size_t>(at)]) {
            const Vec3 in = (points[static_cast<size_t>(at)] - points[static_cast<size_t>(from)]).normalized();
            const Vec3 out = (points[static_cast<size_t>(to)] - points[static_cast<size_t>(at)]).normalized();
            if (in.dot(out) < cosTurn) return false;
        }
        return true;
    };
    for (const auto& l : links) {
        if (adjacent[static_cast<size_t>(l.a)].size() >= 2 || adjacent[static_cast<size_t>(l.b)].size() >= 2) continue;
        const int ra = findRoot(parent, l.a), rb = findRoot(parent, l.b);
        if (ra == rb || !straightEnough(l.a, l.b) || !straightEnough(l.b, l.a)) continue;
        parent[static_cast<size_t>(ra)] = rb;
        adjacent[static_cast<size_t>(l.a)].push_back(l.b);
        adjacent[static_cast<size_t>(l.b)].push_back(l.a);
    }

    for (size_t start = 0; start < n; ++start) {
        if (rows.row[start] >= 0 || adjacent[start].size() > 1) continue;
        const int r = static_cast<int>(rows.members.size());
        rows.members.emplace_back();
        int previous = -1, at = static_cast<int>(start);
        double s = 0.0;
        while (at >= 0) {
            if (previous >= 0) s += (points[static_cast<size_t>(at)] - points[static_cast<size_t>(previous)]).norm();
            rows.row[static_cast<size_t>(at)] = r;
            rows.station[static_cast<size_t>(at)] = s;
            rows.members.back().push_back(at);
            int next = -1;
            for (int k : adjacent[static_cast<size_t>(at)])
                if (k != previous) next = k;
            previous = at;
            at = next;
        }
    }
    return rows;
}

}  // namespace aeronc::compensation
