#include "LevelSlicer.h"
#include "VerticalSection.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRep_Builder.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cstdlib>
#include <cmath>
#include <mutex>
#include <unordered_map>

namespace aeronc::recognition {
namespace {

struct Piece {
    std::vector<P2> pts;
    int face = -1;
    bool used = false;
};

double dist2(const P2& a, const P2& b) { return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y); }

class EndpointGrid {
public:
    explicit EndpointGrid(double cell) : cell_(cell) {}
    void add(const P2& p, int id) { cells_[key(cell(p.x), cell(p.y))].push_back(id); }
    template <class F>
    void near(const P2& p, F f) const {
        const long long cx = cell(p.x), cy = cell(p.y);
        for (long long a = cx - 1; a <= cx + 1; ++a)
            for (long long b = cy - 1; b <= cy + 1; ++b) {
                auto it = cells_.find(key(a, b));
                if (it != cells_.end())
                    for (int id : it->second) f(id);
            }
    }

private:
    long long cell(double x) const { return static_cast<long long>(std::floor(x / cell_)); }
    static long long key(long long a, long long b) { return a * 73856093LL ^ b * 19349663LL; }
    double cell_;
    std::unordered_map<long long, std::vector<int>> cells_;
};

}  // namespace

bool pointInLoop(const SectionLoop& loop, const P2& p) {
    if (p.x < loop.lo.x || p.x > loop.hi.x || p.y < loop.lo.y || p.y > loop.hi.y) return false;
    bool in = false;
    const std::size_t n = loop.pts.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const P2& a = loop.pts[i];
        const P2& b = loop.pts[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

std::vector<SectionLoop> sliceLoops(const FaceCatalogue& faces, const std::vector<int>& candidates,
                                    const SetupFrame& frame, double h, double chordTol, double linTol,
                                    std::vector<std::string>& warnings, MeshSection* meshes) {
    std::vector<SectionLoop> loops;
    if (candidates.empty()) return loops;
    // Faces along the axis are cut in their own parameter space; the rest by OCCT.
    std::vector<Piece> pieces;
    TopoDS_Compound comp;
    BRep_Builder bb;
    bb.MakeCompound(comp);
    int general = 0;
    const bool onlyOcct = std::getenv("AERONC_GENERAL_SECTION") != nullptr;  // to compare with OCCT's section
    for (int i : candidates) {
        std::vector<std::vector<P2>> polys;
        if (!onlyOcct && (sectionVerticalFace(faces[i], faces.boundaryUV(i), faces.classifier(i), frame, h,
                                              chordTol, polys) ||
                          (meshes && meshes->section(i, frame, h, polys)))) {
            for (auto& pl : polys) {
                Piece piece;
                piece.face = i;
                piece.pts = std::move(pl);
                if (piece.pts.size() >= 2) pieces.push_back(std::move(piece));
            }
        } else {
            bb.Add(comp, faces[i].face);
            ++general;
        }
    }
    if (general > 0) {
        // OCCT's Boolean section one at a time: levels may be sliced on several threads.
        static std::mutex occtSection;
        std::lock_guard<std::mutex> lock(occtSection);
        const Vec3 o = frame.world({0, 0}, h);
        const gp_Pln plane(gp_Pnt(o[0], o[1], o[2]), gp_Dir(frame.w[0], frame.w[1], frame.w[2]));
        BRepAlgoAPI_Section sec(comp, plane, false);
        sec.ComputePCurveOn1(false);
        sec.Approximation(false);
        sec.SetRunParallel(false);
        sec.SetNonDestructive(true);  // the part's faces are shared: leave their tolerances alone
        sec.Build();
        if (!sec.IsDone()) {
            warnings.push_back("section at height " + std::to_string(h) + " failed");
            return loops;
        }
        for (TopExp_Explorer ex(sec.Shape(), TopAbs_EDGE); ex.More(); ex.Next()) {
            const TopoDS_Edge& e = TopoDS::Edge(ex.Current());
            TopoDS_Shape anc;
            Piece piece;
            if (sec.HasAncestorFaceOn1(e, anc)) piece.face = faces.indexOf(anc);
            BRepAdaptor_Curve c(e);
            const double t0 = c.FirstParameter(), t1 = c.LastParameter();
            if (c.GetType() == GeomAbs_Line) {
                gp_Pnt a = c.Value(t0), b = c.Value(t1);
                piece.pts = {frame.project({a.X(), a.Y(), a.Z()}), frame.project({b.X(), b.Y(), b.Z()})};
            } else {
                GCPnts_QuasiUniformDeflection d(c, chordTol, t0, t1);
                if (d.IsDone() && d.NbPoints() >= 2) {
                    for (int k = 1; k <= d.NbPoints(); ++k) {
                        const gp_Pnt p = d.Value(k);
                        piece.pts.push_back(frame.project({p.X(), p.Y(), p.Z()}));
                    }
                } else {
                    for (int k = 0; k <= 16; ++k) {
                        const gp_Pnt p = c.Value(t0 + (t1 - t0) * k / 16.0);
                        piece.pts.push_back(frame.project({p.X(), p.Y(), p.Z()}));
                    }
                }
            }
            if (piece.pts.size() >= 2) pieces.push_back(std::move(piece));
        }
    }

    const double tol = std::max(10 * linTol, 1e-7);
    EndpointGrid grid(tol);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        grid.add(pieces[k].pts.front(), static_cast<int>(2 * k));
        grid.add(pieces[k].pts.back(), static_cast<int>(2 * k + 1));
    }
    auto endpoint = [&](int id) -> const P2& {
        const Piece& p = pieces[static_cast<std::size_t>(id / 2)];
        return (id % 2) ? p.pts.back() : p.pts.front();
    };

    int open = 0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        if (pieces[k].used) continue;
        SectionLoop loop;
        pieces[k].used = true;
        const P2 start = pieces[k].pts.front();
        for (std::size_t m = 0; m + 1 < pieces[k].pts.size(); ++m) {
            loop.pts.push_back(pieces[k].pts[m]);
            loop.faces.push_back(pieces[k].face);
        }
        P2 cur = pieces[k].pts.back();
        bool closed = dist2(cur, start) <= tol * tol && pieces[k].pts.size() > 2;
        while (!closed) {
            int best = -1;
            double bestD = tol * tol;
            grid.near(cur, [&](int id) {
                if (pieces[static_cast<std::size_t>(id / 2)].used) return;
                const double dd = dist2(endpoint(id), cur);
                if (dd <= bestD) bestD = dd, best = id;
            });
            if (best < 0) {
                // Close on the start when no other piece continues the chain.
                if (dist2(cur, start) <= tol * tol) closed = true;
                break;
            }
            Piece& p = pieces[static_cast<std::size_t>(best / 2)];
            p.used = true;
            std::vector<P2> pts = p.pts;
            if (best % 2) std::reverse(pts.begin(), pts.end());
            for (std::size_t m = 0; m + 1 < pts.size(); ++m) {
                loop.pts.push_back(pts[m]);
                loop.faces.push_back(p.face);
            }
            cur = pts.back();
            closed = dist2(cur, start) <= tol * tol;
        }
        if (!closed || loop.pts.size() < 3) {
            ++open;
            continue;
        }
        double a = 0;
        loop.lo = loop.hi = loop.pts[0];
        for (std::size_t i = 0; i < loop.pts.size(); ++i) {
            const P2& p = loop.pts[i];
            const P2& q = loop.pts[(i + 1) % loop.pts.size()];
            a += p.x * q.y - q.x * p.y;
            loop.lo.x = std::min(loop.lo.x, p.x), loop.lo.y = std::min(loop.lo.y, p.y);
            loop.hi.x = std::max(loop.hi.x, p.x), loop.hi.y = std::max(loop.hi.y, p.y);
        }
        loop.area = 0.5 * a;
        if (loop.area < 0) {  // store counter-clockwise; segment k keeps its face
            std::reverse(loop.pts.begin(), loop.pts.end());
            std::vector<int> f(loop.faces.rbegin(), loop.faces.rend());
            // After reversal segment k runs pts[k] -> pts[k+1], which was old segment n-2-k.
            const std::size_t n = f.size();
            loop.faces.assign(n, -1);
            for (std::size_t i = 0; i < n; ++i) loop.faces[i] = f[(i + 1) % n];
            loop.area = -loop.area;
        }
        if (loop.area > tol * tol) loops.push_back(std::move(loop));
    }
    if (open > 0)
        warnings.push_back(std::to_string(open) + " open section chain(s) at height " + std::to_string(h) +
                           " were ignored");

    // Nesting: a loop's parent is the smallest loop that contains it.
    std::vector<std::size_t> order(loops.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return loops[a].area > loops[b].area; });
    for (std::size_t oi = 0; oi < order.size(); ++oi) {
        SectionLoop& L = loops[order[oi]];
        const P2 probe{0.5 * (L.pts[0].x + L.pts[1].x), 0.5 * (L.pts[0].y + L.pts[1].y)};
        for (std::size_t oj = oi; oj-- > 0;) {  // smaller candidates first
            const SectionLoop& M = loops[order[oj]];
            if (M.area <= L.area) continue;
            if (L.lo.x < M.lo.x || L.lo.y < M.lo.y || L.hi.x > M.hi.x || L.hi.y > M.hi.y) continue;
            if (pointInLoop(M, probe)) {
                L.parent = static_cast<int>(order[oj]);
                break;
            }
        }
    }
    for (std::size_t oi = 0; oi < order.size(); ++oi) {
        SectionLoop& L = loops[order[oi]];
        L.depth = L.parent < 0 ? 0 : loops[static_cast<std::size_t>(L.parent)].depth + 1;
    }
    return loops;
}

}  // namespace aeronc::recognition
