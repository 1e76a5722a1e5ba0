#include "LevelSlicing.h"

#include "FaceLists.h"
#include "HoleRecognition.h"
#include "LevelSlicer.h"
#include "Workers.h"

#include <aeronc/core/Error.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <thread>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>

namespace aeronc::recognition {
using namespace ClipperLib;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

double segmentDistance(const P2& p, const P2& a, const P2& b) {
    const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0.0;
    return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}
}  // namespace

LevelSlicing::LevelSlicing(const SetupView& view, RegionWidths& widths, std::vector<std::string>& warnings)
    : view_(view), faces_(view.faces), widths_(widths), warnings_(warnings) {
    const std::vector<FaceInSetup>& fs = view.fs;
    const double linTol = view.tol.linear;
    std::vector<double> levels{view.h0};
    for (int i = 0; i < faces_.size(); ++i) {
        const FaceInSetup& s = fs[static_cast<std::size_t>(i)];
        const bool holeWall =
            s.att == Attitude::Vertical && faces_[i].kind == SurfaceKind::Cylinder && faces_[i].concave;
        if (s.att == Attitude::Up && view.reachable(i)) levels.push_back(s.h);
        else if (s.att == Attitude::Down) levels.push_back(s.h);  // openings leave here
        else if (holeWall && onDrillPoint(view, i, s.lo)) levels.push_back(s.lo);
        else if (holeWall && s.base > s.lo + 10 * linTol) levels.push_back(s.base);  // breaks into a bore
    }
    std::sort(levels.begin(), levels.end());
    for (double l : levels)
        if (l < view.h1 - 10 * linTol && (levels_.empty() || l - levels_.back() > 10 * linTol)) levels_.push_back(l);

    for (const FaceInSetup& f : fs) critical_.push_back(f.lo), critical_.push_back(f.hi);
    std::sort(critical_.begin(), critical_.end());
}

double LevelSlicing::islandTop(const VoidRegion& c, const Path& hole, double top) const {
    // The island loop of this hole: the region's holes and its island loops need not come in
    // the same order (an exterior region's holes come from Clipper), so the nearest one.
    const SectionLoop* loop = nullptr;
    double best = kInf;
    for (const SectionLoop* L : c.islandLoops) {
        if (!L || L->pts.empty()) continue;
        const P2 p = L->pts.front();
        double d = kInf;
        for (std::size_t i = 0; i < hole.size(); ++i)
            d = std::min(d, segmentDistance(p, toP2(hole[i]), toP2(hole[(i + 1) % hole.size()])));
        if (d < best) best = d, loop = L;
    }
    if (!loop) return top;
    // The highest point of the island's walls and of the faces next to them (its top face,
    // a chamfer or round on its top edge): an estimate from above, so never a gouge.
    const std::vector<FaceInSetup>& fs = view_.fs;
    double hi = -kInf;
    for (int f : loop->faces) {
        hi = std::max(hi, fs[static_cast<std::size_t>(f)].hi);
        for (int n : faces_[f].neighbours) hi = std::max(hi, fs[static_cast<std::size_t>(n)].hi);
    }
    return std::isfinite(hi) ? std::min(hi, top) : top;
}

namespace {
// The segments of the section loops that run on face f.
std::vector<std::pair<P2, P2>> segmentsOn(const std::vector<SectionLoop>& loops, int f) {
    std::vector<std::pair<P2, P2>> out;
    for (const SectionLoop& L : loops)
        for (std::size_t k = 0; k < L.pts.size() && k < L.faces.size(); ++k)
            if (L.faces[k] == f) out.push_back({L.pts[k], L.pts[(k + 1) % L.pts.size()]});
    return out;
}

// How far any end of a's segments lies from b's nearest segment.
double farthestFrom(const std::vector<std::pair<P2, P2>>& a, const std::vector<std::pair<P2, P2>>& b) {
    double worst = 0;
    for (const auto& s : a)
        for (const P2& p : {s.first, s.second}) {
            double d = kInf;
            for (const auto& t : b) d = std::min(d, segmentDistance(p, t.first, t.second));
            worst = std::max(worst, d);
        }
    return worst;
}
}  // namespace

