#include "LevelSlicing.h"

#include "FaceLists.h"
#include "HoleRecognition.h"
#include "LevelSlicer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace aeronc::recognition {
using namespace ClipperLib;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
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

void LevelSlicing::slice(std::size_t k, int setupId, std::vector<ElementDraft>& made) {
    const std::vector<FaceInSetup>& fs = view_.fs;
    const SetupFrame& frame = view_.frame;
    const double h = levels_[k];
    const double hn = k + 1 < levels_.size() ? levels_[k + 1] : view_.h1;
    const double h1 = view_.h1;
    const bool bottom = k == 0;
    const double tol = 10 * view_.tol.linear;
    // Slice above floor fillets and bottom chamfers so the loops run on the walls.
    std::vector<int> ups;
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
    const double base = h + excess;
    double next = h1;
    for (double c : critical_) {
        if (c > base + tol) {
            next = c;
            break;
        }
    }
    const double z = 0.5 * (base + std::min(next, hn > base + tol ? hn : next));

    std::vector<int> cands;
    const double margin = 0.5;  // boxes of spline faces can be tight; extra faces cost little
    for (int i = 0; i < faces_.size(); ++i) {
        const FaceInSetup& f = fs[static_cast<std::size_t>(i)];
        const double m = (f.att == Attitude::Up || f.att == Attitude::Down) ? 0.0 : margin;
        if (f.lo - m < z && f.hi + m > z) cands.push_back(i);
    }
    const auto ts = std::chrono::steady_clock::now();
    std::vector<SectionLoop> loops = sliceLoops(faces_, cands, frame, z, view_.tol.chord, view_.tol.linear, warnings_);
    if (std::getenv("AERONC_TRACE"))
        std::fprintf(stderr, "  level %.3f: %zu faces cut, %zu loops, %.3f s\n", h, cands.size(), loops.size(),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count());

    std::vector<VoidRegion> regions = voidRegions(loops, view_.blankLo, view_.blankHi, view_.tol.linear);

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
        ElementType type;
        if (!c.floors.empty()) {
            type = c.exterior ? ElementType::OpenPocket : ElementType::ClosedPocket;
        } else if (c.exterior) {
            continue;
        } else if (bottom || leavesPart(c, h, z)) {
            type = ElementType::Opening;
        } else {
            // A drilled hole ends here on a drill point (cone or sphere under its walls).
            bool ends = !c.contourFaces.empty() && c.islandFaces.empty();
            for (int f : c.contourFaces)
                ends = ends && faces_[f].kind == SurfaceKind::Cylinder && faces_[f].concave &&
                       std::fabs(fs[static_cast<std::size_t>(f)].lo - h) <= tol && onDrillPoint(view_, f, h);
            if (!ends) continue;
            type = ElementType::ClosedPocket;
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
        ElementDraft in;
        DomainElement& e = in.el;
        e.id = static_cast<int>(made.size());
        e.setup = setupId;
        e.type = type;
        e.level = h;
        e.area = c.region.area();
        e.minWidth = widths_.minWidth(c.region);
        for (int f : c.contourFaces) e.contourFaces.push_back(f + 1);
        for (auto& isl : c.islandFaces) {
            std::vector<int> v;
            for (int f : isl) v.push_back(f + 1);
            e.islandFaces.push_back(v);
        }
        for (int f : c.floors) {
            e.floorFaces.push_back(f + 1);
            e.floorArea += faces_.area(f);
        }
        double top = -kInf;
        for (int f : c.contourFaces) top = std::max(top, fs[static_cast<std::size_t>(f)].hi);
        if (c.exterior || !std::isfinite(top)) top = std::max(top, h1);
        e.top = top;
        e.depth = top - e.level;
        for (const IntPoint& ip : c.region.outer) e.contour.push_back(frame.world(toP2(ip), h));
        for (const Path& hp : c.region.holes) {
            Polyline pl;
            for (const IntPoint& ip : hp) pl.push_back(frame.world(toP2(ip), h));
            e.islands.push_back(pl);
        }
        for (auto& oe : c.openEdges) e.openEdges.push_back({frame.world(oe.first, h), frame.world(oe.second, h)});
        measureCorners(c, faces_, fs, e);
        for (int rt : c.ribTops) {
            AttachedFeature a;
            a.kind = "island_top";
            a.faces = {rt + 1};
            e.attached.push_back(a);
        }
        in.region = c.region;
        in.sample = c.sample;
        made.push_back(std::move(in));
    }
}

bool LevelSlicing::capped(const VoidRegion& c, double z) const {
    if (!std::isinf(view_.rays().firstHit(view_.frame.world(c.sample, z), true))) return true;
    const double inset = std::max(0.05, 100 * view_.tol.linear);
    for (const P2& p : c.region.boundaryProbes(inset, 24))
        if (!std::isinf(view_.rays().firstHit(view_.frame.world(p, z), true))) return true;
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

}  // namespace aeronc::recognition
