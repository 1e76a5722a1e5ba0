#include <aeronc/core/Error.h>
#include <aeronc/verify/Simulation.h>
#include <aeronc/verify/SweptSegment.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

namespace aeronc::verify {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// What one offending cell shows: copied for every hit, so no label in it.
struct CellHit {
    double depth = 0;
    bool wall = false;
    int face = 0;
    std::array<double, 3> position{};
};

// Counts offending cells of one check, and per move its deepest cell.
class Tally {
public:
    Tally(CheckResult& result, double tolerance, int maxListed) : r_(result), maxListed_(maxListed) {
        r_.tolerance = tolerance;
    }
    void startSegment(int op, const std::string& label, const Segment& seg) {
        op_ = op, label_ = &label, seg_ = &seg;
        segmentWorst_.reset();
    }
    void hit(const CellHit& h) {
        ++r_.cells;
        if (!segmentWorst_ || h.depth > segmentWorst_->depth) segmentWorst_ = h;
    }
    // Returns true when the segment's move offends and was not counted yet; opWorst (and
    // opWorstAt, where it is): the deepest offence of the operation so far, raised to this
    // segment's.
    bool endSegment(double& opWorst, std::optional<MoveEvent>& opWorstAt) {
        if (!segmentWorst_) return false;
        opWorst = std::max(opWorst, segmentWorst_->depth);
        MoveEvent e;
        e.operation = op_, e.label = *label_, e.move = seg_->move, e.tip = seg_->to;
        e.depth = segmentWorst_->depth, e.wall = segmentWorst_->wall, e.face = segmentWorst_->face;
        e.position = segmentWorst_->position;
        const bool sameMove = lastOp_ == op_ && lastMove_ == e.move;
        if (!sameMove) ++r_.moves;
        if (!r_.worst || e.depth > r_.worst->depth) r_.worst = e;
        if (!opWorstAt || e.depth > opWorstAt->depth) opWorstAt = e;
        if (sameMove && !r_.listed.empty() && r_.listed.back().operation == op_ && r_.listed.back().move == e.move) {
            if (e.depth > r_.listed.back().depth) r_.listed.back() = e;
        } else if (!sameMove && int(r_.listed.size()) < maxListed_) {
            r_.listed.push_back(e);
        }
        lastOp_ = op_, lastMove_ = e.move;
        return !sameMove;
    }

private:
    CheckResult& r_;
    int maxListed_;
    int op_ = -1, lastOp_ = -1, lastMove_ = -1;
    const std::string* label_ = nullptr;
    const Segment* seg_ = nullptr;
    std::optional<CellHit> segmentWorst_;
};

struct Run {
    const PartDexels& part;
    StockDexels& stock;
    const SimulationOptions& options;
    Tally gouges, collisions;
    const std::vector<PriorStock>& priors;
};

// How far the material met in column c between z = lo and hi (real heights) reaches towards
// `from` (hi for a cutter from above, lo from below), counting only the points the setups
// before also left: the highest (lowest) such point sampled every half cell; NaN when none.
double priorMaterialReach(const Run& run, std::size_t c, double x, double y, double lo, double hi, bool fromAbove) {
    const double step = 0.5 * run.part.grid.cell;
    double best = std::nan("");
    for (const StockSpan* s = run.stock.begin(c); s != run.stock.end(c); ++s) {
        const double a = std::max(s->z0, lo), b = std::min(s->z1, hi);
        if (!(a <= b)) continue;
        const int n = std::max(1, int(std::ceil((b - a) / step)));
        for (int k = 0; k <= n; ++k) {
            const double z = fromAbove ? b - (b - a) * k / n : a + (b - a) * k / n;
            bool left = true;
            for (const PriorStock& p : run.priors) {
                const auto q = p.toStock({x, y, z});
                if (!p.stock->contains(q[0], q[1], q[2])) {
                    left = false;
                    break;
                }
            }
            if (!left) continue;
            if (std::isnan(best) || (fromAbove ? z > best : z < best)) best = z;
            break;  // the first one found from that side is the farthest in this span
        }
    }
    return best;
}

// The top of the part in column c seen along the axis' sense s (the bottom, negated, for -Z).
inline double partTopAt(const PartDexels& part, std::size_t c, int s) {
    return s > 0 ? (part.end(c) - 1)->z1 : -part.begin(c)->z0;
}

// Gouge: part material above the grown cutter's envelope, lowered by the axial allowance. The
// depth is the smaller of the overlap along the part's normal (the vertical overlap times |nz|
// of the face the dexel ends on: on a slope the vertical overlap overstates how deep the cutter
// went) and the horizontal overlap. Fills e and returns true beyond the tolerance.
bool gougeAt(const PartDexels& part, std::size_t c, const SweptSegment& sw, const Cutter& grown, double axial,
             int s, double tol, double x, double y, double d, CellHit& e) {
    if (part.empty(c)) return false;
    const double partTop = s > 0 ? (part.end(c) - 1)->z1 : -part.begin(c)->z0;
    if (sw.lowerBound(grown, d) - axial >= partTop - tol) return false;  // clear of it everywhere
    const double hg = sw.envelope(grown, x, y) - axial;
    const double sideways = grown.radius - d;
    double depth = 0, contact = 0;
    int face = 0;
    bool wall = false;
    if (s > 0) {
        for (const PartSpan* p = part.end(c); p != part.begin(c);) {
            --p;
            if (p->z1 <= hg + tol) break;
            const double down = p->z1 - hg, dp = std::min(down * p->nz1, sideways);
            if (dp <= depth) continue;
            depth = dp, wall = sideways < down;
            contact = wall ? std::max(hg, p->z0) : p->z1, face = wall ? 0 : p->face1;
        }
    } else {
        for (const PartSpan* p = part.begin(c); p != part.end(c); ++p) {
            if (-p->z0 <= hg + tol) break;
            const double down = -p->z0 - hg, dp = std::min(down * p->nz0, sideways);
            if (dp <= depth) continue;
            depth = dp, wall = sideways < down;
            contact = wall ? std::min(-hg, p->z1) : p->z0, face = wall ? 0 : p->face0;
        }
    }
    if (depth <= tol) return false;
    e.depth = depth, e.wall = wall, e.face = face, e.position = {x, y, contact};
    return true;
}

void runOperation(int index, const Operation& op, Run& run, OperationSummary& summary) {
    const Grid& grid = run.part.grid;
    const int s = op.axis;
    const Cutter& cutter = op.cutter;
    const Cutter grown = cutter.grownBy(op.radialAllowance);  // what the part must stay clear of
    const double reach = std::max(cutter.radius, grown.radius);
    const double gougeTol = run.options.gougeTolerance, collisionTol = run.options.collisionTolerance;
    double removed = 0;

    const auto segments = segmentsOf(op);
    summary.label = op.label;
    summary.moves = op.moves.size();
    summary.segments = segments.size();
    for (const Segment& seg : segments) {
        const SweptSegment sw(seg.from[0], seg.from[1], s * seg.from[2], seg.to[0], seg.to[1], s * seg.to[2]);
        const double lowest = std::min(s * seg.from[2], s * seg.to[2]);  // the tip's, in the axis' sense
        run.gouges.startSegment(index, op.label, seg);
        run.collisions.startSegment(index, op.label, seg);

        const auto rows = grid.rows(sw.minY() - reach, sw.maxY() + reach);
        for (int j = rows.first; j <= rows.second; ++j) {
            const double y = grid.centreY(j);
            double xa, xb;
            if (!sw.rowSpan(y, reach, xa, xb)) continue;
            const auto cols = grid.columns(xa, xb);
            for (int i = cols.first; i <= cols.second; ++i) {
                const std::size_t c = grid.index(i, j);
                // The cutter nowhere reaches below the segment's lower end: a column whose part
                // and stock both end below it has nothing to check (the tests below would say so).
                const bool gougeCheck = !seg.rapid && !run.part.empty(c) &&
                                        lowest - op.axialAllowance < partTopAt(run.part, c, s) - gougeTol;
                if (!gougeCheck && (run.stock.empty(c) || lowest >= (s > 0 ? run.stock.top(c) : -run.stock.bottom(c))))
                    continue;
                const double x = grid.centreX(i);
                const double d = sw.distance(x, y);

                if (gougeCheck && d <= grown.radius) {
                    CellHit e;
                    if (gougeAt(run.part, c, sw, grown, op.axialAllowance, s, gougeTol, x, y, d, e)) run.gouges.hit(e);
                }

                if (d > cutter.radius || run.stock.empty(c)) continue;
                const double top = s > 0 ? run.stock.top(c) : -run.stock.bottom(c);
                if (sw.lowerBound(cutter, d) >= top) continue;  // above all material here
                const double h = sw.envelope(cutter, x, y);
                if (h == HUGE_VAL) continue;
                if (seg.rapid) {
                    double reach = top;
                    if (!run.priors.empty()) {
                        const double z = s > 0 ? priorMaterialReach(run, c, x, y, h, HUGE_VAL, true)
                                               : priorMaterialReach(run, c, x, y, -HUGE_VAL, -h, false);
                        reach = std::isnan(z) ? -HUGE_VAL : s * z;
                    }
                    const double depth = std::min(reach - h, cutter.radius - d);
                    if (depth > collisionTol) run.collisions.hit({depth, cutter.radius - d < reach - h, 0, {x, y, s * reach}});
                }
                removed += s > 0 ? run.stock.removeAbove(c, h) : run.stock.removeBelow(c, -h);
            }
        }
        if (run.gouges.endSegment(summary.worstGouge, summary.worstGougeAt)) ++summary.gougingMoves;
        if (run.collisions.endSegment(summary.worstCollision, summary.worstCollisionAt)) ++summary.collidingMoves;
    }
    summary.removedVolume = removed * grid.cellArea();
}

// The face of the steep triangle nearest to a wall gouge at (x, y, z): dexels only know the faces
// at the ends of their spans.
int wallFaceNear(const TriangleMesh& mesh, const std::array<double, 3>& at) {
    int best = 0;
    double bestDistance = HUGE_VAL;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& v = mesh.triangles[t];
        const Point3* P[3] = {&mesh.vertices[v[0]], &mesh.vertices[v[1]], &mesh.vertices[v[2]]};
        const double zlo = std::min({(*P[0])[2], (*P[1])[2], (*P[2])[2]});
        const double zhi = std::max({(*P[0])[2], (*P[1])[2], (*P[2])[2]});
        if (at[2] < zlo - 1e-6 || at[2] > zhi + 1e-6) continue;
        const double ux = (*P[1])[0] - (*P[0])[0], uy = (*P[1])[1] - (*P[0])[1], uz = (*P[1])[2] - (*P[0])[2];
        const double vx = (*P[2])[0] - (*P[0])[0], vy = (*P[2])[1] - (*P[0])[1], vz = (*P[2])[2] - (*P[0])[2];
        const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        if (std::abs(nz) >= 0.2 * std::sqrt(nx * nx + ny * ny + nz * nz)) continue;  // not a wall
        // Horizontal distance to the triangle's edges: enough for a steep triangle.
        for (int e = 0; e < 3; ++e) {
            const Point3& a = *P[e];
            const Point3& b = *P[(e + 1) % 3];
            const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
            const double t01 = len2 > 0 ? std::clamp(((at[0] - a[0]) * dx + (at[1] - a[1]) * dy) / len2, 0.0, 1.0) : 0;
            const double d = std::hypot(at[0] - a[0] - t01 * dx, at[1] - a[1] - t01 * dy);
            if (d < bestDistance) bestDistance = d, best = mesh.faces[t];
        }
    }
    return best;
}