Paths LevelSlicing::leaningMaterial(const VoidRegion& c, double h, double zl, double z,
                                    std::vector<int>& leaning) const {
    const std::vector<FaceInSetup>& fs = view_.fs;
    const double tol = 10 * view_.tol.linear;
    if (!(z - zl > 0.1 * tol)) return {};
    Paths near, nearFloor;  // footprints of the material sampled at zl, and at the floor
    auto footprint = [&](int f) {
        P2 lo, hi;
        view_.faceBox(f, lo, hi);
        return Path{toInt(lo), toInt({hi.x, lo.y}), toInt(hi), toInt({lo.x, hi.y})};
    };
    // The faces along the region's boundary: its walls, and those its contour loops run on (an
    // exterior region knows its walls by probes only).
    std::vector<int> bounding = c.contourFaces;
    for (const SectionLoop* L : c.contourLoops)
        for (int f : L->faces) pushUnique(bounding, f);
    // And its islands' faces: a cone widening to its foot (FTC-06's) stands wider at the floor.
    for (const SectionLoop* L : c.islandLoops)
        if (L)
            for (int f : L->faces) pushUnique(bounding, f);
    std::vector<int> down;  // leaning faces going on down past zl, into the fillets' band
    for (int f : bounding) {
        const FaceInSetup& s = fs[static_cast<std::size_t>(f)];
        const bool facesUp = s.att == Attitude::Inclined && dot(faces_[f].normal, view_.frame.w) > 0;
        // A curved face spanning the band: a round falling past the floor, or a fillet across
        // the axis whose section moves with the height (seen from a tilted setup its foot
        // stands further into the region at the floor than at the slice).
        const bool spans = s.att == Attitude::Curved && s.lo < zl && s.hi > z;
        if (!facesUp && !spans) continue;
        // The region's walls among them: bevels and rounds (a hole across the axis is concave,
        // and what the region loses beside it is not its wall).
        const bool wall = std::find(c.contourFaces.begin(), c.contourFaces.end(), f) != c.contourFaces.end();
        if (wall && (facesUp || !faces_[f].concave)) leaning.push_back(f);
        // Its footprint: its box in the setup's frame (the same however the part is placed).
        near.push_back(footprint(f));
        if (s.lo < zl - 2 * tol) down.push_back(f);
    }
    // Floor fillets: the slice stands over them, and the cutter keeps off them by the least
    // radius of the round ones (cylinders, tori, spheres). A blend of another kind (a B-spline)
    // rising higher than that, or with no round fillet beside it, is kept off at the floor.
    std::vector<int> blends;
    double radius = kInf;
    for (int fl : c.floors)
        for (int n : faces_[fl].neighbours) {
            const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
            const SurfaceKind k = faces_[n].kind;
            if (s.att != Attitude::Curved || k == SurfaceKind::Cone || !(s.hi > h + tol)) continue;
            if (k == SurfaceKind::Cylinder || k == SurfaceKind::Torus || k == SurfaceKind::Sphere)
                radius = std::min(radius, faces_[n].radius);
            else if (std::fabs(s.lo - h) <= tol)
                pushUnique(blends, n);
        }
    if (!std::isfinite(radius)) radius = 0;  // no round fillet: the walls are taken to meet the floor
    for (int n : blends)
        if (!(fs[static_cast<std::size_t>(n)].hi - h <= radius + tol)) nearFloor.push_back(footprint(n));
    Paths out;
    auto within = [&](const Paths& material, const Paths& boxes) {
        if (boxes.empty()) return;
        Clipper clip;
        clip.AddPaths(material, ptSubject, true);
        clip.AddPaths(boxes, ptClip, true);
        Paths part;
        clip.Execute(ctIntersection, part, pftEvenOdd, pftNonZero);
        out.insert(out.end(), part.begin(), part.end());
    };
    within(materialAt(zl), near);
    // A leaning face going on down past the fillets' top leans out further still to the floor
    // (milled_002's bevel meeting the floor beside its blends): the material at the floor as far
    // from its foot as its section at zl lies (not its whole box, which would keep the region off
    // the round fillets beside it too, those the cutter's corner is told of).
    // Just over the floor: a plane through the floor's edges would give degenerate sections.
    if (!(zl - h > 2 * tol) || (down.empty() && nearFloor.empty())) return out;
    const double hf = h + std::min(tol, 0.5 * (zl - h));
    std::vector<std::string> ignored;
    const std::vector<SectionLoop> atFloor =
        sliceLoops(faces_, cutFaces(hf), view_.frame, hf, view_.tol.chord, view_.tol.linear, ignored, view_.meshes);
    if (!down.empty()) {
        const std::vector<SectionLoop> atLow =
            sliceLoops(faces_, cutFaces(zl), view_.frame, zl, view_.tol.chord, view_.tol.linear, ignored, view_.meshes);
        for (int f : down) {
            const auto foot = segmentsOn(atFloor, f), above = segmentsOn(atLow, f);
            if (foot.empty()) continue;
            if (above.empty()) {
                nearFloor.push_back(footprint(f));
                continue;
            }
            const double lean = std::max(farthestFrom(foot, above), farthestFrom(above, foot)) + tol;
            Paths lines;
            for (const auto& sg : foot) lines.push_back({toInt(sg.first), toInt(sg.second)});
            ClipperOffset strip;
            strip.AddPaths(lines, jtRound, etOpenRound);
            Paths band;
            strip.Execute(band, lean * kClipperScale);
            nearFloor.insert(nearFloor.end(), band.begin(), band.end());
        }
    }
    Paths material;
    for (const SectionLoop& L : atFloor) {
        Path q;
        for (const P2& p : L.pts) q.push_back(toInt(p));
        material.push_back(q);
    }
    within(material, nearFloor);
    return out;
}

