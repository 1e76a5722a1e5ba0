#include <aeronc/core/Error.h>
#include <aeronc/verify/Coverage.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace aeronc::verify {

namespace {

// A face steeper than this (|nz| below it, about 11.5 degrees from vertical) is measured as a wall.
constexpr double wallNz = 0.2;

template <class Span>
double lengthIn(const Span* s, const Span* e, double a, double b) {
    double len = 0;
    for (; s != e; ++s) len += std::max(0.0, std::min(s->z1, b) - std::max(s->z0, a));
    return len;
}

// Length of stock outside the part within [a, b].
double stockBeyondPart(const StockDexels& stock, const PartDexels& part, std::size_t c, double a, double b) {
    double len = lengthIn(stock.begin(c), stock.end(c), a, b);
    for (auto* s = stock.begin(c); s != stock.end(c); ++s)
        for (auto* p = part.begin(c); p != part.end(c); ++p)
            len -= std::max(0.0, std::min({s->z1, p->z1, b}) - std::max({s->z0, p->z0, a}));
    return len;
}

class Measure {
public:
    Measure(const TriangleMesh& mesh, const PartDexels& part, const StockDexels& stock, const CoverageOptions& o)
        : mesh_(mesh), part_(part), stock_(stock), o_(o), grid_(part.grid) {
        band_ = o.wallBand > 0 ? o.wallBand : 2 * grid_.cell;
    }

    void floors(std::unordered_map<int, FaceCoverage>& faces) const {
        const double area = grid_.cellArea();
        auto record = [&](int face, float nz, double vertical) {
            if (nz < wallNz) return;
            auto it = faces.find(face);
            if (it == faces.end()) return;
            const double a = area / nz, left = vertical * nz;
            FaceCoverage& f = it->second;
            f.floorArea += a;
            if (left > o_.floorTolerance) f.uncoveredArea += a;
            f.maxLeftover = std::max(f.maxLeftover, left);
        };
        for (std::size_t c = 0; c < grid_.cells(); ++c) {
            const PartSpan* b = part_.begin(c);
            const PartSpan* e = part_.end(c);
            for (const PartSpan* p = b; p != e; ++p) {
                const double below = p == b ? -HUGE_VAL : (p - 1)->z1;
                const double above = p + 1 == e ? HUGE_VAL : (p + 1)->z0;
                record(p->face1, p->nz1, lengthIn(stock_.begin(c), stock_.end(c), p->z1, above));
                record(p->face0, p->nz0, lengthIn(stock_.begin(c), stock_.end(c), below, p->z0));
            }
        }
    }

    void walls(std::unordered_map<int, FaceCoverage>& faces) const {
        // Each face's height range: its bands split it evenly, so every band is a full one.
        std::unordered_map<int, std::pair<double, double>> heights;
        for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
            if (!faces.count(mesh_.faces[t])) continue;
            auto it = heights.try_emplace(mesh_.faces[t], HUGE_VAL, -HUGE_VAL).first;
            for (int k : mesh_.triangles[t]) {
                it->second.first = std::min(it->second.first, mesh_.vertices[k][2]);
                it->second.second = std::max(it->second.second, mesh_.vertices[k][2]);
            }
        }
        for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
            auto it = faces.find(mesh_.faces[t]);
            if (it != faces.end()) wallTriangle(t, heights.at(mesh_.faces[t]), it->second);
        }
    }

