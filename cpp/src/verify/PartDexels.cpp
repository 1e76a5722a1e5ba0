#include <aeronc/core/Error.h>
#include <aeronc/verify/PartDexels.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

namespace aeronc::verify {

double PartDexels::volume() const {
    double v = 0;
    for (const auto& s : spans) v += s.z1 - s.z0;
    return v * grid.cellArea();
}

namespace {

struct P2 {
    double x, y;
};

// Twice the signed area of (a, b, p), evaluated from the edge's endpoints in a fixed order so
// that the two triangles sharing an edge get exactly opposite values.
double edgeFunction(const P2& a, const P2& b, double px, double py) {
    const bool swap = b.x < a.x || (b.x == a.x && b.y < a.y);
    const P2& s = swap ? b : a;
    const P2& e = swap ? a : b;
    const double v = (e.x - s.x) * (py - s.y) - (e.y - s.y) * (px - s.x);
    return swap ? -v : v;
}

// Which triangle a point exactly on a shared edge belongs to: of a counter-clockwise triangle,
// its edges running down, or running along +x. Edge directions owned form a half-open half
// plane, so a point on an edge or at a vertex of a tiling lies in exactly one triangle.
bool ownsEdge(const P2& a, const P2& b) {
    const double dy = b.y - a.y;
    return dy < 0 || (dy == 0 && b.x > a.x);
}

struct Prepared {
    P2 a, b, c;  // counter-clockwise in XY
    double za, zb, zc;
    bool entry;  // faces down: material starts here going up
    int face;
    float nz;
    int firstRow, lastRow;
};

struct Crossing {
    int column;
    bool entry;
    double z;
    int face;
    float nz;
};

bool inside(const Prepared& t, double x, double y, double& z) {
    const double w0 = edgeFunction(t.b, t.c, x, y);
    if (w0 < 0 || (w0 == 0 && !ownsEdge(t.b, t.c))) return false;
    const double w1 = edgeFunction(t.c, t.a, x, y);
    if (w1 < 0 || (w1 == 0 && !ownsEdge(t.c, t.a))) return false;
    const double w2 = edgeFunction(t.a, t.b, x, y);
    if (w2 < 0 || (w2 == 0 && !ownsEdge(t.a, t.b))) return false;
    const double sum = w0 + w1 + w2;
    if (!(sum > 0)) return false;
    z = (w0 * t.za + w1 * t.zb + w2 * t.zc) / sum;
    return true;
}

// The x-range where the row y meets the triangle's projection.
bool rowRange(const Prepared& t, double y, double& lo, double& hi) {
    lo = HUGE_VAL, hi = -HUGE_VAL;
    auto edge = [&](const P2& p, const P2& q) {
        if ((p.y - y) * (q.y - y) > 0) return;
        if (p.y == q.y) {
            lo = std::min({lo, p.x, q.x}), hi = std::max({hi, p.x, q.x});
        } else {
            const double x = p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y);
            lo = std::min(lo, x), hi = std::max(hi, x);
        }
    };
    edge(t.a, t.b), edge(t.b, t.c), edge(t.c, t.a);
    if (lo > hi) return false;
    const double pad = 1e-9 * (1 + std::abs(lo) + std::abs(hi));
    lo -= pad, hi += pad;
    return true;
}

std::vector<Prepared> prepare(const TriangleMesh& mesh, const Grid& grid) {
    std::vector<Prepared> out;
    out.reserve(mesh.triangles.size());
    for (std::size_t k = 0; k < mesh.triangles.size(); ++k) {
        const auto& v = mesh.triangles[k];
        const Point3& A = mesh.vertices[v[0]];
        const Point3& B = mesh.vertices[v[1]];
        const Point3& C = mesh.vertices[v[2]];
        const double ux = B[0] - A[0], uy = B[1] - A[1], uz = B[2] - A[2];
        const double vx = C[0] - A[0], vy = C[1] - A[1], vz = C[2] - A[2];
        const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        if (nz == 0) continue;  // stands vertical: a line along Z never crosses it
        Prepared t;
        t.entry = nz < 0;
        const Point3& second = t.entry ? C : B;
        const Point3& third = t.entry ? B : C;
        t.a = {A[0], A[1]}, t.b = {second[0], second[1]}, t.c = {third[0], third[1]};
        t.za = A[2], t.zb = second[2], t.zc = third[2];
        t.face = mesh.faces[k];
        t.nz = float(std::abs(nz) / std::sqrt(nx * nx + ny * ny + nz * nz));
        const auto rows = grid.rows(std::min({A[1], B[1], C[1]}), std::max({A[1], B[1], C[1]}));
        if (rows.first > rows.second) continue;
        t.firstRow = rows.first, t.lastRow = rows.second;
        out.push_back(t);
    }
    return out;
}

// Pairs the crossings of one column (sorted by z, entries before exits at equal z) into spans.
// Returns false when the column is inconsistent.
bool pairColumn(const Crossing* c, const Crossing* end, std::vector<PartSpan>& spans, std::size_t first) {
    bool consistent = true;
    int winding = 0;
    PartSpan cur;
    for (; c != end; ++c) {
        if (c->entry) {
            if (winding++ == 0) cur.z0 = c->z, cur.face0 = c->face, cur.nz0 = c->nz;
            continue;
        }
        if (winding == 0) {
            consistent = false;
            continue;
        }
        if (--winding > 0) continue;
        cur.z1 = c->z, cur.face1 = c->face, cur.nz1 = c->nz;
        if (cur.z1 - cur.z0 <= 1e-9) continue;
        if (spans.size() > first && cur.z0 <= spans.back().z1 + 1e-9) {
            spans.back().z1 = cur.z1, spans.back().face1 = cur.face1, spans.back().nz1 = cur.nz1;
        } else {
            spans.push_back(cur);
        }
    }
    return consistent && winding == 0;
}

struct Chunk {
    int firstRow = 0, lastRow = -1;
    std::vector<PartSpan> spans;
    std::vector<std::uint32_t> counts;  // per cell of its rows
    std::size_t inconsistent = 0;
};

void rasteriseRows(const std::vector<Prepared>& tris, const Grid& grid, Chunk& chunk) {
    const int rowCount = chunk.lastRow - chunk.firstRow + 1;
    chunk.counts.assign(std::size_t(rowCount) * std::size_t(grid.nx), 0);
    // Triangles by the first row of the chunk they reach.
    std::vector<std::vector<int>> starting(rowCount);
    for (int k = 0; k < int(tris.size()); ++k) {
        const auto& t = tris[k];
        if (t.lastRow < chunk.firstRow || t.firstRow > chunk.lastRow) continue;
        starting[std::max(t.firstRow, chunk.firstRow) - chunk.firstRow].push_back(k);
    }
    std::vector<int> active;
    std::vector<Crossing> crossings;
    for (int j = chunk.firstRow; j <= chunk.lastRow; ++j) {
        const auto& start = starting[j - chunk.firstRow];
        active.insert(active.end(), start.begin(), start.end());
        active.erase(std::remove_if(active.begin(), active.end(), [&](int k) { return tris[k].lastRow < j; }),
                     active.end());
        const double y = grid.centreY(j);
        crossings.clear();
        for (int k : active) {
            const auto& t = tris[k];
            double lo, hi;
            if (!rowRange(t, y, lo, hi)) continue;
            const auto cols = grid.columns(lo, hi);
            for (int i = cols.first; i <= cols.second; ++i) {
                double z;
                if (inside(t, grid.centreX(i), y, z)) crossings.push_back({i, t.entry, z, t.face, t.nz});
            }
        }
        std::sort(crossings.begin(), crossings.end(), [](const Crossing& a, const Crossing& b) {
            if (a.column != b.column) return a.column < b.column;
            if (a.z != b.z) return a.z < b.z;
            return a.entry && !b.entry;
        });
        for (std::size_t s = 0; s < crossings.size();) {
            std::size_t e = s;
            while (e < crossings.size() && crossings[e].column == crossings[s].column) ++e;
            const std::size_t before = chunk.spans.size();
            if (!pairColumn(&crossings[s], &crossings[e], chunk.spans, before)) ++chunk.inconsistent;
            chunk.counts[std::size_t(j - chunk.firstRow) * grid.nx + crossings[s].column] =
                std::uint32_t(chunk.spans.size() - before);
            s = e;
        }
    }
}

}  // namespace