namespace {
// The height along w where a round face's section seen along w is widest: a sphere's centre,
// the centre plane of a torus about w, the axis of a cylinder square to w; NaN for others.
double equatorHeight(const FaceInfo& f, const Vec3& w) {
    const double along = std::fabs(dot(f.axisDir, w));
    if (f.kind == SurfaceKind::Sphere) return dot(f.axisPoint, w);
    if (f.kind == SurfaceKind::Torus && along > 1 - 1e-9) return dot(f.axisPoint, w);
    if (f.kind == SurfaceKind::Cylinder && along < 1e-9) return dot(f.axisPoint, w);
    return std::numeric_limits<double>::quiet_NaN();
}
}  // namespace

Paths LevelSlicing::overhangingMaterial(const VoidRegion& c, double z, double top) const {
    const std::vector<FaceInSetup>& fs = view_.fs;
    const double tol = 10 * view_.tol.linear;
    if (!(top - z > 2 * tol)) return {};
    // The faces bounding the region and its islands.
    std::vector<int> bounding = c.contourFaces;
    for (const SectionLoop* L : c.contourLoops)
        for (int f : L->faces) pushUnique(bounding, f);
    for (const SectionLoop* L : c.islandLoops)
        if (L)
            for (int f : L->faces) pushUnique(bounding, f);
    // And the round faces joined to them through round faces, up to three faces on, above
    // the slice: a dome over the neck and the blend the slice cuts (FTC-06's).
    for (std::size_t from = 0, ring = 0; ring < 3; ++ring) {
        const std::size_t to = bounding.size();
        for (std::size_t k = from; k < to; ++k)
            for (int g : faces_[bounding[k]].neighbours) {
                const FaceInSetup& s = fs[static_cast<std::size_t>(g)];
                if (s.att == Attitude::Curved && s.hi > z + 2 * tol) pushUnique(bounding, g);
            }
        from = to;
    }
    // Height (rounded to 0.01 mm) -> boxes of the faces whose material is sampled there.
    std::map<long long, Paths> boxesAt;
    for (int f : bounding) {
        const FaceInSetup& s = fs[static_cast<std::size_t>(f)];
        // A plane facing down leans over the region, widest at its top; a curved face (a drafted
        // corner round) may lean either way: sampled through its height.
        const bool facesDown = s.att == Attitude::Inclined && dot(faces_[f].normal, view_.frame.w) < 0;
        if (!facesDown && s.att != Attitude::Curved) continue;
        const double a = std::max(z, s.lo), b = std::min(top, s.hi);
        if (!(b - a > 2 * tol)) continue;
        P2 lo, hi;
        view_.faceBox(f, lo, hi);
        const Path box{toInt(lo), toInt({hi.x, lo.y}), toInt(hi), toInt({lo.x, hi.y})};
        const int samples = facesDown ? 1 : 4;
        for (int k = 0; k < samples; ++k) {
            const double at = b - tol - (b - a - 2 * tol) * k / samples;
            boxesAt[std::llround(at * 100)].push_back(box);
        }
        // A round face is widest at its equator (a dome's sphere reaching below its centre,
        // FTC-06's): sampled there too, or the island is taken narrower than it stands.
        const double widest = equatorHeight(faces_[f], view_.frame.w);
        if (facesDown || !(widest > a + tol && widest < b - tol)) continue;
        boxesAt[std::llround(widest * 100)].push_back(box);
    }
    Paths out;
    for (const auto& [key, boxes] : boxesAt) {
        Clipper clip;
        clip.AddPaths(materialAt(key / 100.0), ptSubject, true);
        clip.AddPaths(boxes, ptClip, true);
        Paths part;
        clip.Execute(ctIntersection, part, pftEvenOdd, pftNonZero);
        out.insert(out.end(), part.begin(), part.end());
    }
    return out;
}

Paths LevelSlicing::materialAt(double z) const {
    std::vector<std::string> ignored;
    const std::vector<SectionLoop> loops =
        sliceLoops(faces_, cutFaces(z), view_.frame, z, view_.tol.chord, view_.tol.linear, ignored, view_.meshes);
    Paths out;
    for (const SectionLoop& L : loops) {
        Path p;
        for (const P2& q : L.pts) p.push_back(toInt(q));
        out.push_back(p);
    }
    return out;
}

