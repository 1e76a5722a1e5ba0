#include "ChainHoles.h"

#include "FaceLists.h"
#include "HoleRecognition.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace aeronc::recognition {
namespace {

constexpr double kPi = 3.14159265358979323846;

Region circle(const P2& c, double r) {
    Region g;
    const int n = 72;
    for (int k = 0; k < n; ++k)
        g.outer.push_back(toInt({c.x + r * std::cos(2 * kPi * k / n), c.y + r * std::sin(2 * kPi * k / n)}));
    g.updateBox();
    return g;
}

void strip(std::vector<int>& v, const std::set<int>& faces) {
    v.erase(std::remove_if(v.begin(), v.end(), [&](int f) { return faces.count(f) > 0; }), v.end());
}

void stripDraft(DomainElement& e, const std::set<int>& faceNs) {
    strip(e.contourFaces, faceNs), strip(e.filletFaces, faceNs), strip(e.chamferFaces, faceNs);
    for (auto& isl : e.islandFaces) strip(isl, faceNs);
    for (AttachedFeature& a : e.attached) strip(a.faces, faceNs);
    e.attached.erase(std::remove_if(e.attached.begin(), e.attached.end(),
                                    [](const AttachedFeature& a) { return a.faces.empty() && a.element < 0; }),
                     e.attached.end());
}

}  // namespace

