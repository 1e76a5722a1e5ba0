#include "FaceDistance.h"

#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Precision.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>

namespace aeronc::impellerpath {

// The tolerances are BRepExtrema_ExtPF's and BRepExtrema_ExtPC's, so that the answers are those
// of a BRepExtrema_DistShapeShape between a vertex and the face.
FaceDistance::FaceDistance(const TopoDS_Face& face) : face_(face), surface_(face, false) {
    const double tol = std::min(BRep_Tool::Tolerance(face), Precision::Confusion());
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    extrema_.SetFlag(Extrema_ExtFlag_MIN);  // the nearest is among the minima
    extrema_.SetAlgo(Extrema_ExtAlgo_Grad);
    extrema_.Initialize(surface_, u0, u1, v0, v1, std::max(surface_.UResolution(tol), Precision::PConfusion()),
                        std::max(surface_.VResolution(tol), Precision::PConfusion()));
    classifier_ = std::make_unique<BRepTopAdaptor_FClass2d>(face, BRep_Tool::Tolerance(face));
    TopTools_IndexedMapOfShape edges, vertices;
    TopExp::MapShapes(face, TopAbs_EDGE, edges);
    TopExp::MapShapes(face, TopAbs_VERTEX, vertices);
    for (int i = 1; i <= edges.Extent(); ++i) {
        const TopoDS_Edge& e = TopoDS::Edge(edges(i));
        if (BRep_Tool::Degenerated(e)) continue;
        auto edge = std::make_unique<Edge>();
        edge->curve.Initialize(e);
        double a, b;
        BRep_Tool::Range(e, a, b);
        const double etol = std::max(edge->curve.Resolution(std::min(BRep_Tool::Tolerance(e), Precision::Confusion())),
                                     Precision::PConfusion());
        edge->extrema.Initialize(edge->curve, a, b, etol);
        BRepBndLib::Add(e, edge->box, false);
        edges_.push_back(std::move(edge));
    }
    for (int i = 1; i <= vertices.Extent(); ++i) vertices_.push_back(BRep_Tool::Pnt(TopoDS::Vertex(vertices(i))));
    BRepBndLib::AddOptimal(face, box_, false, false);
    constexpr int n = 20;
    std::vector<gp_Pnt> g;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) g.push_back(surface_.Value(u0 + (u1 - u0) * i / n, v0 + (v1 - v0) * j / n));
    auto at = [&](int i, int j) { return g[i * (n + 1) + j]; };
    // A point of a cell is no farther from its nearest corner than the cell's longest side or
    // diagonal; 0.1 mm more for the cell's bulge off its corners.
    double longest = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            longest = std::max({longest, at(i, j).Distance(at(i + 1, j + 1)), at(i + 1, j).Distance(at(i, j + 1)),
                                at(i, j).Distance(at(i + 1, j)), at(i, j).Distance(at(i, j + 1)),
                                at(i + 1, j).Distance(at(i + 1, j + 1)), at(i, j + 1).Distance(at(i + 1, j + 1))});
    for (const auto& q : g) grid_.push_back(q.XYZ());
    reach_ = longest + 0.1;
}

double FaceDistance::lowerBound(const gp_Pnt& p) const {
    double best = 1e300;
    for (const gp_XYZ& q : grid_) best = std::min(best, (q - p.XYZ()).SquareModulus());
    return std::sqrt(best) - reach_;
}

double FaceDistance::distance(const gp_Pnt& p, gp_Pnt& nearest) {
    double best = 1e300;  // squared
    auto take = [&](double sq, const gp_Pnt& q) {
        if (sq < best) best = sq, nearest = q;
    };
    // The interior first: when p projects inside the face, that is nearly always the answer and
    // the edges farther than it need no query.
    extrema_.Perform(p);
    if (extrema_.IsDone())
        for (int i = 1; i <= extrema_.NbExt(); ++i) {
            if (extrema_.SquareDistance(i) >= best) continue;
            double u, v;
            extrema_.Point(i).Parameter(u, v);
            const TopAbs_State s = classifier_->Perform(gp_Pnt2d(u, v));
            if (s == TopAbs_IN || s == TopAbs_ON) take(extrema_.SquareDistance(i), extrema_.Point(i).Value());
        }
    for (const gp_Pnt& v : vertices_) take(p.SquareDistance(v), v);
    const Bnd_Box point(p.XYZ(), p.XYZ());
    for (auto& e : edges_) {
        const double away = e->box.Distance(point);
        if (away * away >= best) continue;
        e->extrema.Perform(p);
        if (!e->extrema.IsDone()) continue;
        for (int i = 1; i <= e->extrema.NbExt(); ++i) take(e->extrema.SquareDistance(i), e->extrema.Point(i).Value());
    }
    return std::sqrt(best);
}

}  // namespace aeronc::impellerpath