std::vector<VoidRegion> LevelSlicing::trimToReach(const VoidRegion& c, double h, double z, double low, double top,
                                                  std::vector<std::string>& warnings) const {
    const std::vector<FaceInSetup>& fs = view_.fs;
    const double tol = 10 * view_.tol.linear;
    // Walls leaning back hold more material at the floor than at the slice: the region (the
    // pocket the tool may clear down to its floor) keeps off it. No warning: a bevel or a round
    // falling past the floor is ordinary geometry.
    std::vector<int> leaningFaces;
    Paths leaning = leaningMaterial(c, h, low, z, leaningFaces);
    // Walls leaning over the region (an island wider at its top): their material at the top.
    for (Path& p : overhangingMaterial(c, z, top)) leaning.push_back(std::move(p));
    // Material over the region starts above an underside between the slice and the top: a
    // plane facing down, an inclined plane (a dovetail) or a curved face (the vault of a hole
    // across the axis) ending there.
    std::vector<double> heights;
    for (int i = 0; i < faces_.size(); ++i) {
        const FaceInSetup& s = fs[static_cast<std::size_t>(i)];
        if (s.att != Attitude::Down && s.att != Attitude::Curved && s.att != Attitude::Inclined) continue;
        if (!(s.hi > z + tol && s.hi < top - tol)) continue;
        // Over the region at all: its box seen along the axis overlaps the region's.
        const Vec3 &a = faces_[i].boxMin, &b = faces_[i].boxMax;
        P2 lo{kInf, kInf}, hi{-kInf, -kInf};
        for (int k = 0; k < 8; ++k) {
            const P2 q = view_.frame.project(Vec3{k & 1 ? b[0] : a[0], k & 2 ? b[1] : a[1], k & 4 ? b[2] : a[2]});
            lo = {std::min(lo.x, q.x), std::min(lo.y, q.y)}, hi = {std::max(hi.x, q.x), std::max(hi.y, q.y)};
        }
        if (hi.x < c.region.lo.x || lo.x > c.region.hi.x || hi.y < c.region.lo.y || lo.y > c.region.hi.y) continue;
        heights.push_back(s.hi);
    }
    if (heights.empty() && leaning.empty()) return {c};
    std::sort(heights.begin(), heights.end());
    heights.erase(std::unique(heights.begin(), heights.end(), [&](double a, double b) { return b - a <= tol; }),
                  heights.end());
    Paths reach = c.region.paths();
    if (!leaning.empty()) {
        Clipper cut;
        cut.AddPaths(reach, ptSubject, true);
        cut.AddPaths(leaning, ptClip, true);
        Paths left;
        cut.Execute(ctDifference, left, pftNonZero, pftNonZero);
        reach = left;
    }
    double unleaned = 0;
    for (const Path& p : reach) unleaned += Area(p) / (kClipperScale * kClipperScale);
    for (double hd : heights) {
        // Just above the underside, short of the next height where a face starts or ends.
        double next = top;
        for (double x : critical_)
            if (x > hd + tol) {
                next = std::min(next, x);
                break;
            }
        Clipper material;
        material.AddPaths(materialAt(0.5 * (hd + next)), ptClip, true);
        material.AddPaths(reach, ptSubject, true);
        Paths left;
        material.Execute(ctDifference, left, pftNonZero, pftEvenOdd);
        reach = left;
    }
    double before = c.region.area(), after = 0;
    for (const Path& p : reach) after += Area(p) / (kClipperScale * kClipperScale);
    if (after >= before - std::max(0.01, 1e-4 * before)) return {c};
    Clipper pieces;
    pieces.AddPaths(reach, ptSubject, true);
    PolyTree tree;
    pieces.Execute(ctUnion, tree, pftNonZero, pftNonZero);
    std::vector<const PolyNode*> kept;
    const PolyNode* largest = nullptr;
    double largestArea = 0;
    for (const PolyNode* n = tree.GetFirst(); n; n = n->GetNext()) {
        if (n->IsHole()) continue;
        const double a = std::fabs(Area(n->Contour));
        if (a / (kClipperScale * kClipperScale) < 1e-3 * before) continue;
        kept.push_back(n);
        if (a > largestArea) largestArea = a, largest = n;
    }
    char b[200];
    if (!largest) {
        std::snprintf(b, sizeof b, "level %.3f: a region of %.1f mm2 lies wholly under material (an undercut): left out",
                      h, before);
        warnings.push_back(b);
        return {};
    }
    if (after < unleaned - std::max(0.01, 1e-4 * before)) {
        std::snprintf(b, sizeof b,
                      "level %.3f: %.1f mm2 of a region of %.1f mm2 lie under material (an undercut): left out of the "
                      "pocket",
                      h, unleaned - after, before);
        warnings.push_back(b);
    }
    // Each piece reachable from above that holds some of the floors is a pocket of its own
    // (the trim may part a bore from the region it joined through a cross hole, or two
    // pockets alike); a region without floors keeps its largest piece.
    std::vector<VoidRegion> out;
    for (const PolyNode* n : kept) {
        if (c.floors.empty() && n != largest) continue;
        VoidRegion piece = c;
        Region& r = piece.region;
        r.outer = n->Contour;
        if (!Orientation(r.outer)) ReversePath(r.outer);
        r.holes.clear();
        for (const PolyNode* hole : n->Childs) {
            Path p = hole->Contour;
            if (Orientation(p)) ReversePath(p);
            r.holes.push_back(p);
        }
        r.updateBox();
        if (!c.floors.empty() && !keepReachedFloors(piece)) continue;
        if (!r.contains(piece.sample)) piece.sample = r.interiorPoint();
        // The islands standing in this piece.
        piece.islandFaces.clear(), piece.islandLoops.clear();
        for (std::size_t k = 0; k < c.islandLoops.size(); ++k) {
            const SectionLoop* L = c.islandLoops[k];
            if (L && !L->pts.empty() && PointInPolygon(toInt(L->pts.front()), r.outer) == 0) continue;
            piece.islandFaces.push_back(c.islandFaces[k]);
            piece.islandLoops.push_back(L);
        }
        // The pieces of the open edges still on the boundary: where an outer segment runs along one.
        std::vector<std::pair<P2, P2>> open;
        for (const auto& oe : c.openEdges) {
            const double ex = oe.second.x - oe.first.x, ey = oe.second.y - oe.first.y, len = std::hypot(ex, ey);
            if (!(len > 0)) continue;
            auto along = [&](const P2& p) { return ((p.x - oe.first.x) * ex + (p.y - oe.first.y) * ey) / len; };
            auto off = [&](const P2& p) { return std::fabs((p.x - oe.first.x) * ey - (p.y - oe.first.y) * ex) / len; };
            for (std::size_t i = 0; i < r.outer.size(); ++i) {
                const P2 a = toP2(r.outer[i]), q = toP2(r.outer[(i + 1) % r.outer.size()]);
                if (off(a) > 1e-3 || off(q) > 1e-3) continue;
                const double s0 = std::max(0.0, std::min(along(a), along(q))), s1 = std::min(len, std::max(along(a), along(q)));
                if (s1 - s0 <= 1e-3) continue;
                open.push_back({{oe.first.x + ex * s0 / len, oe.first.y + ey * s0 / len},
                                {oe.first.x + ex * s1 / len, oe.first.y + ey * s1 / len}});
            }
        }
        piece.openEdges = open;
        // The walls it still has: faces with a piece of section on the new boundary.
        auto onBoundary = [&](const P2& m) {
            auto near = [&](const Path& path) {
                for (std::size_t i = 0; i < path.size(); ++i)
                    if (segmentDistance(m, toP2(path[i]), toP2(path[(i + 1) % path.size()])) <= tol) return true;
                return false;
            };
            if (near(r.outer)) return true;
            for (const Path& hp : r.holes)
                if (near(hp)) return true;
            return false;
        };
        std::vector<int> walls, others;
        for (const SectionLoop* L : c.contourLoops)
            for (std::size_t k = 0; k < L->pts.size(); ++k) {
                const P2& a = L->pts[k];
                const P2& q = L->pts[(k + 1) % L->pts.size()];
                const int f = L->faces[k];
                if (!onBoundary({0.5 * (a.x + q.x), 0.5 * (a.y + q.y)})) continue;
                const bool wall = std::find(c.contourFaces.begin(), c.contourFaces.end(), f) != c.contourFaces.end();
                pushUnique(wall ? walls : others, f);
            }
        // A leaning wall bounds the region at its foot, below the slice: those beside this piece.
        for (int f : leaningFaces) {
            P2 lo, hi;
            view_.faceBox(f, lo, hi);
            if (hi.x >= r.lo.x - tol && lo.x <= r.hi.x + tol && hi.y >= r.lo.y - tol && lo.y <= r.hi.y + tol)
                walls.push_back(f);
        }
        std::vector<int> wallsKept;
        for (int f : c.contourFaces)
            if (std::find(walls.begin(), walls.end(), f) != walls.end()) wallsKept.push_back(f);
        // A piece parted from the region's walls (a bore reached through a cross hole) is
        // bounded by the faces of the section along its own boundary.
        if (wallsKept.empty()) wallsKept = others;
        if (!wallsKept.empty()) piece.contourFaces = wallsKept;
        out.push_back(std::move(piece));
    }
    return out;
}

