// Several bodies to one solid. A plain multi-argument fuse of the shared 11-body impeller gives
// two solids and an invalid B-rep: its blades touch the hub only to the exporter's tolerance.
// Fusing one body at a time with a fuzzy value, and checking each step, keeps it valid.
#include <aeronc/impeller/BodyFusion.h>

#include <aeronc/core/Error.h>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <sstream>
#include <vector>

namespace aeronc::impeller {

namespace {

double volume(const TopoDS_Shape& s) {
    GProp_GProps g;
    BRepGProp::VolumeProperties(s, g);
    return std::abs(g.Mass());
}

// The one solid of a fuse result, or a null shape when it is not one valid solid.
TopoDS_Shape oneValidSolid(const TopoDS_Shape& s) {
    if (s.IsNull() || solidCount(s) != 1) return {};
    TopExp_Explorer e(s, TopAbs_SOLID);
    const TopoDS_Shape solid = e.Current();
    return BRepCheck_Analyzer(solid).IsValid() ? solid : TopoDS_Shape();
}

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b, double fuzzy) {
    TopTools_ListOfShape args, tools;
    args.Append(a);
    tools.Append(b);
    BRepAlgoAPI_Fuse op;
    op.SetArguments(args);
    op.SetTools(tools);
    op.SetFuzzyValue(fuzzy);
    op.SetRunParallel(true);
    op.Build();
    if (!op.IsDone() || op.HasErrors()) return {};
    // The fuse leaves the hub's faces split where a blade's foot ran (and OCCT's checker may
    // refuse those pieces); faces of one surface merged again make the step's solid.
    ShapeUpgrade_UnifySameDomain unify(op.Shape(), true, true, false);
    unify.Build();
    if (TopoDS_Shape merged = oneValidSolid(unify.Shape()); !merged.IsNull()) return merged;
    return oneValidSolid(op.Shape());
}

}  // namespace

int solidCount(const TopoDS_Shape& shape) {
    int n = 0;
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) ++n;
    return n;
}

FusedBodies fuseBodies(const TopoDS_Shape& shape) {
    std::vector<std::pair<double, TopoDS_Shape>> bodies;
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) bodies.push_back({volume(e.Current()), e.Current()});
    if (bodies.empty()) throw inputError("fuse bodies: the shape holds no solid");
    std::stable_sort(bodies.begin(), bodies.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    FusedBodies out;
    out.bodies = static_cast<int>(bodies.size());
    TopoDS_Shape solid = bodies.front().second;
    out.fused = 1;
    const double largest = bodies.front().first;
    for (size_t i = 1; i < bodies.size(); ++i) {
        if (bodies[i].first < 1e-4 * largest) {
            ++out.dropped;
            continue;
        }
        TopoDS_Shape next;
        for (double fuzzy : {1e-3, 1e-2}) {
            next = fuse(solid, bodies[i].second, fuzzy);
            if (!next.IsNull()) {
                out.fuzzyValue = std::max(out.fuzzyValue, fuzzy);
                break;
            }
        }
        if (next.IsNull())
            throw geometryError("fuse bodies: body " + std::to_string(i + 1) + " of " + std::to_string(out.bodies) +
                                " (by volume) does not fuse with the others into one valid solid; it may not touch them");
        solid = next;
        ++out.fused;
    }
    out.solid = solid;
    std::ostringstream s;
    s << out.bodies << " bodies: " << out.fused << " fused into one solid";
    if (out.dropped) s << ", " << out.dropped << " degenerate (no volume) left out";
    s << " (fuzzy value " << out.fuzzyValue << " mm)";
    out.summary = s.str();
    return out;
}

}  // namespace aeronc::impeller
