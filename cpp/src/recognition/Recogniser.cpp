// Layered-slicing recognition (integral-panel seed §2.2; patent step 1).
#include <aeronc/core/Error.h>
#include <aeronc/recognition/Recogniser.h>

#include "AxisRays.h"
#include "FaceCatalogue.h"
#include "LevelSlicer.h"
#include "Region.h"

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <Bnd_Box.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <Standard_Failure.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <unordered_map>

namespace aeronc::recognition {
using namespace ClipperLib;

const char* toString(ElementType t) {
    switch (t) {
        case ElementType::ClosedPocket: return "closed_pocket";
        case ElementType::OpenPocket: return "open_pocket";
        case ElementType::Opening: return "opening";
        case ElementType::Hole: return "hole";
    }
    return "?";
}

const char* toString(FaceRole r) {
    switch (r) {
        case FaceRole::Unclaimed: return "unclaimed";
        case FaceRole::Floor: return "floor";
        case FaceRole::Wall: return "wall";
        case FaceRole::IslandWall: return "island_wall";
        case FaceRole::HoleWall: return "hole_wall";
        case FaceRole::FloorFillet: return "floor_fillet";
        case FaceRole::CornerFillet: return "corner_fillet";
        case FaceRole::Chamfer: return "chamfer";
        case FaceRole::OpenBevel: return "open_bevel";
        case FaceRole::ClosedBevel: return "closed_bevel";
        case FaceRole::RibTop: return "rib_top";
        case FaceRole::CounterboreFloor: return "counterbore_floor";
        case FaceRole::Countersink: return "countersink";
        case FaceRole::Top: return "top";
        case FaceRole::Stock: return "stock";
    }
    return "?";
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Attitude { Up, Down, Vertical, Inclined, Curved };

// How one face stands relative to a setup direction.
struct FaceInSetup {
    Attitude att = Attitude::Curved;
    double lo = 0, hi = 0;  // height range
    double base = 0;        // top of its lower boundary (see FaceCatalogue::HeightRange)
    double h = 0;           // planes normal to the axis: their height
};

// A void region at one slicing level, before it becomes an element.
struct Candidate {
    Region region;
    bool exterior = false;
    std::vector<int> contourFaces;
    std::vector<std::vector<int>> islandFaces;
    std::vector<const SectionLoop*> contourLoops;  // loops bounding it (void side known)
    std::vector<bool> contourVoidLeft;
    std::vector<const SectionLoop*> islandLoops;
    std::vector<int> floors;
    std::vector<int> ribTops;
    P2 sample{0, 0};
    bool hasSample = false;
    std::vector<std::pair<P2, P2>> openEdges;
};

struct Internal {
    DomainElement el;
    Region region;
    P2 sample;
};

void pushUnique(std::vector<int>& v, int x) {
    if (x >= 0 && std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
}

std::string dirName(const Vec3& d) {
    const char* axes[3] = {"X", "Y", "Z"};
    for (int k = 0; k < 3; ++k) {
        if (std::fabs(std::fabs(d[k]) - 1) < 1e-9) return std::string(d[k] > 0 ? "+" : "-") + axes[k];
    }
    std::ostringstream s;
    s.precision(4);
    s << "(" << d[0] << ", " << d[1] << ", " << d[2] << ")";
    return s.str();
}

class Recogniser {
public:
    Recogniser(const TopoDS_Shape& solid, const RecogniseOptions& o)
        : solid_(solid), opt_(o), faces_(solid) {
        tree_.faceCount = faces_.size();
        tree_.faceRoles.assign(static_cast<std::size_t>(faces_.size()), FaceRole::Unclaimed);
        tree_.faceElement.assign(static_cast<std::size_t>(faces_.size()), -1);
        claimed_.assign(static_cast<std::size_t>(faces_.size()), false);
        TopExp::MapShapes(solid, TopAbs_EDGE, edges_);
        consumed_.assign(static_cast<std::size_t>(faces_.size()), false);
    }

    DomainTree run() {
        std::vector<Vec3> dirs = opt_.directions;
        if (dirs.empty()) {
            runAuto();
        } else {
            for (std::size_t k = 0; k < dirs.size(); ++k) {
                const double n = norm(dirs[k]);
                if (!(n > 1e-12) || !std::isfinite(n))
                    throw inputError("setup direction " + std::to_string(k + 1) + " is not a valid vector");
                const Vec3 d{dirs[k][0] / n, dirs[k][1] / n, dirs[k][2] / n};
                if (!hasNormalFace(d))
                    throw inputError("the part has no planar face normal to the setup direction " + dirName(d) +
                                     "; pick a direction along a face normal");
                progressBase_ = double(k) / dirs.size();
                progressSpan_ = 1.0 / dirs.size();
                runSetup(d);
            }
        }
        assignRoles();
        return std::move(tree_);
    }

private:
    const TopoDS_Shape& solid_;
    RecogniseOptions opt_;
    FaceCatalogue faces_;
    DomainTree tree_;
    std::vector<bool> claimed_;
    std::vector<bool> consumed_;  // faces whose direction was already tried
    std::vector<Vec3> axes_;      // principal axes, on first use
    TopTools_IndexedMapOfShape edges_;
    std::unique_ptr<AxisRays> rays_;  // along the current setup's axis
    Vec3 currentAxis_{0, 0, 1};
    std::vector<signed char> reach_;  // -1 unknown, 0/1
    std::unordered_map<std::string, double> widths_;  // minimum width by region shape
    double progressBase_ = 0, progressSpan_ = 1;

    // Parallel: |cos| >= cos(tol); square: |cos| <= sin(tol).
    double cosTol() const { return std::cos(opt_.angularTolerance); }
    double sinTol() const { return std::sin(opt_.angularTolerance); }
    double linTol() const { return opt_.linearTolerance; }

    void progress(double f, const std::string& stage) {
        if (opt_.progress && !opt_.progress(progressBase_ + progressSpan_ * f, stage))
            throw inputError("recognition cancelled");
    }

    bool hasNormalFace(const Vec3& d) const {
        for (int i = 0; i < faces_.size(); ++i)
            if (faces_[i].kind == SurfaceKind::Plane && std::fabs(dot(faces_[i].normal, d)) >= cosTol())
                return true;
        return false;
    }

    std::vector<FaceInSetup> classify(const SetupFrame& frame) const {
        const Vec3& w = frame.w;
        const auto ranges = faces_.heightRanges(frame.u, frame.v, w);
        std::vector<FaceInSetup> out(static_cast<std::size_t>(faces_.size()));
        for (int i = 0; i < faces_.size(); ++i) {
            const FaceInfo& f = faces_[i];
            FaceInSetup& s = out[static_cast<std::size_t>(i)];
            s.lo = ranges[static_cast<std::size_t>(i)].lo;
            s.hi = ranges[static_cast<std::size_t>(i)].hi;
            s.base = ranges[static_cast<std::size_t>(i)].base;
            if (f.kind == SurfaceKind::Plane) {
                const double c = dot(f.normal, w);
                if (c >= cosTol()) s.att = Attitude::Up;
                else if (c <= -cosTol()) s.att = Attitude::Down;
                else if (std::fabs(c) <= sinTol()) s.att = Attitude::Vertical;
                else s.att = Attitude::Inclined;
                if (s.att == Attitude::Up || s.att == Attitude::Down) s.h = 0.5 * (s.lo + s.hi);
            } else if ((f.kind == SurfaceKind::Cylinder) && std::fabs(dot(f.axisDir, w)) >= cosTol()) {
                s.att = Attitude::Vertical;
            } else {
                s.att = Attitude::Curved;
            }
        }
        return out;
    }

    // Floor-like area per direction among unclaimed faces: what is still to machine.
    void runAuto() {
        std::vector<Vec3> tried;
        for (int round = 0; round < 12; ++round) {
            std::vector<std::pair<double, Vec3>> cands;
            for (int i = 0; i < faces_.size(); ++i) {
                const FaceInfo& f = faces_[i];
                if (claimed_[static_cast<std::size_t>(i)] || consumed_[static_cast<std::size_t>(i)]) continue;
                if (f.kind == SurfaceKind::Plane) cands.push_back({0.0, f.normal});
                if (f.kind == SurfaceKind::Cylinder && f.concave) {
                    cands.push_back({0.0, f.axisDir});
                    cands.push_back({0.0, {-f.axisDir[0], -f.axisDir[1], -f.axisDir[2]}});
                }
            }
            // Unique directions.
            std::vector<Vec3> dirs;
            for (auto& c : cands) {
                bool seen = false;
                for (const Vec3& d : dirs) seen |= dot(d, c.second) >= cosTol();
                for (const Vec3& d : tried) seen |= dot(d, c.second) >= cosTol();
                if (!seen) dirs.push_back(c.second);
            }
            double bestScore = 0;
            Vec3 best{0, 0, 0};
            const auto ts = std::chrono::steady_clock::now();
            for (const Vec3& d : dirs) {
                const double s = score(d);
                // Ties resolve by the score only up to rounding, then by the first found.
                if (s > bestScore * (1 + 1e-9) + 1e-9) bestScore = s, best = d;
            }
            if (std::getenv("AERONC_TRACE"))
                std::fprintf(stderr, "scored %zu directions: %.3f s\n", dirs.size(),
                             std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count());
            if (bestScore <= 0) break;
            tried.push_back(best);
            // Faces that called for this direction do not call for another one.
            score(best, true);
            progressBase_ = std::min(0.9, 0.45 * round);
            progressSpan_ = round == 0 ? 0.45 : 0.1;
            runSetup(best);
        }
        // The part's principal axes too: through openings have no floor to call for them.
        for (const Vec3& d : principalAxes()) {
            bool seen = false;
            for (const Vec3& t : tried) seen |= dot(d, t) >= cosTol();
            if (seen) continue;
            tried.push_back(d);
            runSetup(d);
        }
        // Setups that found nothing are noise in the tree.
        std::vector<SetupDirection> keep;
        for (SetupDirection& s : tree_.setups)
            if (!s.elements.empty()) {
                for (int e : s.elements) renumberSetup(e, static_cast<int>(keep.size()));
                s.id = static_cast<int>(keep.size());
                keep.push_back(std::move(s));
            }
        tree_.setups = std::move(keep);
        if (tree_.setups.empty()) throw inputError("no machining feature found in any setup direction");
    }

    void renumberSetup(int e, int setup) {
        DomainElement& el = tree_.elements[static_cast<std::size_t>(e)];
        el.setup = setup;
        for (int c : el.children) renumberSetup(c, setup);
    }

    // ± the normal of the largest planar face, of the largest one square to it, and their cross product.
    std::vector<Vec3> principalAxes() const {
        int a = -1, b = -1;
        for (int i = 0; i < faces_.size(); ++i)
            if (faces_[i].kind == SurfaceKind::Plane && (a < 0 || faces_.area(i) > faces_.area(a))) a = i;
        if (a < 0) return {};
        const Vec3 n1 = faces_[a].normal;
        for (int i = 0; i < faces_.size(); ++i)
            if (faces_[i].kind == SurfaceKind::Plane && std::fabs(dot(faces_[i].normal, n1)) <= sinTol() &&
                (b < 0 || faces_.area(i) > faces_.area(b)))
                b = i;
        std::vector<Vec3> out{n1, {-n1[0], -n1[1], -n1[2]}};
        if (b < 0) return out;
        const Vec3 n2 = faces_[b].normal;
        const Vec3 n3{n1[1] * n2[2] - n1[2] * n2[1], n1[2] * n2[0] - n1[0] * n2[2], n1[0] * n2[1] - n1[1] * n2[0]};
        for (const Vec3& n : {n2, n3}) out.push_back(n), out.push_back({-n[0], -n[1], -n[2]});
        return out;
    }

    // Unclaimed floor area seen from d plus unclaimed concave cylinder area along d.
    double score(const Vec3& d, bool consume = false) {
        const SetupFrame frame(d);
        const std::vector<FaceInSetup> fs = classify(frame);
        std::unique_ptr<AxisRays> rays;  // built on the first floor that needs it
        double s = 0;
        for (int i = 0; i < faces_.size(); ++i) {
            if (claimed_[static_cast<std::size_t>(i)] || consumed_[static_cast<std::size_t>(i)]) continue;
            const double before = s;
            const FaceInfo& f = faces_[i];
            const FaceInSetup& fi = fs[static_cast<std::size_t>(i)];
            if (fi.att == Attitude::Up) {
                bool rising = false;
                for (int n : f.neighbours) rising |= fs[static_cast<std::size_t>(n)].hi > fi.h + 10 * linTol();
                if (rising && !rays) rays = std::make_unique<AxisRays>(faces_, frame);
                if (rising && rays->reachable(i)) s += faces_.area(i);
            } else if (f.kind == SurfaceKind::Cylinder && f.concave && fi.att == Attitude::Vertical) {
                s += 0.5 * faces_.area(i);
            }
            if (consume && s > before) consumed_[static_cast<std::size_t>(i)] = true;
        }
        return s;
    }

    // Reachability of faces from the current setup direction, computed once per face.
    bool reachableNow(int i) {
        signed char& r = reach_[static_cast<std::size_t>(i)];
        if (r < 0) r = rays_->reachable(i) ? 1 : 0;
        return r == 1;
    }

    void runSetup(const Vec3& d) {
        currentAxis_ = d;
        reach_.assign(static_cast<std::size_t>(faces_.size()), -1);
        // Align the frame with a principal axis square to d, so the blank box fits the part.
        const Vec3* ref = nullptr;
        if (axes_.empty()) axes_ = principalAxes();
        for (const Vec3& a : axes_)
            if (std::fabs(dot(a, d)) <= sinTol()) {
                ref = &a;
                break;
            }
        SetupFrame frame(d, ref);
        rays_ = std::make_unique<AxisRays>(faces_, frame);
        const std::vector<FaceInSetup> fs = classify(frame);

        // Part extent in the setup frame.
        gp_Trsf t;
        t.SetValues(frame.u[0], frame.u[1], frame.u[2], 0, frame.v[0], frame.v[1], frame.v[2], 0, frame.w[0],
                    frame.w[1], frame.w[2], 0);
        // The part's extremes in a prismatic part lie on its edges, whose boxes are exact
        // for lines and arcs (a face box can be loose, and the optimal one is slow).
        Bnd_Box box;
        const TopLoc_Location frameLoc(t);
        for (int e = 1; e <= edges_.Extent(); ++e) BRepBndLib::Add(edges_(e).Moved(frameLoc), box, false);
        double x0, y0, h0, x1, y1, h1;
        box.Get(x0, y0, h0, x1, y1, h1);
        const double gap = box.GetGap();
        x0 += gap, y0 += gap, h0 += gap, x1 -= gap, y1 -= gap, h1 -= gap;
        P2 blo{x0 - opt_.blankAllowance, y0 - opt_.blankAllowance};
        P2 bhi{x1 + opt_.blankAllowance, y1 + opt_.blankAllowance};
        if (opt_.blank) {
            blo = {kInf, kInf}, bhi = {-kInf, -kInf};
            for (int c = 0; c < 8; ++c) {
                const Vec3 p{(c & 1) ? opt_.blank->max[0] : opt_.blank->min[0],
                             (c & 2) ? opt_.blank->max[1] : opt_.blank->min[1],
                             (c & 4) ? opt_.blank->max[2] : opt_.blank->min[2]};
                const P2 q = frame.project(p);
                blo.x = std::min(blo.x, q.x), blo.y = std::min(blo.y, q.y);
                bhi.x = std::max(bhi.x, q.x), bhi.y = std::max(bhi.y, q.y);
            }
        }

        SetupDirection setup;
        setup.id = static_cast<int>(tree_.setups.size());
        setup.direction = frame.w;
        setup.name = dirName(frame.w);

        // Slicing levels: floors, hole bottoms, and the faces openings leave the part by.
        std::vector<double> levels{h0};
        for (int i = 0; i < faces_.size(); ++i) {
            const FaceInSetup& s = fs[static_cast<std::size_t>(i)];
            const bool holeWall = s.att == Attitude::Vertical && faces_[i].kind == SurfaceKind::Cylinder && faces_[i].concave;
            if (s.att == Attitude::Up && reachableNow(i)) levels.push_back(s.h);
            else if (s.att == Attitude::Down) levels.push_back(s.h);  // openings leave here
            else if (holeWall && onDrillPoint(i, s.lo, fs)) levels.push_back(s.lo);
            else if (holeWall && s.base > s.lo + 10 * linTol()) levels.push_back(s.base);  // breaks into a bore
        }
        std::sort(levels.begin(), levels.end());
        std::vector<double> uniq;
        for (double l : levels)
            if (l < h1 - 10 * linTol() && (uniq.empty() || l - uniq.back() > 10 * linTol())) uniq.push_back(l);

        std::vector<double> critical;  // heights where faces start or end
        for (const FaceInSetup& f : fs) critical.push_back(f.lo), critical.push_back(f.hi);
        std::sort(critical.begin(), critical.end());
        std::vector<Internal> made;
        const auto t0 = std::chrono::steady_clock::now();
        for (std::size_t li = 0; li < uniq.size(); ++li) {
            progress(double(li) / uniq.size(), "slicing " + setup.name);
            const double h = uniq[li];
            const double hn = li + 1 < uniq.size() ? uniq[li + 1] : h1;
            sliceLevel(frame, fs, critical, h, hn, h1, blo, bhi, li == 0, setup.id, made);
        }
        if (std::getenv("AERONC_TRACE"))
            std::fprintf(stderr, "setup %s: %zu levels, %zu elements, %.3f s\n", setup.name.c_str(), uniq.size(),
                         made.size(), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
        progress(1.0, "linking " + setup.name);
        link(made);
        finish(made, frame, fs);

        // Claim: an element whose floors (or, without floor, all walls) belong to an
        // earlier setup is that setup's already.
        std::vector<int> remap(made.size(), -1);
        std::vector<Internal> kept;
        for (std::size_t k = 0; k < made.size(); ++k) {
            const DomainElement& e = made[k].el;
            bool taken = false;
            if (!e.floorFaces.empty()) {
                for (int f : e.floorFaces) taken |= claimed_[static_cast<std::size_t>(f - 1)];
            } else {
                taken = !e.contourFaces.empty();
                for (int f : e.contourFaces) taken &= claimed_[static_cast<std::size_t>(f - 1)];
            }
            if (!taken) {
                remap[k] = static_cast<int>(tree_.elements.size() + kept.size());
                kept.push_back(made[k]);
                // Faces an earlier setup machines stay with it: one owner per face.
                DomainElement& el = kept.back().el;
                auto mine = [&](std::vector<int>& v) {
                    v.erase(std::remove_if(v.begin(), v.end(),
                                           [&](int f) { return claimed_[static_cast<std::size_t>(f - 1)]; }),
                            v.end());
                };
                mine(el.contourFaces), mine(el.filletFaces), mine(el.chamferFaces), mine(el.topFaces);
                for (auto& isl : el.islandFaces) mine(isl);
                for (auto& a : el.attached) mine(a.faces);
            }
        }
        for (Internal& in : kept) {
            DomainElement& e = in.el;
            // Parent dropped: attach to the nearest kept ancestor.
            int p = e.parent;
            while (p >= 0 && remap[static_cast<std::size_t>(p)] < 0) p = made[static_cast<std::size_t>(p)].el.parent;
            e.parent = p >= 0 ? remap[static_cast<std::size_t>(p)] : -1;
        }
        const int base = static_cast<int>(tree_.elements.size());
        for (std::size_t k = 0; k < kept.size(); ++k) {
            DomainElement& e = kept[k].el;
            e.id = base + static_cast<int>(k);
            e.children.clear();
            for (auto& a : e.attached)
                if (a.element >= 0) a.element = remap[static_cast<std::size_t>(a.element)];
        }
        for (std::size_t k = 0; k < kept.size(); ++k) {
            DomainElement& e = kept[k].el;
            if (e.parent >= 0) kept[static_cast<std::size_t>(e.parent - base)].el.children.push_back(e.id);
            else setup.elements.push_back(e.id);
            auto claim = [&](const std::vector<int>& v) {
                for (int f : v) claimed_[static_cast<std::size_t>(f - 1)] = true;
            };
            claim(e.floorFaces), claim(e.contourFaces), claim(e.filletFaces), claim(e.chamferFaces);
            for (auto& isl : e.islandFaces) claim(isl);
            for (auto& a : e.attached) claim(a.faces);
        }
        for (auto& in : kept) tree_.elements.push_back(std::move(in.el));
        tree_.setups.push_back(std::move(setup));
    }

    void sliceLevel(const SetupFrame& frame, const std::vector<FaceInSetup>& fs, const std::vector<double>& critical,
                    double h, double hn, double h1, const P2& blo, const P2& bhi, bool bottom, int setupId,
                    std::vector<Internal>& made) {
        const double tol = 10 * linTol();
        // Slice above floor fillets and bottom chamfers so the loops run on the walls.
        std::vector<int> ups;
        double excess = 0;
        for (int i = 0; i < faces_.size(); ++i) {
            const FaceInSetup& s = fs[static_cast<std::size_t>(i)];
            if (s.att != Attitude::Up || std::fabs(s.h - h) > tol || !reachableNow(i)) continue;
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
        for (double c : critical) {
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
        std::vector<SectionLoop> loops =
            sliceLoops(faces_, cands, frame, z, opt_.chordTolerance, linTol(), tree_.warnings);
        if (std::getenv("AERONC_TRACE"))
            std::fprintf(stderr, "  level %.3f: %zu faces cut, %zu loops, %.3f s\n", h, cands.size(), loops.size(),
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - ts).count());

        // Closed void regions: odd-depth loops with their even-depth children as islands.
        std::vector<Candidate> regions;
        std::vector<int> regionOfLoop(loops.size(), -1);
        for (std::size_t k = 0; k < loops.size(); ++k) {
            if (loops[k].depth % 2 == 0) continue;
            Candidate c;
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
            Candidate& c = regions[static_cast<std::size_t>(regionOfLoop[static_cast<std::size_t>(L.parent)])];
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
            const double delta = std::max(5 * linTol(), 2e-3) * kClipperScale;
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
                Candidate c;
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
            const double off = std::max(20 * linTol(), 0.02);
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
                    Candidate& c = regions[*touched.begin()];
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
            Candidate& c = regions[static_cast<std::size_t>(r)];
            if (rising) {
                c.floors.push_back(i);
                if (!c.hasSample) c.sample = p, c.hasSample = true;
            } else {
                c.ribTops.push_back(i);
            }
        }

        for (std::size_t r = 0; r < regions.size(); ++r) {
            Candidate& c = regions[r];
            ElementType type;
            if (!c.floors.empty()) {
                type = c.exterior ? ElementType::OpenPocket : ElementType::ClosedPocket;
            } else if (c.exterior) {
                continue;
            } else if (bottom || leavesPart(c, fs, frame, h, z)) {
                type = ElementType::Opening;
            } else {
                // A drilled hole ends here on a drill point (cone or sphere under its walls).
                bool ends = !c.contourFaces.empty() && c.islandFaces.empty();
                for (int f : c.contourFaces)
                    ends = ends && faces_[f].kind == SurfaceKind::Cylinder && faces_[f].concave &&
                           std::fabs(fs[static_cast<std::size_t>(f)].lo - h) <= tol && onDrillPoint(f, h, fs);
                if (!ends) continue;
                type = ElementType::ClosedPocket;
            }
            if (!c.hasSample) c.sample = c.region.interiorPoint();
            if (type == ElementType::Opening) {
                // Bounded only by cones or chamfers: the mouth of a hole, not an opening.
                bool wall = false;
                for (int f : c.contourFaces) wall |= fs[static_cast<std::size_t>(f)].att == Attitude::Vertical;
                if (!wall) continue;
                // Capped from above (a cavity seen from the wrong side): not machinable here.
                if (!std::isinf(rays_->firstHit(frame.world(c.sample, z), true))) continue;
            }
            Internal in;
            DomainElement& e = in.el;
            e.id = static_cast<int>(made.size());
            e.setup = setupId;
            e.type = type;
            e.level = h;
            e.area = c.region.area();
            e.minWidth = minWidth(c.region);
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
            cornerRadius(c, fs, e);
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

    // An opening: the region's walls all end at this level and below it lies no material.
    bool leavesPart(Candidate& c, const std::vector<FaceInSetup>& fs, const SetupFrame& frame, double h, double z) {
        if (c.contourFaces.empty()) return false;
        for (int f : c.contourFaces)
            if (std::fabs(fs[static_cast<std::size_t>(f)].base - h) > 10 * linTol()) return false;
        if (!c.hasSample) c.sample = c.region.interiorPoint(), c.hasSample = true;
        // Looking down from the slice: material right under the level means a floor, not an exit.
        const Vec3 q = frame.world(c.sample, z);
        const double margin = std::max(0.1, 100 * linTol());
        return rays_->firstHit(q, false) > z - h + margin;
    }

    // Whether face f's bottom at height h rests on a drill point (cone or sphere below it).
    // A cone that narrows downwards is a drill point; one that widens is a countersink at
    // the far end of a through hole.
    bool onDrillPoint(int f, double h, const std::vector<FaceInSetup>& fs) const {
        for (int n : faces_[f].neighbours) {
            const FaceInfo& c = faces_[n];
            const FaceInSetup& cs = fs[static_cast<std::size_t>(n)];
            if (cs.hi > h + 10 * linTol()) continue;
            if (c.kind == SurfaceKind::Sphere) return true;
            if (c.kind == SurfaceKind::Cone && coneRadiusAt(c, cs.lo) < faces_[f].radius - 10 * linTol()) return true;
        }
        return false;
    }

    double coneRadiusAt(const FaceInfo& c, double height) const {
        const Vec3& w = currentAxis_;
        const double sgn = dot(c.axisDir, w) > 0 ? 1 : -1;
        return std::fabs(c.radius + std::tan(c.semiAngle) * sgn * (height - dot(c.axisPoint, w)));
    }

    // Regions of the same shape (repeated pockets) share one width computation.
    double minWidth(const Region& r) {
        std::string key;
        auto add = [&](const Path& p) {
            for (const IntPoint& q : p) {
                const cInt d[2] = {q.X - p[0].X, q.Y - p[0].Y};
                key.append(reinterpret_cast<const char*>(d), sizeof d);
            }
            const cInt o[2] = {p[0].X - r.outer[0].X, p[0].Y - r.outer[0].Y};
            key.append(reinterpret_cast<const char*>(o), sizeof o);
            key.push_back('|');
        };
        add(r.outer);
        for (const Path& h : r.holes) add(h);
        auto it = widths_.find(key);
        if (it != widths_.end()) return it->second;
        const double w = r.minWidth();
        widths_.emplace(std::move(key), w);
        return w;
    }

    // Smallest concave corner radius along the loops; 0 where two walls meet sharp.
    void cornerRadius(const Candidate& c, const std::vector<FaceInSetup>& fs, DomainElement& e) const {
        double r = kInf;
        std::map<double, std::vector<int>> corners;
        auto visit = [&](const SectionLoop& L, bool voidLeft) {
            const std::size_t n = L.pts.size();
            for (std::size_t i = 0; i < n; ++i) {
                const int f = L.faces[i];
                if (f < 0) continue;
                const FaceInfo& fi = faces_[f];
                if (fi.kind == SurfaceKind::Cylinder && fs[static_cast<std::size_t>(f)].att == Attitude::Vertical &&
                    fi.concave) {
                    r = std::min(r, fi.radius);
                    auto& v = corners[std::round(fi.radius * 1e6) / 1e6];
                    if (std::find(v.begin(), v.end(), f + 1) == v.end()) v.push_back(f + 1);
                }
                const int g = L.faces[(i + 1) % n];
                if (g == f || g < 0 || fi.kind != SurfaceKind::Plane || faces_[g].kind != SurfaceKind::Plane) continue;
                const P2& a = L.pts[i];
                const P2& b = L.pts[(i + 1) % n];
                const P2& q = L.pts[(i + 2) % n];
                const double ux = b.x - a.x, uy = b.y - a.y, vx = q.x - b.x, vy = q.y - b.y;
                const double cr = ux * vy - uy * vx;
                const double sn = cr / (std::hypot(ux, uy) * std::hypot(vx, vy) + 1e-300);
                // A turn towards the void side is a corner the tool cannot reach.
                if ((voidLeft ? sn : -sn) > std::sin(0.05)) r = 0;
            }
        };
        for (std::size_t k = 0; k < c.contourLoops.size(); ++k) visit(*c.contourLoops[k], c.contourVoidLeft[k]);
        for (const SectionLoop* L : c.islandLoops) visit(*L, false);
        e.minCornerRadius = std::isfinite(r) ? r : -1;
        for (auto& kv : corners) {
            AttachedFeature a;
            a.kind = "corner_fillet";
            a.radius = kv.first;
            a.faces = kv.second;
            e.attached.push_back(a);
        }
    }

    // Parent: the element at the nearest higher level whose region holds the sample.
    void link(std::vector<Internal>& made) {
        std::vector<std::size_t> byLevel(made.size());
        for (std::size_t k = 0; k < made.size(); ++k) byLevel[k] = k;
        std::stable_sort(byLevel.begin(), byLevel.end(),
                         [&](std::size_t a, std::size_t b) { return made[a].el.level < made[b].el.level; });
        for (std::size_t k = 0; k < made.size(); ++k) {
            Internal& in = made[k];
            int best = -1;
            double bestLevel = kInf;
            for (std::size_t j = 0; j < made.size(); ++j) {
                const Internal& o = made[j];
                if (o.el.level <= in.el.level + 10 * linTol() || o.el.level >= bestLevel) continue;
                if (o.region.contains(in.sample)) best = static_cast<int>(j), bestLevel = o.el.level;
            }
            in.el.parent = best;
        }
        for (Internal& in : made)
            if (in.el.parent >= 0) made[static_cast<std::size_t>(in.el.parent)].el.children.push_back(in.el.id);
    }

    // Attached features, holes, counterbores and countersinks, joggles.
    void finish(std::vector<Internal>& made, const SetupFrame& frame, const std::vector<FaceInSetup>& fs) {
        const double tol = 10 * linTol();
        for (Internal& in : made) {
            DomainElement& e = in.el;
            std::set<int> inLoops(e.contourFaces.begin(), e.contourFaces.end());
            for (auto& isl : e.islandFaces) inLoops.insert(isl.begin(), isl.end());
            // Floor fillets: curved faces between the floor and the walls.
            double ff = kInf;
            std::vector<int> fillets;
            for (int f : e.floorFaces)
                for (int n : faces_[f - 1].neighbours) {
                    const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                    const SurfaceKind k = faces_[n].kind;
                    if (s.att != Attitude::Curved || k == SurfaceKind::Cone) continue;
                    if (std::find(fillets.begin(), fillets.end(), n + 1) != fillets.end()) continue;
                    fillets.push_back(n + 1);
                    if (k == SurfaceKind::Cylinder || k == SurfaceKind::Torus || k == SurfaceKind::Sphere)
                        ff = std::min(ff, faces_[n].radius);
                }
            // Fillet corners (tori, spheres) touching the fillets found.
            for (std::size_t q = 0; q < fillets.size(); ++q)
                for (int n : faces_[fillets[q] - 1].neighbours) {
                    const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                    if (s.att == Attitude::Curved && faces_[n].kind != SurfaceKind::Cone &&
                        std::fabs(s.lo - e.level) <= tol && !inLoops.count(n + 1) &&
                        std::find(fillets.begin(), fillets.end(), n + 1) == fillets.end())
                        fillets.push_back(n + 1);
                }
            e.filletFaces = fillets;
            e.floorFilletRadius = std::isfinite(ff) ? ff : 0;
            if (!fillets.empty()) {
                AttachedFeature a;
                a.kind = "floor_fillet";
                a.faces = fillets;
                a.radius = e.floorFilletRadius;
                e.attached.push_back(a);
            }
            // Chamfers and bevels on the side walls.
            std::set<int> seen;
            for (int w : inLoops) {
                const FaceInSetup& ws = fs[static_cast<std::size_t>(w - 1)];
                if (ws.att == Attitude::Inclined) {
                    AttachedFeature a;
                    const double c = dot(faces_[w - 1].normal, frame.w);
                    a.kind = c > 0 ? "open_corner" : "closed_corner";
                    a.faces = {w};
                    a.size = std::asin(std::min(1.0, std::fabs(c))) * 180 / M_PI;
                    e.attached.push_back(a);
                }
                for (int n : faces_[w - 1].neighbours) {
                    if (inLoops.count(n + 1) || seen.count(n)) continue;
                    const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                    if (s.att == Attitude::Inclined) {
                        seen.insert(n);
                        e.chamferFaces.push_back(n + 1);
                    }
                }
            }
            if (!e.chamferFaces.empty()) {
                AttachedFeature a;
                a.kind = "chamfer";
                a.faces = e.chamferFaces;
                e.attached.push_back(a);
            }
            // Island tops: faces normal to the axis on top of the island walls.
            for (auto& isl : e.islandFaces) {
                double islTop = -kInf;
                for (int f : isl) islTop = std::max(islTop, fs[static_cast<std::size_t>(f - 1)].hi);
                AttachedFeature a;
                a.kind = "island_top";
                for (int f : isl)
                    for (int n : faces_[f - 1].neighbours) {
                        const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                        if (s.att == Attitude::Up && std::fabs(s.h - islTop) <= tol && islTop < e.top - tol)
                            pushUnique(a.faces, n + 1);
                    }
                if (!a.faces.empty()) e.attached.push_back(a);
            }
            // Top constraint: faces normal to the axis at the top of the walls.
            for (int w : e.contourFaces)
                for (int n : faces_[w - 1].neighbours) {
                    const FaceInSetup& s = fs[static_cast<std::size_t>(n)];
                    if (s.att == Attitude::Up && std::fabs(s.h - e.top) <= tol) pushUnique(e.topFaces, n + 1);
                }
            // Hole: one circular contour of concave vertical cylinders, no islands.
            holeCheck(in, frame, fs);
        }
        for (Internal& in : made) {
            DomainElement& e = in.el;
            if (!e.hole || e.parent < 0) continue;
            DomainElement& p = made[static_cast<std::size_t>(e.parent)].el;
            if (!p.hole || p.hole->diameter <= e.hole->diameter) continue;
            const Vec3 dl{p.hole->location[0] - e.hole->location[0], p.hole->location[1] - e.hole->location[1],
                          p.hole->location[2] - e.hole->location[2]};
            const double along = dot(dl, frame.w);
            const Vec3 perp{dl[0] - along * frame.w[0], dl[1] - along * frame.w[1], dl[2] - along * frame.w[2]};
            if (norm(perp) > tol) continue;
            e.hole->counterboreDiameter = p.hole->diameter;
            e.hole->counterboreDepth = p.depth;
        }
        // Joggle: a shallow child pocket that shares a side wall with its parent.
        for (Internal& in : made) {
            DomainElement& e = in.el;
            if (e.parent < 0 || e.hole || e.type == ElementType::Opening) continue;
            DomainElement& p = made[static_cast<std::size_t>(e.parent)].el;
            const double step = p.level - e.level;
            bool shares = false;
            for (int f : e.contourFaces)
                shares |= std::find(p.contourFaces.begin(), p.contourFaces.end(), f) != p.contourFaces.end();
            if (shares && step < 0.5 * p.depth) {
                AttachedFeature a;
                a.kind = "joggle";
                a.element = e.id;
                a.size = step;
                a.faces = e.floorFaces;
                p.attached.push_back(a);
            }
        }
        // Rib: the floor of a region joining several pockets is the top of the rib between them.
        for (Internal& in : made) {
            DomainElement& e = in.el;
            if (e.children.size() >= 2 && e.floorArea < 0.5 * e.area && !e.floorFaces.empty()) {
                AttachedFeature a;
                a.kind = "rib";
                a.faces = e.floorFaces;
                e.attached.push_back(a);
            }
            if (e.type == ElementType::OpenPocket && !e.openEdges.empty() && e.minWidth > 0 &&
                e.area > 4 * e.minWidth * e.minWidth) {
                AttachedFeature a;
                a.kind = "flange";
                a.faces = e.floorFaces;
                a.size = e.minWidth;
                e.attached.push_back(a);
            }
        }
    }

    void holeCheck(Internal& in, const SetupFrame& frame, const std::vector<FaceInSetup>& fs) {
        DomainElement& e = in.el;
        if (!e.islandFaces.empty() || e.contourFaces.empty() || e.type == ElementType::OpenPocket) return;
        const FaceInfo& f0 = faces_[e.contourFaces[0] - 1];
        const double tol = 10 * linTol();
        for (int f : e.contourFaces) {
            const FaceInfo& fi = faces_[f - 1];
            if (fi.kind != SurfaceKind::Cylinder || !fi.concave || fs[static_cast<std::size_t>(f - 1)].att != Attitude::Vertical)
                return;
            if (std::fabs(fi.radius - f0.radius) > tol) return;
            const Vec3 dp{fi.axisPoint[0] - f0.axisPoint[0], fi.axisPoint[1] - f0.axisPoint[1],
                          fi.axisPoint[2] - f0.axisPoint[2]};
            const double along = dot(dp, frame.w);
            const Vec3 perp{dp[0] - along * frame.w[0], dp[1] - along * frame.w[1], dp[2] - along * frame.w[2]};
            if (norm(perp) > tol) return;
        }
        HoleInfo hi;
        hi.diameter = 2 * f0.radius;
        hi.through = e.type == ElementType::Opening;
        hi.axis = frame.w;
        const P2 c = frame.project(f0.axisPoint);
        hi.location = frame.world(c, e.top);
        hi.depth = e.depth;
        // Countersink: a concave cone on the axis above the wall; drill point: below it.
        for (int f : e.contourFaces)
            for (int n : faces_[f - 1].neighbours) {
                const FaceInfo& cf = faces_[n];
                const FaceInSetup& cs = fs[static_cast<std::size_t>(n)];
                if (cf.kind != SurfaceKind::Cone || std::fabs(dot(cf.axisDir, frame.w)) < cosTol()) continue;
                if (cs.lo >= e.top - tol) {
                    const double sgn = dot(cf.axisDir, frame.w) > 0 ? 1 : -1;
                    const double href = dot(cf.axisPoint, frame.w);
                    const double rTop = cf.radius + std::tan(cf.semiAngle) * sgn * (cs.hi - href);
                    hi.countersinkDiameter = 2 * std::fabs(rTop);
                    hi.countersinkAngle = 2 * cf.semiAngle * 180 / M_PI;
                    pushUnique(e.chamferFaces, n + 1);
                    AttachedFeature a;
                    a.kind = "countersink";
                    a.faces = {n + 1};
                    a.size = hi.countersinkDiameter;
                    e.attached.push_back(a);
                } else if (cs.hi <= e.level + tol && coneRadiusAt(cf, cs.lo) < f0.radius - tol) {
                    pushUnique(e.floorFaces, n + 1);  // drill point is the hole's bottom
                }
            }
        e.type = ElementType::Hole;
        e.hole = hi;
    }

    void assignRoles() {
        auto set = [&](int f, FaceRole r, int el) {
            const std::size_t i = static_cast<std::size_t>(f - 1);
            if (tree_.faceRoles[i] != FaceRole::Unclaimed) return;
            tree_.faceRoles[i] = r;
            tree_.faceElement[i] = el;
        };
        // By priority over all elements: a face that is some element's floor is a floor,
        // whatever else touches it; then walls; then blends and chamfers; then tops.
        auto attachedRole = [](const AttachedFeature& a, const DomainElement& e) {
            if (a.kind == "corner_fillet") return e.hole ? FaceRole::HoleWall : FaceRole::CornerFillet;
            if (a.kind == "floor_fillet") return FaceRole::FloorFillet;
            if (a.kind == "open_corner") return FaceRole::OpenBevel;
            if (a.kind == "closed_corner") return FaceRole::ClosedBevel;
            if (a.kind == "countersink") return FaceRole::Countersink;
            if ((a.kind == "rib" && e.children.size() < 2) || a.kind == "island_top") return FaceRole::RibTop;
            return FaceRole::Unclaimed;
        };
        for (int pass = 0; pass < 4; ++pass)
            for (const DomainElement& e : tree_.elements) {
                const bool isHole = e.hole.has_value();
                if (pass == 0) {
                    bool counterbore = false;
                    for (int c : e.children) counterbore |= isHole && tree_.elements[static_cast<std::size_t>(c)].hole.has_value();
                    for (int f : e.floorFaces) set(f, counterbore ? FaceRole::CounterboreFloor : FaceRole::Floor, e.id);
                } else if (pass == 1) {
                    for (const AttachedFeature& a : e.attached)  // walls of a particular kind first
                        if (a.kind == "corner_fillet" || a.kind == "open_corner" || a.kind == "closed_corner")
                            for (int f : a.faces) set(f, attachedRole(a, e), e.id);
                    for (int f : e.contourFaces) set(f, isHole ? FaceRole::HoleWall : FaceRole::Wall, e.id);
                    for (auto& isl : e.islandFaces)
                        for (int f : isl) set(f, FaceRole::IslandWall, e.id);
                } else if (pass == 2) {
                    for (const AttachedFeature& a : e.attached) {
                        const FaceRole r = attachedRole(a, e);
                        if (r != FaceRole::RibTop && r != FaceRole::Unclaimed)
                            for (int f : a.faces) set(f, r, e.id);
                    }
                    for (int f : e.chamferFaces) set(f, FaceRole::Chamfer, e.id);
                } else {
                    for (const AttachedFeature& a : e.attached)
                        if (attachedRole(a, e) == FaceRole::RibTop)
                            for (int f : a.faces) set(f, FaceRole::RibTop, e.id);
                }
            }
        // What no element machines: the top of the part in the first setup, else stock.
        if (!tree_.setups.empty()) {
            const SetupFrame frame(tree_.setups[0].direction);
            const std::vector<FaceInSetup> fs = classify(frame);
            double hi = -kInf;
            for (const FaceInSetup& f : fs) hi = std::max(hi, f.hi);
            for (int i = 0; i < faces_.size(); ++i) {
                if (tree_.faceRoles[static_cast<std::size_t>(i)] != FaceRole::Unclaimed) continue;
                const FaceInSetup& f = fs[static_cast<std::size_t>(i)];
                const bool top = f.att == Attitude::Up && std::fabs(f.hi - hi) <= 10 * linTol();
                tree_.faceRoles[static_cast<std::size_t>(i)] = top ? FaceRole::Top : FaceRole::Stock;
            }
        }
    }
};

}  // namespace

DomainTree recognise(const TopoDS_Shape& solid, const RecogniseOptions& options) {
    if (options.linearTolerance <= 0 || options.angularTolerance <= 0 || options.chordTolerance <= 0)
        throw inputError("tolerances must be positive");
    if (options.blankAllowance < 0) throw inputError("the blank allowance must not be negative");
    try {
        Recogniser r(solid, options);
        return r.run();
    } catch (const Error&) {
        throw;
    } catch (const Standard_Failure& f) {
        throw geometryError(std::string("OpenCASCADE failed during recognition: ") + f.GetMessageString());
    }
}

}  // namespace aeronc::recognition