double LevelSlicing::sliceHeight(std::size_t k, std::vector<int>& ups, double* low) const {
    const std::vector<FaceInSetup>& fs = view_.fs;
    const double h = levels_[k];
    const double hn = k + 1 < levels_.size() ? levels_[k + 1] : view_.h1;
    const double h1 = view_.h1;
    const double tol = 10 * view_.tol.linear;
    // Slice above floor fillets and bottom chamfers so the loops run on the walls.
    double excess = 0;
    for (int i = 0; i < faces_.size(); ++i) {
        const FaceInSetup& s = fs[static_cast<std::size_t>(i)];
        if (s.att != Attitude::Up || std::fabs(s.h - h) > tol || !view_.reachable(i)) continue;
        ups.push_back(i);
        for (int n : faces_[i].neighbours) {
            const FaceInSetup& ns = fs[static_cast<std::size_t>(n)];
            if (ns.att == Attitude::Curved && faces_[n].kind != SurfaceKind::Cone && std::fabs(ns.lo - h) <= tol)
                excess = std::max(excess, ns.hi - h);
        }
    }
    // Mid-way to the next height where any face starts or ends: a plane through an
    // edge would give degenerate sections.
    // Blends that rise to the level above (a shallow engraving rounded to its top) leave no
    // wall to cut: then the blends are cut.
    const double base = h + excess < std::min(hn, h1) - tol ? h + excess : h;
    double next = h1;
    for (double c : critical_) {
        if (c > base + tol) {
            next = c;
            break;
        }
    }
    const double z = 0.5 * (base + std::min(next, hn > base + tol ? hn : next));
    if (low) *low = base + std::min(tol, 0.5 * (z - base));
    return z;
}