// Stock minus part at the two ends of each column (see LeftoverMap).
LeftoverMap leftoverOf(const PartDexels& part, const StockDexels& stock) {
    LeftoverMap m;
    m.grid = part.grid;
    const std::size_t n = part.grid.cells();
    m.top.assign(n, 0.f), m.bottom.assign(n, 0.f);
    for (std::size_t c = 0; c < n; ++c) {
        const bool hasPart = !part.empty(c), hasStock = !stock.empty(c);
        if (!hasPart && !hasStock) continue;
        if (!hasPart) {
            double len = 0;
            for (auto* s = stock.begin(c); s != stock.end(c); ++s) len += s->z1 - s->z0;
            m.top[c] = m.bottom[c] = float(len);
            continue;
        }
        const double partTop = (part.end(c) - 1)->z1, partBottom = part.begin(c)->z0;
        if (!hasStock) {
            m.top[c] = m.bottom[c] = float(partBottom - partTop);
            continue;
        }
        m.top[c] = float(stock.top(c) - partTop);
        m.bottom[c] = float(partBottom - stock.bottom(c));
    }
    return m;
}

}  // namespace

namespace {

// The program run on the blank: the report without its coverage and leftover map (finishReport's).
SimulationReport runProgram(const PartDexels& part, const TriangleMesh& mesh, const Program& program,
                            const SimulationOptions& options, const std::vector<PriorStock>& priors,
                            StockDexels& stock) {
    if (!(options.gougeTolerance >= 0) || !(options.collisionTolerance >= 0))
        throw inputError("the gouge and collision tolerances must not be negative");
    SimulationReport r;
    r.grid = part.grid;
    r.partVolume = part.volume();
    r.triangles = mesh.triangles.size();
    r.inconsistentColumns = part.inconsistentColumns;

    const auto blank = program.hasBlank ? program.blank : bounds(mesh);
    stock = StockDexels::box(part.grid, blank);
    r.blankVolume = stock.volume();

    auto t = Clock::now();
    Run run{part, stock, options, Tally(r.gouges, options.gougeTolerance, options.maxListed),
            Tally(r.collisions, options.collisionTolerance, options.maxListed), priors};
    r.operations.resize(program.operations.size());
    for (std::size_t k = 0; k < program.operations.size(); ++k)
        runOperation(int(k), program.operations[k], run, r.operations[k]);
    r.simulateSeconds = since(t);
    r.finalStockVolume = stock.volume();
    for (auto& e : r.gouges.listed)
        if (e.wall) e.face = wallFaceNear(mesh, e.position);
    if (r.gouges.worst && r.gouges.worst->wall) r.gouges.worst->face = wallFaceNear(mesh, r.gouges.worst->position);
    for (auto& o : r.operations)
        if (o.worstGougeAt && o.worstGougeAt->wall) o.worstGougeAt->face = wallFaceNear(mesh, o.worstGougeAt->position);
    return r;
}

// What the program left against the part: only reads the part, the mesh and the final stock, so
// it may run beside the next setup's simulation.
void finishReport(SimulationReport& r, const PartDexels& part, const TriangleMesh& mesh, const Program& program,
                  const SimulationOptions& options, const StockDexels& stock) {
    const auto t = Clock::now();
    r.coverage = measureCoverage(mesh, part, stock, program.finishedFaces, program.elements, options.coverage);
    if (options.leftoverMap) r.leftover = leftoverOf(part, stock);
    r.coverageSeconds = since(t);
}

}  // namespace

