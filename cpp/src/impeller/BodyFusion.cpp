// Several bodies to one solid.
//
// Measured on the shared 11-body impeller (OCCT 7.6): fusing the blades one at a time to the hub
// leaves the hub's B-spline face split where a blade's foot runs and refused by OCCT's face
// check; fixed and fused on, the general face merge throws from the fifth blade on and the
// seventh blade's fuse did not return in six minutes. All blades fused to the hub in one
// Boolean give one solid with a single refused face, which ShapeFix_Face makes valid; the
// faces split on one surface are merged again by FaceMerging.h, which avoids the merges that
// do not return.
#include <aeronc/impeller/BodyFusion.h>

#include <aeronc/core/Error.h>
#include <aeronc/impeller/FaceMerging.h>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRep_Tool.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <Message_ProgressIndicator.hxx>
#include <Message_ProgressRange.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_Face.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <sstream>
#include <vector>

namespace aeronc::impeller {

namespace {

using Clock = std::chrono::steady_clock;

double volume(const TopoDS_Shape& s) {
    GProp_GProps g;
    BRepGProp::VolumeProperties(s, g);
    return std::abs(g.Mass());
}

// Asks the fuse to stop once the time is up (it looks between its stages, not within them).
class TimeLimit : public Message_ProgressIndicator {
public:
    explicit TimeLimit(Clock::time_point end) : end_(end) {}
    Standard_Boolean UserBreak() override { return Clock::now() > end_; }
    void Show(const Message_ProgressScope&, const Standard_Boolean) override {}

private:
    Clock::time_point end_;
};

// The faces of `s` OCCT's checker refuses, each replaced by ShapeFix_Face's; `fixed` counts them.
TopoDS_Shape fixRefusedFaces(const TopoDS_Shape& s, int& fixed) {
    fixed = 0;
    if (BRepCheck_Analyzer(s).IsValid()) return s;
    Handle(ShapeBuild_ReShape) context = new ShapeBuild_ReShape;
    for (TopExp_Explorer e(s, TopAbs_FACE); e.More(); e.Next()) {
        if (BRepCheck_Analyzer(e.Current()).IsValid()) continue;
        ShapeFix_Face fix(TopoDS::Face(e.Current()));
        fix.SetContext(context);  // an edge it replaces is replaced in the neighbours too
        fix.Perform();
        context->Replace(e.Current(), fix.Face());
        ++fixed;
    }
    return context->Apply(s);
}

struct Attempt {
    TopoDS_Shape result;  // the fuse's shape, null when it failed
    TopoDS_Shape solid;   // its one valid solid, null when it is not one
    int facesFixed = 0;
};

Attempt fuse(const TopoDS_Shape& largest, const std::vector<TopoDS_Shape>& others, double fuzzy,
             Clock::time_point end) {
    TopTools_ListOfShape args, tools;
    args.Append(largest);
    for (const TopoDS_Shape& b : others) tools.Append(b);
    BRepAlgoAPI_Fuse op;
    op.SetArguments(args);
    op.SetTools(tools);
    op.SetFuzzyValue(fuzzy);
    op.SetNonDestructive(true);  // the caller's bodies keep their tolerances for the next value
    op.SetRunParallel(false);    // the machine's cores are the caller's
    Handle(TimeLimit) limit = new TimeLimit(end);
    op.Build(limit->Start());
    if (Clock::now() > end) return {};
    Attempt a;
    if (!op.IsDone() || op.HasErrors()) return a;
    a.result = op.Shape();
    if (solidCount(a.result) != 1) return a;
    TopExp_Explorer e(a.result, TopAbs_SOLID);
    const TopoDS_Shape fixed = fixRefusedFaces(e.Current(), a.facesFixed);
    if (solidCount(fixed) == 1 && BRepCheck_Analyzer(fixed).IsValid()) a.solid = fixed;
    return a;
}

// The bodies (1-based, by volume) whose faces end in another solid of `result` than the largest
// body's: those that do not touch it.
std::vector<int> apartBodies(const TopoDS_Shape& result, const std::vector<TopoDS_Shape>& bodies) {
    std::vector<TopoDS_Shape> solids;
    for (TopExp_Explorer e(result, TopAbs_SOLID); e.More(); e.Next()) solids.push_back(e.Current());
    // A body's solid: the one a vertex of the body lies on or in.
    auto solidOf = [&](const TopoDS_Shape& body) {
        TopExp_Explorer v(body, TopAbs_VERTEX);
        if (!v.More()) return -1;
        const gp_Pnt p = BRep_Tool::Pnt(TopoDS::Vertex(v.Current()));
        for (size_t k = 0; k < solids.size(); ++k) {
            BRepClass3d_SolidClassifier c(solids[k], p, 1e-3);
            if (c.State() == TopAbs_ON || c.State() == TopAbs_IN) return static_cast<int>(k);
        }
        return -1;
    };
    const int main = solidOf(bodies.front());
    std::vector<int> apart;
    for (size_t i = 1; i < bodies.size(); ++i) {
        const int k = solidOf(bodies[i]);
        if (k >= 0 && k != main) apart.push_back(static_cast<int>(i) + 1);
    }
    return apart;
}

}  // namespace

int solidCount(const TopoDS_Shape& shape) {
    int n = 0;
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) ++n;
    return n;
}