std::vector<int> LevelSlicing::cutFaces(double z) const {
    std::vector<int> cands;
    const double margin = 0.5;  // boxes of spline faces can be tight; extra faces cost little
    for (int i = 0; i < faces_.size(); ++i) {
        const FaceInSetup& f = view_.fs[static_cast<std::size_t>(i)];
        const double m = (f.att == Attitude::Up || f.att == Attitude::Down) ? 0.0 : margin;
        if (f.lo - m < z && f.hi + m > z) cands.push_back(i);
    }
    return cands;
}

bool LevelSlicing::useful(std::size_t k, const std::vector<bool>& claimed) const {
    // An element whose floor an earlier setup machines is dropped, and so is one without a
    // floor whose walls it all machines: a level where that holds of every floor and every
    // face cut makes nothing.
    std::vector<int> ups;
    const double z = sliceHeight(k, ups);
    for (int i : ups)
        if (!claimed[static_cast<std::size_t>(i)]) return true;
    for (int i : cutFaces(z))
        if (!claimed[static_cast<std::size_t>(i)]) return true;
    return false;
}

void LevelSlicing::slice(std::size_t k, int setupId, std::vector<ElementDraft>& made,
                         std::vector<std::string>& warnings) {
    const std::vector<FaceInSetup>& fs = view_.fs;
    const SetupFrame& frame = view_.frame;
    const double h = levels_[k];
    const double h1 = view_.h1;
    const bool bottom = k == 0;
    const double tol = 10 * view_.tol.linear;
    std::vector<int> ups;
    double low = 0;
    const double z = sliceHeight(k, ups, &low);
    const std::vector<int> cands = cutFaces(z);
    const auto ts = std::chrono::steady_clock::now();
    std::vector<SectionLoop> loops = sliceLoops(faces_, cands, frame, z, view_.tol.chord, view_.tol.linear, warnings,
                                                view_.meshes);
    if (std::getenv("AERONC_TRACE"))
        std::fprintf(stderr, "  level %.3f: %zu faces cut, %zu loops, %.3f s\n", h, cands.size(), loops.size(),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count());

    std::vector<VoidRegion> regions = voidRegions(loops, view_.blankLo, view_.blankHi, view_.tol.linear);
    // An element's top: its highest wall, or for a region open to the blank the blank's top
    // (above the part's on a tilted axis, where the box's corner rises over the region).
    auto topOf = [&](const VoidRegion& c) {
        double top = -kInf;
        for (int f : c.contourFaces) top = std::max(top, fs[static_cast<std::size_t>(f)].hi);
        if (c.exterior || !std::isfinite(top)) top = std::max(top, h1);
        if (c.exterior && view_.clampedBlankTop > top + tol) top = view_.clampedBlankTop;
        return top;
    };

    // Floors and rib tops at this level, placed in the region above them.
    auto regionAt = [&](const P2& p) -> int {
        int best = -1;
        double bestArea = kInf;
        for (std::size_t r = 0; r < regions.size(); ++r) {
            const Region& g = regions[r].region;
            if (!g.contains(p)) continue;
            const double a = (g.hi.x - g.lo.x) * (g.hi.y - g.lo.y);
            if (a < bestArea) bestArea = a, best = static_cast<int>(r);
        }
        return best;
    };
    for (int i : ups) {
        bool rising = false;
        for (int n : faces_[i].neighbours) rising |= fs[static_cast<std::size_t>(n)].hi > h + tol;
        const Vec3 wp = faces_.interiorPoint(i);
        const P2 p = frame.project(wp);
        const int r = regionAt(p);
        if (r < 0) continue;  // under material: not reachable from this side
        VoidRegion& c = regions[static_cast<std::size_t>(r)];
        if (rising) {
            c.floors.push_back(i);
            if (!c.hasSample) c.sample = p, c.hasSample = true;
        } else {
            c.ribTops.push_back(i);
        }
    }

    for (std::size_t r = 0; r < regions.size(); ++r) {
        VoidRegion& c = regions[r];
        // A drilled hole ends here on a drill point (cone or sphere under its walls): a ray
        // down its axis runs on to the point's apex, so this comes before the exit test.
        bool drillPoint = !c.floors.empty() || c.exterior ? false : !c.contourFaces.empty() && c.islandFaces.empty();
        if (drillPoint)
            for (int f : c.contourFaces)
                drillPoint = drillPoint && faces_[f].kind == SurfaceKind::Cylinder && faces_[f].concave &&
                             std::fabs(fs[static_cast<std::size_t>(f)].lo - h) <= tol && onDrillPoint(view_, f, h);
        ElementType type;
        if (!c.floors.empty()) {
            type = c.exterior ? ElementType::OpenPocket : ElementType::ClosedPocket;
        } else if (c.exterior) {
            continue;
        } else if (drillPoint) {
            type = ElementType::ClosedPocket;
        } else if (bottom || leavesPart(c, h, z)) {
            // Walls ending on material (the rounds of a pocket below continuing them) make a
            // pocket whose floor is the cavity below: taken down to its level, not through.
            type = !bottom && materialUnder(c, h) ? ElementType::ClosedPocket : ElementType::Opening;
        } else {
            continue;
        }
        if (!c.hasSample) c.sample = c.region.interiorPoint();
        if (type == ElementType::Opening) {
            // Bounded only by cones or chamfers: the mouth of a hole, not an opening.
            bool wall = false;
            for (int f : c.contourFaces) wall |= fs[static_cast<std::size_t>(f)].att == Attitude::Vertical;
            if (!wall) continue;
            // Capped from above anywhere (a cavity seen from the wrong side, maybe with a hole
            // in its floor): not machinable here.
            if (capped(c, z)) continue;
        }
        for (const VoidRegion& piece : trimToReach(c, h, z, low, topOf(c), warnings)) {
            ElementDraft in;
            DomainElement& e = in.el;
            e.id = static_cast<int>(made.size());
            e.setup = setupId;
            e.type = type;
            e.level = h;
            e.area = piece.region.area();
            e.minWidth = -1;  // measured once it is known to stay (measureWidths)
            for (int f : piece.contourFaces) e.contourFaces.push_back(f + 1);
            for (auto& isl : piece.islandFaces) {
                std::vector<int> v;
                for (int f : isl) v.push_back(f + 1);
                e.islandFaces.push_back(v);
            }
            for (int f : piece.floors) {
                e.floorFaces.push_back(f + 1);
                e.floorArea += faces_.area(f);
            }
            const double top = topOf(piece);
            e.top = top;
            e.depth = top - e.level;
            for (const IntPoint& ip : piece.region.outer) e.contour.push_back(frame.world(toP2(ip), h));
            for (const Path& hp : piece.region.holes) {
                Polyline pl;
                for (const IntPoint& ip : hp) pl.push_back(frame.world(toP2(ip), h));
                e.islands.push_back(pl);
                e.islandTops.push_back(islandTop(piece, hp, e.top));
            }
            for (auto& oe : piece.openEdges) e.openEdges.push_back({frame.world(oe.first, h), frame.world(oe.second, h)});
            measureCorners(piece, faces_, fs, e);
            for (int rt : piece.ribTops) {
                AttachedFeature a;
                a.kind = "island_top";
                a.faces = {rt + 1};
                e.attached.push_back(a);
            }
            in.region = piece.region;
            in.sample = piece.sample;
            made.push_back(std::move(in));
        }
    }
}

