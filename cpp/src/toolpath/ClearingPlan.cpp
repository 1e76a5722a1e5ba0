#include "ClearingPlan.h"

#include <aeronc/core/Error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace aeronc::toolpath {
using clip::Paths;
using clip::Piece;

namespace {

constexpr int kMaxRings = 100000;
constexpr int kMaxResidualDepth = 64;
constexpr std::size_t kLinkCandidates = 8;

bool pieceContains(const Piece& piece, const Point& p) {
    const auto q = clip::toInt(p);
    if (ClipperLib::PointInPolygon(q, piece.outer) == 0) return false;
    for (const auto& h : piece.holes)
        if (ClipperLib::PointInPolygon(q, h) == 1) return false;
    return true;
}

// One connected piece of the region eroded by k step-overs; its children lie inside it, one
// step-over further in (or, with step-overs beyond the cutter's reach, in what the rings
// would miss).
struct Node {
    Piece piece;
    std::vector<int> children;
};

// The rings of a region as a forest: the pieces of region ⊖ k·s for k = 0, 1, ... A point of
// C_k outside C_{k+1} lies within s of C_k's boundary, so with s <= reach every point of the
// region is within reach of a ring. With s > reach the points of (C_k ⊖ reach) outside
// (C_{k+1} ⊕ reach) are not; they are cleared as regions of their own, nested under C_k.
class RingForest {
public:
    explicit RingForest(const ClearingOptions& o) : o_(o) {}
    std::vector<Node> nodes;

    std::vector<int> build(const Paths& region, int depth) {
        if (depth > kMaxResidualDepth) throw inputError("the clearing does not converge: lower stepOver");
        const double s = o_.stepOver, tol = o_.chordTolerance;
        const bool residual = s > o_.reach + 1e-9;
        const double reach = o_.reach + 2 * tol;
        std::vector<int> roots, prev;
        for (int k = 0;; ++k) {
            if (k > kMaxRings) throw inputError("the pocket needs more than 100,000 rings: raise stepOver");
            const std::vector<Piece> ps = k == 0 ? clip::pieces(region) : clip::offsetPieces(region, -k * s, tol);
            std::vector<int> cur;
            for (const Piece& p : ps) {
                const int id = int(nodes.size());
                nodes.push_back({p, {}});
                cur.push_back(id);
                attach(id, prev, roots);
            }
            if (residual && k > 0) {
                Paths next;
                for (const Piece& p : ps) {
                    const Paths pp = clip::pathsOf(p);
                    next.insert(next.end(), pp.begin(), pp.end());
                }
                const Paths missed = clip::subtract(clip::offset(region, -((k - 1) * s + reach), tol),
                                                    clip::offset(next, reach, tol));
                for (const Piece& m : clip::pieces(missed)) {
                    const Paths mp = clip::pathsOf(m);
                    if (clip::offset(mp, -tol, tol).empty()) continue;  // a sliver of rounding
                    for (int r : build(mp, depth + 1)) attach(r, prev, roots);
                }
            }
            if (ps.empty()) break;
            prev = std::move(cur);
        }
        return roots;
    }

private:
    void attach(int id, const std::vector<int>& parents, std::vector<int>& roots) {
        const Point anchor = clip::toPoint(nodes[id].piece.outer.front());
        for (int p : parents)
            if (pieceContains(nodes[p].piece, anchor)) {
                nodes[p].children.push_back(id);
                return;
            }
        roots.push_back(id);
    }