SimulationReport simulate(const PartDexels& part, const TriangleMesh& mesh, const Program& program,
                          const SimulationOptions& options, const std::vector<PriorStock>& priors,
                          StockDexels* finalStock) {
    StockDexels stock;
    SimulationReport r = runProgram(part, mesh, program, options, priors, stock);
    finishReport(r, part, mesh, program, options, stock);
    if (finalStock) *finalStock = std::move(stock);
    return r;
}

namespace {

// The part rasterised on a grid over it and the blank, then simulated.
SimulationReport rasteriseAndSimulate(const TriangleMesh& mesh, const Program& program, const SimulationOptions& options,
                                      const std::vector<PriorStock>& priors, StockDexels* finalStock) {
    const auto b = bounds(mesh);
    const auto box = program.hasBlank ? program.blank : b;
    const Grid grid = gridCovering(std::min(b[0], box[0]), std::min(b[1], box[1]), std::max(b[3], box[3]),
                                   std::max(b[4], box[4]), program.cellSize);
    const auto t = Clock::now();
    const PartDexels part = rasterise(mesh, grid);
    const double seconds = since(t);
    SimulationReport r = simulate(part, mesh, program, options, priors, finalStock);
    r.rasteriseSeconds = seconds;
    return r;
}

}  // namespace

