// The channel width that limits a tool, measured where the channel is deep enough to matter: a
// generated impeller whose blades are cut down to half a millimetre at their leading edges (as
// blades that run in to a nose are), against the width known by construction (OCCT's distance
// from the part of the wall where the channel is deep to the next blade's walls).
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impeller/ProcessRoute.h>
#include <aeronc/testparts/ImpellerGenerator.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_IntCS.hxx>
#include <Geom_Line.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax2.hxx>

#include <gtest/gtest.h>

using namespace aeronc;
using namespace aeronc::impeller;

namespace {

struct CutImpeller {
    TopoDS_Shape shape;
    Handle(Geom_Surface) hub;  // the generated hub's surface of revolution about +Z
    double top = 0;            // the cut: nothing of the part above this height
    double leading = 0;        // the blades' leading radius
    ImpellerFeatures features;
    ImpellerDimensions dimensions;
};

// Height of the hub of revolution at radius r.
double hubHeight(const Handle(Geom_Surface)& hub, double r) {
    GeomAPI_IntCS hit(new Geom_Line(gp_Pnt(r, 0, 0), gp_Dir(0, 0, 1)), hub);
    double z = -1e300;
    for (int i = 1; hit.IsDone() && i <= hit.NbPoints(); ++i) z = std::max(z, hit.Point(i).Z());
    return z;
}

// Nine blades without fillets, cut flat half a millimetre above the hub at the blades' leading
// radius: they stand 0.5 mm tall there and full height further out, where the channel is wider.
const CutImpeller& cutImpeller() {
    static const CutImpeller part = [] {
        testparts::ImpellerSpec s;
        s.splitters = false;
        s.filletRadius = 0;
        const auto imp = testparts::makeImpeller(s);
        TopTools_IndexedMapOfShape faces;
        TopExp::MapShapes(imp.shape, TopAbs_FACE, faces);
        CutImpeller c;
        c.hub = BRep_Tool::Surface(TopoDS::Face(faces(imp.truth.hub)));
        c.top = hubHeight(c.hub, s.leadingRadius) + 0.5;
        const TopoDS_Shape above = BRepPrimAPI_MakeBox(gp_Pnt(-100, -100, c.top), gp_Pnt(100, 100, 200)).Shape();
        c.shape = BRepAlgoAPI_Cut(imp.shape, above).Shape();
        c.leading = s.leadingRadius;
        c.features = recogniseImpeller(c.shape);
        c.dimensions = measureImpeller(c.shape, c.features);
        return c;
    }();
    return part;
}

// Where the channel is at least `depth` deep: outside the radius where the hub is `depth` below the cut.
double deepFrom(const CutImpeller& c, double depth) {
    double lo = c.leading, hi = 60;  // the hub falls outwards from the blades' leading edges
    for (int i = 0; i < 60; ++i) {
        const double m = 0.5 * (lo + hi);
        (c.top - hubHeight(c.hub, m) < depth ? lo : hi) = m;
    }
    return hi;
}

TopoDS_Shape compoundOf(const TopTools_IndexedMapOfShape& faces, const std::vector<int>& ids) {
    TopoDS_Compound out;
    BRep_Builder b;
    b.MakeCompound(out);
    for (int id : ids) b.Add(out, faces(id));
    return out;
}

// The truth: OCCT's distance from blade 0's walls outside radius r to blade 1's walls.
double widthOutside(const CutImpeller& c, const ImpellerFeatures& f, double r) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(c.shape, TopAbs_FACE, faces);
    const TopoDS_Shape inner = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -10), gp_Dir(0, 0, 1)), r, 300).Shape();
    const TopoDS_Shape walls = compoundOf(faces, f.blades[0].walls);
    BRepAlgoAPI_Cut cut(walls, inner);
    EXPECT_TRUE(cut.IsDone());
    const TopoDS_Shape outer = cut.Shape();
    auto area = [](const TopoDS_Shape& s) {
        GProp_GProps g;
        BRepGProp::SurfaceProperties(s, g);
        return g.Mass();
    };
    EXPECT_LT(area(outer), area(walls) - 1.0);  // the cut took the walls' inner part
    BRepExtrema_DistShapeShape d(outer, compoundOf(faces, f.blades[1].walls));
    EXPECT_TRUE(d.IsDone());
    return d.Value();
}

}  // namespace

TEST(ChannelWidth, MeasuredWhereTheChannelIsDeep) {
    const CutImpeller& c = cutImpeller();
    const ImpellerFeatures& f = c.features;
    ASSERT_EQ(f.bladeCount, 9);
    ASSERT_EQ(f.splitterCount, 0);
    const ImpellerDimensions& d = c.dimensions;
    // The narrowest gap is at the leading edges, where the blades stand 0.5 mm tall (the station
    // there, 0.7 mm of radius, reaches down the falling hub to about 1 mm).
    EXPECT_LT(d.minChannelDepth, 1.5);
    for (double depth : {2.0, 4.0, 8.0}) {
        SCOPED_TRACE("channel at least " + std::to_string(depth) + " mm deep");
        const double truth = widthOutside(c, f, deepFrom(c, depth));
        EXPECT_GT(truth, d.minChannelWidth + 0.3);  // the case matters: the deep channel is wider
        EXPECT_NEAR(d.channelWidth(depth), truth, 0.25);
    }
    // Up to the depth of the narrowest gap, that gap is the width.
    EXPECT_DOUBLE_EQ(d.channelWidth(0.0), d.minChannelWidth);
}

// The route's roughing ball fits the channel where it is as deep as the ball's radius: a larger
// ball than the shallow gap at the leading edges would allow.
TEST(ChannelWidth, RoughingBallChosenForTheDeepChannel) {
    const CutImpeller& c = cutImpeller();
    const ImpellerFeatures& f = c.features;
    const ImpellerDimensions& d = c.dimensions;
    RouteRule rule;
    rule.position = 1, rule.operation = "rough_channels", rule.toolRule = "ball_in_channel";
    rule.allowance = 0.5, rule.clearance = 0.5;
    std::vector<CuttingTool> tools;
    for (double dia : {4.0, 8.0, 12.0, 16.0, 20.0}) {
        CuttingTool t;
        t.id = "BALL" + std::to_string(static_cast<int>(dia));
        t.type = "ball", t.diameter = dia, t.reach = 40, t.fluteLength = 2 * dia;
        tools.push_back(t);
    }
    const ProcessRoute route = planRoute(f, d, {rule}, tools);
    ASSERT_EQ(route.steps.size(), 1u);
    const double ball = route.steps[0].tool->diameter;
    EXPECT_GT(ball, d.minChannelWidth - 1.5);  // the shallow gap alone would allow less
    EXPECT_LE(ball, d.channelWidth(ball / 2) - 1.5 + 1e-9);
}