    const ClearingOptions& o_;
};

struct Box {
    double u0 = 1e300, v0 = 1e300, u1 = -1e300, v1 = -1e300;
    explicit Box(const std::vector<Point>& pts) {
        for (const Point& p : pts) u0 = std::min(u0, p[0]), v0 = std::min(v0, p[1]), u1 = std::max(u1, p[0]), v1 = std::max(v1, p[1]);
    }
    double gap(const Box& o) const { return std::max({o.u0 - u1, u0 - o.u1, o.v0 - v1, v0 - o.v1, 0.0}); }
};

// Where a closed polyline a (a[0] == a.back()) comes nearest a loop: x on edge a[seg] -> a[seg + 1].
struct Pair {
    double distance;
    Point x;
    std::size_t seg;
    clip::LoopPoint y;
};

// The pairs of points nearer than `limit`, nearest first: every vertex of one against the other
// (two polylines come nearest at a vertex of one of them).
std::vector<Pair> nearPairs(const std::vector<Point>& a, const Loop& l, double limit) {
    std::vector<Pair> out;
    if (Box(a).gap(Box(l)) > limit) return out;
    for (std::size_t i = 0; i + 1 < a.size(); ++i) {
        const auto y = clip::nearestOnLoop(l, a[i]);
        if (y.distance <= limit) out.push_back({y.distance, a[i], i, y});
    }
    for (std::size_t j = 0; j < l.size(); ++j) {
        double best = 1e300;
        std::size_t seg = 0;
        Point x{};
        for (std::size_t i = 0; i + 1 < a.size(); ++i) {
            const Point q = clip::nearestOnSegment(l[j], a[i], a[i + 1]);
            const double d = clip::distance(q, l[j]);
            if (d < best) best = d, seg = i, x = q;
        }
        if (best <= limit) out.push_back({best, x, seg, {l[j], j, best}});
    }
    std::sort(out.begin(), out.end(), [](const Pair& p, const Pair& q) { return p.distance < q.distance; });
    return out;
}

class Planner {
public:
    Planner(const std::vector<Node>& nodes, const Paths& allowed, const Paths& entryArea, const ClearingOptions& o)
        : nodes_(nodes), allowed_(allowed), o_(o) {
        if (!entryArea.empty())
            for (const auto& path : clip::offset(entryArea, -std::min(0.5, o.stepOver / 4), o.chordTolerance))
                for (const auto& q : path) entryPoints_.push_back(clip::toPoint(q));
        linkMax_ = o.stepOver + 4 * o.chordTolerance + 1e-3;
    }

    ClearingPlan run(std::vector<int> roots) {
        while (!roots.empty()) {
            const auto next = nearest(roots);
            const int id = roots[next];
            roots.erase(roots.begin() + long(next));
            chain_ = -1;  // separate regions never link
            cutLoops_.clear();
            visit(id);
        }
        return std::move(plan_);
    }

private:
    // Which of the nodes has its outer loop nearest the tool; the first with no chain under way.
    std::size_t nearest(const std::vector<int>& ids) const {
        if (chain_ < 0) return 0;
        std::size_t best = 0;
        double bestD = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < ids.size(); ++i) {
            for (const auto& q : nodes_[ids[i]].piece.outer) {
                const double d = clip::distance(pos_, clip::toPoint(q));
                if (d < bestD) bestD = d, best = i;
            }
        }
        return best;
    }

    // Inside-out: the children (further in) before the node's own loops.
    void visit(int id) {
        std::vector<int> todo = nodes_[id].children;
        while (!todo.empty()) {
            const auto next = nearest(todo);
            const int child = todo[next];
            todo.erase(todo.begin() + long(next));
            visit(child);
        }
        const Piece& piece = nodes_[id].piece;
        std::vector<Loop> loops{loopOf(piece.outer)};
        for (const auto& h : piece.holes) loops.push_back(loopOf(h));
        const bool leaf = nodes_[id].children.empty();
        bool first = true;
        while (!loops.empty()) {
            std::size_t pick = 0;
            if (chain_ >= 0) {
                double bestD = std::numeric_limits<double>::infinity();
                for (std::size_t i = 0; i < loops.size(); ++i) {
                    const double d = clip::nearestOnLoop(loops[i], pos_).distance;
                    if (d < bestD) bestD = d, pick = i;
                }
            }
            cut(loops[pick], leaf && first && pick == 0);
            loops.erase(loops.begin() + long(pick));
            first = false;
            ++plan_.rings;
        }
    }

    Loop loopOf(const clip::Path& p) const {
        Loop l = clip::toLoop(p);
        // Clipper gives outers counter-clockwise and holes clockwise: the material still to cut
        // lies on the right. Climb milling with a clockwise spindle wants it on the left.
        if (o_.climb) std::reverse(l.begin(), l.end());
        return l;
    }