PartDexels rasterise(const TriangleMesh& mesh, const Grid& grid) {
    validate(mesh);
    if (grid.nx <= 0 || grid.ny <= 0 || !(grid.cell > 0)) throw inputError("the dexel grid is empty");
    const auto tris = prepare(mesh, grid);

    // Bands of rows, shared out over the hardware threads.
    const int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, 8u));
    const int bands = std::min(grid.ny, threads * 8);
    std::vector<Chunk> chunks(bands);
    for (int b = 0; b < bands; ++b) {
        chunks[b].firstRow = int(std::int64_t(grid.ny) * b / bands);
        chunks[b].lastRow = int(std::int64_t(grid.ny) * (b + 1) / bands) - 1;
    }
    std::atomic<int> next{0};
    auto work = [&] {
        for (int b; (b = next++) < bands;) rasteriseRows(tris, grid, chunks[b]);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();

    PartDexels out;
    out.grid = grid;
    out.offsets.assign(grid.cells() + 1, 0);
    std::size_t total = 0;
    for (const auto& c : chunks) total += c.spans.size();
    if (total > std::size_t(UINT32_MAX)) throw inputError("the part has too many dexel spans; use a larger cell size");
    out.spans.reserve(total);
    std::size_t cell = 0;
    for (auto& c : chunks) {
        out.spans.insert(out.spans.end(), c.spans.begin(), c.spans.end());
        out.inconsistentColumns += c.inconsistent;
        for (std::uint32_t n : c.counts) {
            out.offsets[cell + 1] = out.offsets[cell] + n;
            ++cell;
        }
        c = Chunk{};
    }
    return out;
}

}  // namespace aeronc::verify