private:
    // Samples a steep triangle along its horizontal direction, in its face's bands of height.
    void wallTriangle(std::size_t t, std::pair<double, double> faceHeight, FaceCoverage& f) const {
        const auto& v = mesh_.triangles[t];
        const Point3& A = mesh_.vertices[v[0]];
        const Point3& B = mesh_.vertices[v[1]];
        const Point3& C = mesh_.vertices[v[2]];
        double n[3] = {(B[1] - A[1]) * (C[2] - A[2]) - (B[2] - A[2]) * (C[1] - A[1]),
                       (B[2] - A[2]) * (C[0] - A[0]) - (B[0] - A[0]) * (C[2] - A[2]),
                       (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0])};
        const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(len > 0)) return;
        for (double& x : n) x /= len;
        if (std::abs(n[2]) >= wallNz) return;
        const double h = std::hypot(n[0], n[1]);
        const double nx = n[0] / h, ny = n[1] / h;  // outward, horizontal
        // In-plane frame: U horizontal, V up the slope.
        const double U[3] = {-ny, nx, 0};
        double V[3] = {-n[2] * n[0], -n[2] * n[1], 1 - n[2] * n[2]};
        const double vl = std::sqrt(V[0] * V[0] + V[1] * V[1] + V[2] * V[2]);
        for (double& x : V) x /= vl;
        auto uv = [&](const Point3& P, double& u, double& w) {
            const double d[3] = {P[0] - A[0], P[1] - A[1], P[2] - A[2]};
            u = d[0] * U[0] + d[1] * U[1] + d[2] * U[2];
            w = d[0] * V[0] + d[1] * V[1] + d[2] * V[2];
        };
        double u[3], w[3];
        uv(A, u[0], w[0]), uv(B, u[1], w[1]), uv(C, u[2], w[2]);
        const double umin = std::min({u[0], u[1], u[2]}), umax = std::max({u[0], u[1], u[2]});
        if (!(umax > umin)) return;
        const int ns = std::max(1, int(std::ceil((umax - umin) / (0.5 * grid_.cell))));
        const double du = (umax - umin) / ns;
        for (int k = 0; k < ns; ++k) {
            const double us = umin + (k + 0.5) * du;
            double lo = HUGE_VAL, hi = -HUGE_VAL;
            for (int e = 0; e < 3; ++e) {
                const int g = (e + 1) % 3;
                if ((u[e] - us) * (u[g] - us) > 0 || u[e] == u[g]) continue;
                const double ws = w[e] + (us - u[e]) * (w[g] - w[e]) / (u[g] - u[e]);
                lo = std::min(lo, ws), hi = std::max(hi, ws);
            }
            if (!(hi > lo)) continue;
            const double za = A[2] + lo * V[2], zb = A[2] + hi * V[2];
            const auto [fz0, fz1] = faceHeight;
            const int nb = std::max(1, int(std::lround((fz1 - fz0) / band_)));
            const double dz = (fz1 - fz0) / nb;
            for (int b = std::max(0, int((za - fz0) / dz)); b < nb; ++b) {
                const double z0 = fz0 + b * dz, z1 = z0 + dz;
                const double from = std::max(z0, za), to = std::min(z1, zb);
                if (from >= zb) break;
                if (!(to > from)) continue;
                const double wm = (0.5 * (from + to) - A[2]) / V[2];
                const double px = A[0] + us * U[0] + wm * V[0], py = A[1] + us * U[1] + wm * V[1];
                const double left = wallLeftover(px, py, z0, z1, nx, ny);
                const double area = du * (to - from) / V[2];
                f.wallArea += area;
                if (left > o_.wallTolerance) f.uncoveredArea += area;
                f.maxLeftover = std::max(f.maxLeftover, left);
            }
        }
    }

    // Walks the cells along the outward normal from a wall point while they hold stock beyond the
    // part over most of the band [z0, z1]; returns the thickness left (0 when the first cell out
    // is clear).
    double wallLeftover(double x, double y, double z0, double z1, double nx, double ny) const {
        const double half = 0.5 * (z1 - z0);
        const double step = 0.25 * grid_.cell;
        int li = -1, lj = -1;
        double last = -1;
        for (double t = 0; t <= o_.wallSearch + grid_.cell; t += step) {
            int i, j;
            if (!grid_.cellAt(x + t * nx, y + t * ny, i, j)) break;
            if (i == li && j == lj) continue;
            li = i, lj = j;
            const double tc = (grid_.centreX(i) - x) * nx + (grid_.centreY(j) - y) * ny;
            if (tc <= 0) continue;  // its centre is still on the part's side of the wall
            if (tc > o_.wallSearch) break;
            const std::size_t c = grid_.index(i, j);
            if (lengthIn(part_.begin(c), part_.end(c), z0, z1) > half) break;  // the part again
            if (stockBeyondPart(stock_, part_, c, z0, z1) <= half) break;      // clear
            // Alongside another wall (a sample by a sharp corner walking down the neighbouring
            // wall's allowance): what is met is that wall's material, not this one's thickness.
            if (last >= 0 && (partBeside(x + tc * nx - grid_.cell * ny, y + tc * ny + grid_.cell * nx, z0, z1, half) ||
                              partBeside(x + tc * nx + grid_.cell * ny, y + tc * ny - grid_.cell * nx, z0, z1, half)))
                break;
            last = tc;
        }
        return last < 0 ? 0 : std::min(last + 0.5 * grid_.cell, o_.wallSearch);
    }

    bool partBeside(double x, double y, double z0, double z1, double half) const {
        int i, j;
        if (!grid_.cellAt(x, y, i, j)) return false;
        const std::size_t c = grid_.index(i, j);
        return lengthIn(part_.begin(c), part_.end(c), z0, z1) > half;
    }

    const TriangleMesh& mesh_;
    const PartDexels& part_;
    const StockDexels& stock_;
    const CoverageOptions& o_;
    const Grid& grid_;
    double band_ = 1;
};

}  // namespace

CoverageReport measureCoverage(const TriangleMesh& mesh, const PartDexels& part, const StockDexels& stock,
                               const std::vector<int>& faces,
                               const std::vector<std::pair<std::string, std::vector<int>>>& elements,
                               const CoverageOptions& options) {
    if (!(options.floorTolerance >= 0) || !(options.wallTolerance >= 0) || !(options.wallSearch > 0) ||
        !(options.wallBand >= 0))
        throw inputError("coverage tolerances must not be negative and the wall search must be positive");
    CoverageReport r;
    r.options = options;
    std::unordered_map<int, FaceCoverage> byFace;
    for (int f : faces) byFace[f].face = f;
    for (const auto& e : elements)
        for (int f : e.second) byFace[f].face = f;
    if (!byFace.empty()) {
        const Measure m(mesh, part, stock, options);
        m.floors(byFace);
        m.walls(byFace);
    }
    std::vector<int> seen;
    for (int f : faces) {
        if (std::find(seen.begin(), seen.end(), f) != seen.end()) continue;
        seen.push_back(f);
        r.faces.push_back(byFace[f]);
    }
    for (const auto& [id, list] : elements) {
        ElementCoverage e;
        e.id = id;
        for (int f : list)
            if (std::find(e.faces.begin(), e.faces.end(), f) == e.faces.end()) e.faces.push_back(f);
        for (int f : e.faces) {
            const FaceCoverage& fc = byFace[f];
            e.area += fc.floorArea + fc.wallArea;
            e.uncoveredArea += fc.uncoveredArea;
            e.maxLeftover = std::max(e.maxLeftover, fc.maxLeftover);
        }
        r.elements.push_back(std::move(e));
    }
    return r;
}

}  // namespace aeronc::verify