    std::vector<Point>& path() { return plan_.chains[std::size_t(chain_)].path; }

    // `closed` starts where the chain's path ends.
    void appendLoop(const std::vector<Point>& closed) {
        auto& p = path();
        const std::size_t begin = p.size() - 1;
        p.insert(p.end(), closed.begin() + 1, closed.end());
        pos_ = p.back();
        cutLoops_.push_back(std::vector<Point>(p.begin() + long(begin), p.end()));
    }

    void cut(const Loop& loop, bool leafOuter) {
        if (chain_ >= 0 && link(loop)) return;
        if (reenter(loop)) return;
        startChain(loop, leafOuter);
    }

    // A short feed from the tool to the loop, inside the allowed region; else along the loop
    // just cut (cleared already) to where it comes nearest the new loop, then across.
    bool link(const Loop& loop) {
        const auto direct = clip::nearestOnLoop(loop, pos_);
        if (direct.distance <= linkMax_ && clip::segmentInside(allowed_, pos_, direct.at)) {
            path().push_back(direct.at);
            appendLoop(clip::loopFrom(loop, direct));
            return true;
        }
        const std::vector<Point> last = cutLoops_.back();  // starts and ends at the tool
        const auto pairs = nearPairs(last, loop, linkMax_);
        for (std::size_t k = 0; k < pairs.size() && k < kLinkCandidates; ++k) {
            const Pair& pr = pairs[k];
            if (!clip::segmentInside(allowed_, pr.x, pr.y.at)) continue;
            // Back along the loop the shorter way.
            double forward = clip::distance(last[pr.seg], pr.x);
            for (std::size_t i = 1; i <= pr.seg; ++i) forward += clip::distance(last[i - 1], last[i]);
            auto& p = path();
            if (2 * forward <= clip::length(last))
                for (std::size_t i = 1; i <= pr.seg; ++i) p.push_back(last[i]);
            else
                for (std::size_t i = last.size() - 1; i-- > pr.seg + 1;) p.push_back(last[i]);
            if (clip::distance(p.back(), pr.x) > 1e-9) p.push_back(pr.x);
            if (clip::distance(p.back(), pr.y.at) > 1e-9) p.push_back(pr.y.at);
            appendLoop(clip::loopFrom(loop, pr.y));
            return true;
        }
        return false;
    }

    // A plunge on a loop cut earlier at this level (the cutter's disc there is cleared), then a
    // short feed across to the loop.
    bool reenter(const Loop& loop) {
        for (std::size_t m = cutLoops_.size(); m-- > 0;) {
            const auto pairs = nearPairs(cutLoops_[m], loop, linkMax_);
            for (std::size_t k = 0; k < pairs.size() && k < kLinkCandidates; ++k) {
                const Pair& pr = pairs[k];
                if (!clip::segmentInside(allowed_, pr.x, pr.y.at)) continue;
                Chain c;
                c.entry.kind = Entry::Kind::Plunge;
                c.path = {pr.x};
                if (clip::distance(pr.x, pr.y.at) > 1e-9) c.path.push_back(pr.y.at);
                begin(std::move(c), clip::loopFrom(loop, pr.y));
                return true;
            }
        }
        return false;
    }

    void startChain(const Loop& loop, bool leafOuter) {
        Chain c;
        if (auto e = entryFromArea(loop)) {
            c.entry.kind = Entry::Kind::Plunge;
            c.path = {e->first, e->second.at};
            begin(std::move(c), clip::loopFrom(loop, e->second));
            return;
        }
        if (leafOuter)
            if (auto h = helixFor(loop)) {
                c.entry.kind = Entry::Kind::Helix;
                c.entry.centre = h->centre;
                c.entry.radius = h->radius;
                c.path = {h->start};
                if (clip::distance(h->start, h->to.at) > 1e-9) c.path.push_back(h->to.at);
                begin(std::move(c), clip::loopFrom(loop, h->to));
                return;
            }
        const auto at = clip::nearestOnLoop(loop, chain_ >= 0 ? pos_ : loop.front());
        const std::vector<Point> closed = clip::loopFrom(loop, at);
        c.path = {closed.front()};
        if (clip::length(closed) >= std::max(o_.reach, o_.stepOver) / 10) {
            c.entry.kind = Entry::Kind::Ramp;
            c.entry.rampEnd = closed.size() - 1;
        }
        begin(std::move(c), closed);
    }