void addChainHoles(std::vector<ElementDraft>& made, const SetupView& view, const std::vector<HoleChain>& chains,
                   std::vector<std::vector<bool>>& taken, const std::vector<bool>& claimed) {
    const FaceCatalogue& faces = view.faces;
    const SetupFrame& frame = view.frame;
    const double tol = 10 * view.tol.linear;
    const std::size_t first = made.size();
    std::set<int> owned;  // FaceN the new holes take from the slicing's drafts
    for (std::size_t c = 0; c < chains.size(); ++c) {
        const HoleChain& ch = chains[c];
        const double along = dot(ch.axis, frame.w);
        if (std::fabs(along) < view.tol.parallelCos) continue;
        const int entry = along > 0 ? 1 : -1;
        // Its segments a tool reaches along this direction, mouth first.
        std::vector<std::size_t> run;
        for (std::size_t k = 0; k < ch.segments.size(); ++k) {
            const HoleSegment& s = ch.segments[k];
            bool mine = !taken[c][k] && std::find(s.entries.begin(), s.entries.end(), entry) != s.entries.end();
            for (int f : s.faces) mine = mine && !claimed[static_cast<std::size_t>(f)];
            if (mine) run.push_back(k);
        }
        if (run.empty()) continue;
        if (entry > 0) std::reverse(run.begin(), run.end());
        for (std::size_t k : run) taken[c][k] = true;
        // The slicing found it already when each diameter is the whole contour of one of its holes.
        std::set<int> walls;
        bool found = true;
        for (std::size_t k : run) {
            std::set<int> mine;
            for (int f : ch.segments[k].faces) mine.insert(f + 1), walls.insert(f + 1);
            bool one = false;
            for (std::size_t j = 0; j < first; ++j) {
                const DomainElement& e = made[j].el;
                one |= e.hole && std::set<int>(e.contourFaces.begin(), e.contourFaces.end()) == mine;
            }
            found = found && one;
        }
        auto overhung = [&](std::size_t k) {
            const auto& o = ch.segments[k].overhung;
            return std::find(o.begin(), o.end(), entry) != o.end();
        };
        if (found) {
            // The slicing's holes: told whether a tool as wide as each comes down to it.
            for (std::size_t k : run) {
                std::set<int> mine;
                for (int f : ch.segments[k].faces) mine.insert(f + 1);
                for (std::size_t j = 0; j < first; ++j) {
                    DomainElement& e = made[j].el;
                    if (e.hole && std::set<int>(e.contourFaces.begin(), e.contourFaces.end()) == mine)
                        e.hole->overhung = overhung(k);
                }
            }
            continue;
        }
        // A boss standing in it (a ring groove round it, milled_003's): the slicing's pocket with
        // that island, bounded by these walls alone, is the element. A hole of the whole circle
        // would cut the boss.
        bool ring = false;
        for (std::size_t j = 0; j < first && !ring; ++j) {
            const ElementDraft& d = made[j];
            if (d.dropped || d.el.contourFaces.empty() || d.el.islandFaces.empty()) continue;
            bool inside = true;
            for (int f : d.el.contourFaces) inside = inside && walls.count(f);
            ring = inside;
        }
        if (ring) continue;
        // The slicing's drafts bounded by these walls alone were this hole, seen in part.
        for (std::size_t j = 0; j < first; ++j) {
            ElementDraft& d = made[j];
            if (d.dropped || d.el.contourFaces.empty() || !d.el.islandFaces.empty()) continue;
            bool inside = true;
            for (int f : d.el.contourFaces) inside = inside && walls.count(f);
            if (inside) d.dropped = true;
        }
        owned.insert(walls.begin(), walls.end());
        for (int f : ch.cones) owned.insert(f + 1);
        // A step that is the floor of a pocket the slicing keeps stays that pocket's floor.
        std::set<int> floorsKept;
        for (std::size_t j = 0; j < first; ++j)
            if (!made[j].dropped) floorsKept.insert(made[j].el.floorFaces.begin(), made[j].el.floorFaces.end());

        auto lo = [&](const HoleSegment& s) { return along > 0 ? s.lo : -s.hi; };
        auto hi = [&](const HoleSegment& s) { return along > 0 ? s.hi : -s.lo; };
        const P2 centre = frame.project(ch.point);
        for (std::size_t i = 0; i < run.size(); ++i) {
            const HoleSegment& s = ch.segments[run[i]];
            const bool innermost = i + 1 == run.size();
            ElementDraft d;
            d.fromChain = true;
            DomainElement& e = d.el;
            e.id = static_cast<int>(made.size());
            e.type = ElementType::Hole;
            e.level = lo(s);
            e.top = hi(s);
            e.depth = e.top - e.level;
            e.area = kPi * s.radius * s.radius;
            e.minWidth = 2 * s.radius;
            e.minCornerRadius = s.radius;
            for (int f : s.faces) e.contourFaces.push_back(f + 1);
            HoleInfo h;
            h.diameter = 2 * s.radius;
            h.depth = e.depth;
            h.through = innermost && ch.through();
            h.overhung = overhung(run[i]);
            h.axis = frame.w;
            h.location = frame.world(centre, e.top);
            // The faces at its bottom: a step to the next diameter, a flat bottom, a drill point.
            for (int f : ch.steps) {
                const FaceInSetup& fs = view.fs[static_cast<std::size_t>(f)];
                if (fs.att == Attitude::Up && std::fabs(fs.h - e.level) <= tol && !floorsKept.count(f + 1)) {
                    pushUnique(e.floorFaces, f + 1);
                    owned.insert(f + 1);
                }
            }
            for (int f : ch.cones) {
                const FaceInfo& cf = faces[f];
                const FaceInSetup& cs = view.fs[static_cast<std::size_t>(f)];
                if (innermost && cs.hi <= e.level + tol && coneRadiusAt(cf, frame.w, cs.lo) < s.radius - tol) {
                    pushUnique(e.floorFaces, f + 1);  // drill point
                } else if (i == 0 && cs.lo >= e.top - tol) {
                    h.countersinkDiameter = 2 * coneRadiusAt(cf, frame.w, cs.hi);
                    h.countersinkAngle = 2 * cf.semiAngle * 180 / kPi;
                    pushUnique(e.chamferFaces, f + 1);
                    e.attached.push_back({"countersink", {f + 1}, 0, h.countersinkDiameter, -1});
                }
            }
            for (int f : e.floorFaces) e.floorArea += faces.area(f - 1);
            // The top constraint: faces square to the axis round its mouth.
            for (int f : s.faces)
                for (int nb : faces[f].neighbours) {
                    const FaceInSetup& ns = view.fs[static_cast<std::size_t>(nb)];
                    if (ns.att == Attitude::Up && std::fabs(ns.h - e.top) <= tol) pushUnique(e.topFaces, nb + 1);
                }
            e.hole = h;
            d.region = circle(centre, s.radius);
            d.sample = centre;
            made.push_back(std::move(d));
        }
    }
    if (made.size() == first) return;
    // Their faces are theirs alone.
    for (std::size_t k = 0; k < first; ++k)
        if (!made[k].dropped) stripDraft(made[k].el, owned);
    // Parents: the element at the nearest higher level whose region holds the hole's centre
    // (a pocket whose floor it pierces, its counterbore).
    for (std::size_t k = first; k < made.size(); ++k) {
        ElementDraft& in = made[k];
        int best = -1;
        double bestLevel = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < made.size(); ++j) {
            const ElementDraft& o = made[j];
            if (j == k || o.dropped || o.el.level <= in.el.level + tol || o.el.level >= bestLevel) continue;
            if (o.region.contains(in.sample)) best = static_cast<int>(j), bestLevel = o.el.level;
        }
        in.el.parent = best;
        if (best >= 0) made[static_cast<std::size_t>(best)].el.children.push_back(in.el.id);
    }
}

void releaseReservedFaces(std::vector<ElementDraft>& made, const std::vector<bool>& reserved) {
    std::set<int> faceNs;
    for (std::size_t f = 0; f < reserved.size(); ++f)
        if (reserved[f]) faceNs.insert(static_cast<int>(f) + 1);
    if (faceNs.empty()) return;
    for (ElementDraft& d : made) {
        if (d.fromChain || d.dropped) continue;
        // The slicing's own hole of such walls: from the wrong side (a counterbored hole seen
        // from its exit), the hole is the other setup's.
        bool inside = !d.el.contourFaces.empty() && d.el.islandFaces.empty();
        for (int f : d.el.contourFaces) inside = inside && faceNs.count(f);
        if (d.el.hole && inside) d.dropped = true;
        else if (!d.el.hole) stripDraft(d.el, faceNs);
    }
}

}  // namespace aeronc::recognition
