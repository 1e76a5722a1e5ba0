#include "VoidRegions.h"

#include "FaceLists.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace aeronc::recognition {
using namespace ClipperLib;

std::vector<VoidRegion> voidRegions(const std::vector<SectionLoop>& loops, const P2& blo, const P2& bhi,
                                    double linTol) {
    // Closed void regions: odd-depth loops with their even-depth children as islands.
    std::vector<VoidRegion> regions;
    std::vector<int> regionOfLoop(loops.size(), -1);
    for (std::size_t k = 0; k < loops.size(); ++k) {
        if (loops[k].depth % 2 == 0) continue;
        VoidRegion c;
        for (const P2& p : loops[k].pts) c.region.outer.push_back(toInt(p));
        c.contourLoops.push_back(&loops[k]);
        c.contourVoidLeft.push_back(true);
        for (int f : loops[k].faces) pushUnique(c.contourFaces, f);
        regionOfLoop[k] = static_cast<int>(regions.size());
        regions.push_back(std::move(c));
    }
    for (std::size_t k = 0; k < loops.size(); ++k) {
        const SectionLoop& L = loops[k];
        if (L.depth % 2 != 0 || L.parent < 0) continue;
        VoidRegion& c = regions[static_cast<std::size_t>(regionOfLoop[static_cast<std::size_t>(L.parent)])];
        Path hole;
        for (auto it = L.pts.rbegin(); it != L.pts.rend(); ++it) hole.push_back(toInt(*it));
        c.region.holes.push_back(hole);
        c.islandLoops.push_back(&L);
        std::vector<int> fl;
        for (int f : L.faces) pushUnique(fl, f);
        c.islandFaces.push_back(fl);
    }
    const std::size_t closedCount = regions.size();

    // Exterior: the blank minus the material, opened to drop slivers along the blank.
    {
        Clipper clip;
        Path rect{toInt(blo), toInt({bhi.x, blo.y}), toInt(bhi), toInt({blo.x, bhi.y})};
        clip.AddPath(rect, ptSubject, true);
        for (const SectionLoop& L : loops) {
            if (L.depth != 0) continue;
            Path p;
            for (const P2& q : L.pts) p.push_back(toInt(q));
            clip.AddPath(p, ptClip, true);
        }
        Paths diff;
        clip.Execute(ctDifference, diff, pftNonZero, pftNonZero);
        const double delta = std::max(5 * linTol, 2e-3) * kClipperScale;
        ClipperOffset in(2.0), out(2.0);
        in.AddPaths(diff, jtMiter, etClosedPolygon);
        Paths eroded;
        in.Execute(eroded, -delta);
        out.AddPaths(eroded, jtMiter, etClosedPolygon);
        PolyTree opened;
        out.Execute(opened, delta);
        Clipper trim;  // dilation must not leave the blank
        Paths openedPaths;
        PolyTreeToPaths(opened, openedPaths);
        trim.AddPaths(openedPaths, ptSubject, true);
        trim.AddPath(rect, ptClip, true);
        PolyTree comps;
        trim.Execute(ctIntersection, comps, pftNonZero, pftNonZero);
        for (PolyNode* n = comps.GetFirst(); n; n = n->GetNext()) {
            if (n->IsHole()) continue;
            VoidRegion c;
            c.exterior = true;
            c.region.outer = n->Contour;
            for (PolyNode* ch : n->Childs) c.region.holes.push_back(ch->Contour);
            c.region.updateBox();
            if (c.region.area() < 1e-6 * (bhi.x - blo.x) * (bhi.y - blo.y)) continue;
            // Open edges: boundary pieces on the blank rectangle.
            const double bt = 2 * delta / kClipperScale + 1e-6;
            const Path& o = c.region.outer;
            for (std::size_t i = 0; i < o.size(); ++i) {
                const P2 a = toP2(o[i]), b = toP2(o[(i + 1) % o.size()]);
                auto on = [&](double x, double lim) { return std::fabs(x - lim) <= bt; };
                if ((on(a.x, blo.x) && on(b.x, blo.x)) || (on(a.x, bhi.x) && on(b.x, bhi.x)) ||
                    (on(a.y, blo.y) && on(b.y, blo.y)) || (on(a.y, bhi.y) && on(b.y, bhi.y)))
                    c.openEdges.push_back({a, b});
            }
            regions.push_back(std::move(c));
        }
    }
    for (std::size_t r = 0; r < closedCount; ++r) regions[r].region.updateBox();

    // Faces bounding the exterior components: probe the void side of material outers.
    if (regions.size() > closedCount) {
        const double off = std::max(20 * linTol, 0.02);
        for (const SectionLoop& L : loops) {
            if (L.depth != 0) continue;
            std::set<std::size_t> touched;
            std::vector<std::pair<std::size_t, int>> hits;
            // One probe per run of segments on the same face, at the run's longest segment.
            const std::size_t n = L.pts.size();
            std::size_t runs = 0;
            for (std::size_t i = 0; i < n;) {
                std::size_t j = i, best = i;
                double bestLen = -1;
                for (; j < n && L.faces[j] == L.faces[i]; ++j) {
                    const P2& a = L.pts[j];
                    const P2& b = L.pts[(j + 1) % n];
                    const double len = std::hypot(b.x - a.x, b.y - a.y);
                    if (len > bestLen) bestLen = len, best = j;
                }
                ++runs;
                const P2& a = L.pts[best];
                const P2& b = L.pts[(best + 1) % n];
                const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
                i = j;
                if (len <= 0) continue;
                const P2 probe{0.5 * (a.x + b.x) + dy / len * off, 0.5 * (a.y + b.y) - dx / len * off};
                for (std::size_t r = closedCount; r < regions.size(); ++r)
                    if (regions[r].region.contains(probe)) {
                        touched.insert(r);
                        hits.push_back({r, L.faces[best]});
                        break;
                    }
            }
            bool touchesBlank = L.lo.x <= blo.x + 1e-6 || L.lo.y <= blo.y + 1e-6 || L.hi.x >= bhi.x - 1e-6 ||
                                L.hi.y >= bhi.y - 1e-6;
            if (touched.size() == 1 && !touchesBlank && hits.size() == runs) {
                // A material loop inside one exterior region only: an island of it.
                VoidRegion& c = regions[*touched.begin()];
                std::vector<int> fl;
                for (int f : L.faces) pushUnique(fl, f);
                c.islandFaces.push_back(fl);
                c.islandLoops.push_back(&L);
            } else {
                for (auto& hf : hits) pushUnique(regions[hf.first].contourFaces, hf.second);
                for (std::size_t r : touched) {
                    regions[r].contourLoops.push_back(&L);
                    regions[r].contourVoidLeft.push_back(false);
                }
            }
        }
    }
    return regions;
}

}  // namespace aeronc::recognition