    void begin(Chain c, const std::vector<Point>& closed) {
        plan_.chains.push_back(std::move(c));
        chain_ = int(plan_.chains.size()) - 1;
        appendLoop(closed);
    }

    // A plunge where it meets no material (beyond an open edge), then a feed to the loop.
    std::optional<std::pair<Point, clip::LoopPoint>> entryFromArea(const Loop& loop) const {
        std::vector<std::pair<double, std::size_t>> near;
        for (std::size_t i = 0; i < entryPoints_.size(); ++i) {
            const double d = clip::nearestOnLoop(loop, entryPoints_[i]).distance;
            if (d <= o_.maxEntryLink) near.push_back({d, i});
        }
        std::sort(near.begin(), near.end());
        for (std::size_t k = 0; k < near.size() && k < kLinkCandidates; ++k) {
            const Point& from = entryPoints_[near[k].second];
            const auto to = clip::nearestOnLoop(loop, from);
            if (clip::segmentInside(allowed_, from, to.at)) return std::make_pair(from, to);
        }
        return std::nullopt;
    }

    struct Helix {
        Point centre;
        double radius;
        Point start;         // on the circle, nearest the loop
        clip::LoopPoint to;  // where the chain joins the loop
    };

    // A helix inside the allowed region, centred within the leaf loop: at its centroid, or
    // deeper inside when the centroid lies outside it or too near its edge.
    std::optional<Helix> helixFor(const Loop& loop) const {
        const clip::Path outer = clip::toPath(loop);
        auto tryAt = [&](const Point& c) -> std::optional<Helix> {
            if (ClipperLib::PointInPolygon(clip::toInt(c), outer) == 0 || !clip::contains(allowed_, c)) return std::nullopt;
            const double r = std::min(o_.helixRadius, clip::boundaryDistance(allowed_, c) - 2 * o_.chordTolerance);
            if (r < o_.minHelixRadius) return std::nullopt;
            const auto to = clip::nearestOnLoop(loop, c);
            Point dir{to.at[0] - c[0], to.at[1] - c[1]};
            const double len = std::hypot(dir[0], dir[1]);
            dir = len > 1e-9 ? Point{dir[0] / len, dir[1] / len} : Point{1, 0};
            const Point start{c[0] + r * dir[0], c[1] + r * dir[1]};
            if (!clip::segmentInside(allowed_, start, to.at)) return std::nullopt;
            return Helix{c, r, start, to};
        };
        if (auto h = tryAt(clip::centroid(loop))) return h;
        for (double t : {o_.helixRadius, o_.helixRadius / 2, o_.minHelixRadius}) {
            const auto inner = clip::offsetPieces({outer}, -t, o_.chordTolerance);
            const Piece* best = nullptr;
            double bestA = 0;
            for (const auto& p : inner) {
                const double a = std::abs(ClipperLib::Area(p.outer));
                if (a > bestA) bestA = a, best = &p;
            }
            if (!best) continue;
            if (auto h = tryAt(clip::centroid(clip::toLoop(best->outer)))) return h;
            if (auto h = tryAt(clip::toPoint(best->outer.front()))) return h;
        }
        return std::nullopt;
    }

    const std::vector<Node>& nodes_;
    const Paths& allowed_;
    const ClearingOptions& o_;
    std::vector<Point> entryPoints_;
    double linkMax_ = 0;
    ClearingPlan plan_;
    int chain_ = -1;
    std::vector<std::vector<Point>> cutLoops_;  // of the region under way, as cut, the last one last
    Point pos_{};
};

}  // namespace

ClearingPlan planClearing(const Paths& centres, const Paths& allowed, const Paths& entryArea,
                          const ClearingOptions& options) {
    RingForest forest(options);
    const std::vector<int> roots = forest.build(centres, 0);
    return Planner(forest.nodes, allowed, entryArea, options).run(roots);
}

}  // namespace aeronc::toolpath