void LevelSlicing::sliceAll(int setupId, std::vector<ElementDraft>& made, int threads,
                            const std::function<bool(double)>& progress, const std::vector<bool>& claimed) {
    std::vector<std::size_t> todo;
    for (std::size_t k = 0; k < levels_.size(); ++k)
        if (useful(k, claimed)) todo.push_back(k);
    const std::size_t n = todo.size();
    std::vector<std::vector<ElementDraft>> perLevel(n);
    std::vector<std::vector<std::string>> warned(n);
    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> stop{false};
    std::exception_ptr failure;
    std::mutex failureMutex;
    // One level; the first failure stops every thread and is rethrown here.
    auto sliceOne = [&](std::size_t k) {
        try {
            slice(todo[k], setupId, perLevel[k], warned[k]);
        } catch (...) {
            std::lock_guard<std::mutex> lock(failureMutex);
            if (!failure) failure = std::current_exception();
            stop = true;
        }
        ++done;
    };
    auto work = [&](int slot) {
        setWorkerSlot(slot);
        for (std::size_t k; !stop && (k = next++) < n;) sliceOne(k);
    };
    const int helpers = std::max(0, std::min(threads, static_cast<int>(n)) - 1);
    std::vector<std::thread> pool;
    for (int t = 0; t < helpers; ++t) pool.emplace_back(work, t + 1);
    // This thread slices too, and reports between its levels.
    for (std::size_t k; !stop && (k = next++) < n;) {
        if (progress && !progress(double(done) / n)) {
            stop = true;
            break;
        }
        sliceOne(k);
    }
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
    if (stop) throw inputError("recognition cancelled");
    for (std::size_t k = 0; k < n; ++k) {
        for (ElementDraft& d : perLevel[k]) {
            d.el.id = static_cast<int>(made.size());
            made.push_back(std::move(d));
        }
        warnings_.insert(warnings_.end(), warned[k].begin(), warned[k].end());
    }
}