FusedBodies fuseBodies(const TopoDS_Shape& shape, double timeLimit) {
    const auto start = Clock::now();
    const auto end = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(timeLimit));
    std::vector<std::pair<double, TopoDS_Shape>> bodies;
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) bodies.push_back({volume(e.Current()), e.Current()});
    if (bodies.empty()) throw inputError("fuse bodies: the shape holds no solid");
    std::stable_sort(bodies.begin(), bodies.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    FusedBodies out;
    out.bodies = static_cast<int>(bodies.size());
    // Copies: a fuse may raise the tolerances of its arguments' edges in place.
    std::vector<TopoDS_Shape> kept{BRepBuilderAPI_Copy(bodies.front().second).Shape()};
    std::vector<int> keptNumber{1};
    for (size_t i = 1; i < bodies.size(); ++i) {
        if (bodies[i].first < 1e-4 * bodies.front().first) {
            ++out.dropped;
            continue;
        }
        kept.push_back(BRepBuilderAPI_Copy(bodies[i].second).Shape());
        keptNumber.push_back(static_cast<int>(i) + 1);
    }
    out.fused = static_cast<int>(kept.size());
    if (kept.size() == 1) {
        out.solid = kept.front();
    } else {
        const std::vector<TopoDS_Shape> others(kept.begin() + 1, kept.end());
        Attempt a;
        for (double fuzzy : {0.0, 1e-3, 1e-2}) {
            a = fuse(kept.front(), others, fuzzy, end);
            if (Clock::now() > end) {
                std::ostringstream m;
                m << "fuse bodies: the fuse of " << kept.size() << " bodies took longer than " << timeLimit
                  << " s and was stopped";
                throw geometryError(m.str());
            }
            if (!a.solid.IsNull()) {
                out.fuzzyValue = fuzzy;
                break;
            }
        }
        if (a.solid.IsNull()) {
            if (!a.result.IsNull() && solidCount(a.result) > 1) {
                std::string names;
                for (int k : apartBodies(a.result, kept))
                    names += (names.empty() ? "" : ", ") + std::to_string(keptNumber[k - 1]);
                if (!names.empty())
                    throw inputError("fuse bodies: body " + names + " of " + std::to_string(out.bodies) +
                                     " (by volume) does not fuse with the others into one solid: it does not "
                                     "touch them");
            }
            throw geometryError("fuse bodies: the " + std::to_string(kept.size()) +
                                " bodies do not fuse with the others into one valid solid at any fuzzy value "
                                "up to 0.01 mm");
        }
        out.facesFixed = a.facesFixed;
        out.solid = mergeFacesOfOneSurface(a.solid);
    }
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    std::ostringstream s;
    s << out.bodies << " bodies: " << out.fused << " fused into one solid";
    if (out.dropped) s << ", " << out.dropped << " degenerate (no volume) left out";
    s << " (fuzzy value " << out.fuzzyValue << " mm";
    if (out.facesFixed) s << ", " << out.facesFixed << " face" << (out.facesFixed > 1 ? "s" : "") << " fixed";
    s << ", " << std::fixed << std::setprecision(1) << out.seconds << " s)";
    out.summary = s.str();
    return out;
}

}  // namespace aeronc::impeller