SimulationReport simulate(const TriangleMesh& mesh, const Program& program, const SimulationOptions& options) {
    validate(mesh);
    return rasteriseAndSimulate(mesh, program, options, {}, nullptr);
}

std::array<double, 3> Rigid::operator()(const std::array<double, 3>& p) const {
    const auto& m = rotation;
    return {m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + translation[0],
            m[3] * p[0] + m[4] * p[1] + m[5] * p[2] + translation[1],
            m[6] * p[0] + m[7] * p[1] + m[8] * p[2] + translation[2]};
}

Rigid Rigid::inverse() const {
    Rigid r;
    const auto& m = rotation;
    r.rotation = {m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]};  // orthonormal: the transpose
    const auto t = r({translation[0], translation[1], translation[2]});
    r.translation = {-(t[0]), -(t[1]), -(t[2])};
    return r;
}

Rigid Rigid::then(const Rigid& next) const {
    Rigid r;
    const auto& a = next.rotation;
    const auto& b = rotation;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            r.rotation[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
    r.translation = next(translation);
    return r;
}

namespace {

// Tasks 0, 1, 2 ... handed out in order to a few worker threads as they are pushed; finish() (or
// the destructor, should the pushing thread throw) waits for those pushed and joins.
class CoverageQueue {
public:
    explicit CoverageQueue(std::function<void(std::size_t)> task) : task_(std::move(task)) {
        const unsigned workers = std::clamp(std::thread::hardware_concurrency(), 1u, 4u);
        for (unsigned w = 0; w < workers; ++w) threads_.emplace_back([this] { work(); });
    }
    ~CoverageQueue() { finish(); }
    void push(std::size_t k) {
        {
            std::lock_guard<std::mutex> lock(m_);
            ready_ = k + 1;
        }
        cv_.notify_one();
    }
    void finish() {
        {
            std::lock_guard<std::mutex> lock(m_);
            done_ = true;
        }
        cv_.notify_all();
        for (std::thread& t : threads_)
            if (t.joinable()) t.join();
    }

private:
    void work() {
        for (;;) {
            std::size_t k;
            {
                std::unique_lock<std::mutex> lock(m_);
                cv_.wait(lock, [this] { return next_ < ready_ || done_; });
                if (next_ >= ready_) return;  // done and nothing left
                k = next_++;
            }
            task_(k);
        }
    }
    std::function<void(std::size_t)> task_;
    std::vector<std::thread> threads_;
    std::mutex m_;
    std::condition_variable cv_;
    std::size_t next_ = 0, ready_ = 0;
    bool done_ = false;
};

}  // namespace

std::vector<SimulationReport> simulateSetups(const TriangleMesh& partMesh, const std::vector<SetupProgram>& setups,
                                             const SimulationOptions& options) {
    validate(partMesh);
    for (const SetupProgram& s : setups) {
        const auto& m = s.toPart.rotation;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const double dot = m[i] * m[j] + m[3 + i] * m[3 + j] + m[6 + i] * m[6 + j];
                if (!(std::abs(dot - (i == j ? 1.0 : 0.0)) < 1e-9))
                    throw inputError("setup " + s.name + ": its motion to the part is not a rotation");
            }
    }
    // The setups are simulated in order on this thread (each against the stocks the setups before
    // it left); each one's coverage, which reads only its own part, mesh and final stock, is
    // measured meanwhile on the workers: on a large part it takes longer than the simulation.
    const std::size_t n = setups.size();
    std::vector<SimulationReport> reports(n);
    std::vector<StockDexels> stocks(n);
    std::vector<TriangleMesh> meshes(n);
    std::vector<PartDexels> parts(n);
    std::vector<std::exception_ptr> failed(n);
    CoverageQueue queue([&](std::size_t k) {
        try {
            finishReport(reports[k], parts[k], meshes[k], setups[k].program, options, stocks[k]);
        } catch (...) {
            failed[k] = std::current_exception();
        }
        parts[k] = PartDexels(), meshes[k] = TriangleMesh();  // no longer needed
    });
    for (std::size_t k = 0; k < n; ++k) {
        const SetupProgram& s = setups[k];
        const Rigid toSetup = s.toPart.inverse();
        meshes[k] = partMesh;
        for (Point3& v : meshes[k].vertices) v = toSetup(v);
        std::vector<PriorStock> priors;
        for (std::size_t j = 0; j < k; ++j) priors.push_back({&stocks[j], s.toPart.then(setups[j].toPart.inverse())});
        const auto b = bounds(meshes[k]);
        const auto box = s.program.hasBlank ? s.program.blank : b;
        const Grid grid = gridCovering(std::min(b[0], box[0]), std::min(b[1], box[1]), std::max(b[3], box[3]),
                                       std::max(b[4], box[4]), s.program.cellSize);
        const auto t = Clock::now();
        parts[k] = rasterise(meshes[k], grid);
        const double seconds = since(t);
        reports[k] = runProgram(parts[k], meshes[k], s.program, options, priors, stocks[k]);
        reports[k].rasteriseSeconds = seconds;
        queue.push(k);
    }
    queue.finish();
    for (const auto& e : failed)
        if (e) std::rethrow_exception(e);
    return reports;
}

}  // namespace aeronc::verify