bool LevelSlicing::capped(const VoidRegion& c, double z) const {
    if (view_.rays().anyHit(view_.frame.world(c.sample, z), true)) return true;
    const double inset = std::max(0.05, 100 * view_.tol.linear);
    for (const P2& p : c.region.boundaryProbes(inset, 16))
        if (view_.rays().anyHit(view_.frame.world(p, z), true)) return true;
    return false;
}

// An opening: the region's walls all end at this level and below it lies no material.
bool LevelSlicing::leavesPart(VoidRegion& c, double h, double z) const {
    if (c.contourFaces.empty()) return false;
    for (int f : c.contourFaces)
        if (std::fabs(view_.fs[static_cast<std::size_t>(f)].base - h) > 10 * view_.tol.linear) return false;
    if (!c.hasSample) c.sample = c.region.interiorPoint(), c.hasSample = true;
    // Looking down from the slice: material right under the level means a floor, not an exit.
    const Vec3 q = view_.frame.world(c.sample, z);
    const double margin = std::max(0.1, 100 * view_.tol.linear);
    return view_.rays().firstHit(q, false) > z - h + margin;
}

bool LevelSlicing::keepReachedFloors(VoidRegion& c) const {
    auto reached = [&](int f) { return c.region.contains(view_.frame.project(faces_.interiorPoint(f))); };
    c.floors.erase(std::remove_if(c.floors.begin(), c.floors.end(), [&](int f) { return !reached(f); }), c.floors.end());
    c.ribTops.erase(std::remove_if(c.ribTops.begin(), c.ribTops.end(), [&](int f) { return !reached(f); }),
                    c.ribTops.end());
    return !c.floors.empty();
}

bool LevelSlicing::materialUnder(const VoidRegion& c, double h) const {
    // As deep as an opening is broken through, the cutter's corner radius below that.
    const double depth = 2.0;
    const double tol = 10 * view_.tol.linear;
    double zp = h - depth;
    for (double x : critical_)
        if (std::fabs(x - zp) <= tol) zp = x - 3 * tol;  // a plane through an edge cuts badly
    const Paths under = materialAt(zp);
    if (under.empty()) return false;
    // Inside the region by more than the sections' chords: a wall's own section is no material under.
    const double inset = std::max(0.05, 10 * view_.tol.chord);
    ClipperOffset off;
    off.AddPaths(c.region.paths(), jtMiter, etClosedPolygon);
    Paths inner;
    off.Execute(inner, -inset * kClipperScale);
    Clipper clip;
    clip.AddPaths(inner, ptSubject, true);
    clip.AddPaths(under, ptClip, true);
    Paths both;
    clip.Execute(ctIntersection, both, pftNonZero, pftEvenOdd);
    double area = 0;
    for (const Path& p : both) area += std::fabs(Area(p)) / (kClipperScale * kClipperScale);
    return area > std::max(0.05, 1e-4 * c.region.area());
}

}  // namespace aeronc::recognition
