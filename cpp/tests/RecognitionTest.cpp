// Recognition on parts built here with known answers, and on bad input.
#include <aeronc/core/Error.h>
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Builder.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Pln.hxx>
#include <gp.hxx>
#include <gp_Ax2.hxx>
#include <gp_Ax3.hxx>
#include <Bnd_Box.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace aeronc;
using namespace aeronc::recognition;

namespace {

TopoDS_Shape roundedBox(double x, double y, double z, double dx, double dy, double dz, double r) {
    TopoDS_Shape b = BRepPrimAPI_MakeBox(gp_Pnt(x, y, z), dx, dy, dz).Shape();
    if (r <= 0) return b;
    BRepFilletAPI_MakeFillet f(b);
    for (TopExp_Explorer e(b, TopAbs_EDGE); e.More(); e.Next()) {
        TopoDS_Vertex v1, v2;
        TopExp::Vertices(TopoDS::Edge(e.Current()), v1, v2);
        const gp_Pnt a = BRep_Tool::Pnt(v1), c = BRep_Tool::Pnt(v2);
        if (std::fabs(a.X() - c.X()) < 1e-9 && std::fabs(a.Y() - c.Y()) < 1e-9) f.Add(r, TopoDS::Edge(e.Current()));
    }
    return f.Shape();
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) { return BRepAlgoAPI_Cut(a, b).Shape(); }

RecogniseOptions along(std::initializer_list<Vec3> dirs) {
    RecogniseOptions o;
    o.directions = dirs;
    return o;
}

std::string tmpFile(const std::string& name, const std::string& content) {
    const std::string p = (std::filesystem::temp_directory_path() / name).string();
    std::ofstream(p, std::ios::binary) << content;
    return p;
}

}  // namespace

TEST(Recognition, RoundedPocketInBlock) {
    const TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 80, 20).Shape(), roundedBox(30, 25, 10, 40, 30, 15, 5));
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    ASSERT_EQ(t.setups.size(), 1u);
    ASSERT_EQ(t.elements.size(), 1u);
    const DomainElement& e = t.elements[0];
    EXPECT_EQ(e.type, ElementType::ClosedPocket);
    EXPECT_EQ(e.parent, -1);
    EXPECT_NEAR(e.level, 10, 1e-6);
    EXPECT_NEAR(e.depth, 10, 1e-6);
    EXPECT_NEAR(e.minCornerRadius, 5, 1e-6);
    EXPECT_NEAR(e.minWidth, 30, 0.05);
    EXPECT_NEAR(e.floorArea, 40 * 30 - (4 - M_PI) * 25, 1e-3);
    EXPECT_NEAR(e.area, 40 * 30 - (4 - M_PI) * 25, 0.5);
    EXPECT_EQ(e.floorFaces.size(), 1u);
    EXPECT_EQ(e.contourFaces.size(), 8u);  // 4 planes + 4 corner cylinders
    EXPECT_TRUE(e.islandFaces.empty());
    EXPECT_EQ(e.topFaces.size(), 1u);
    // Every face has exactly one role; the pocket's faces belong to it.
    int claimed = 0;
    for (std::size_t i = 0; i < t.faceRoles.size(); ++i) claimed += t.faceElement[i] == 0;
    EXPECT_EQ(claimed, 9);
}

TEST(Recognition, SharpCornersGiveZeroRadius) {
    const TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 80, 20).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(30, 25, 12), 40, 30, 10).Shape());
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    ASSERT_EQ(t.elements.size(), 1u);
    EXPECT_EQ(t.elements[0].minCornerRadius, 0);
    EXPECT_NEAR(t.elements[0].depth, 8, 1e-6);
}

// Fillets the edges of `s` whose two ends lie at height z inside the (x0, y0)-(x1, y1) rectangle.
TopoDS_Shape filletEdgesAt(const TopoDS_Shape& s, double z, double x0, double y0, double x1, double y1, double r) {
    BRepFilletAPI_MakeFillet f(s);
    auto in = [&](const gp_Pnt& p) {
        return std::fabs(p.Z() - z) < 1e-9 && p.X() > x0 - 1e-9 && p.X() < x1 + 1e-9 && p.Y() > y0 - 1e-9 &&
               p.Y() < y1 + 1e-9;
    };
    for (TopExp_Explorer e(s, TopAbs_EDGE); e.More(); e.Next()) {
        TopoDS_Vertex v1, v2;
        TopExp::Vertices(TopoDS::Edge(e.Current()), v1, v2);
        if (in(BRep_Tool::Pnt(v1)) && in(BRep_Tool::Pnt(v2))) f.Add(r, TopoDS::Edge(e.Current()));
    }
    return f.Shape();
}

// A round on the floor's outer edge falls away from the floor: not a fillet the cutter's corner
// must fit, unlike the fillet at the foot of the boss standing on it.
TEST(Recognition, RoundOnTheFloorsOuterEdgeIsNoFloorFillet) {
    TopoDS_Shape part = filletEdgesAt(BRepPrimAPI_MakeBox(100, 60, 20).Shape(), 20, 0, 0, 100, 60, 3);
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(gp_Pnt(30, 15, 20), 40, 30, 10).Shape()).Shape();
    part = filletEdgesAt(part, 20, 30, 15, 70, 45, 2);
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    const DomainElement* flange = nullptr;
    for (const DomainElement& e : t.elements)
        if (std::fabs(e.level - 20) < 1e-6 && !e.floorFaces.empty()) flange = &e;
    ASSERT_NE(flange, nullptr);
    EXPECT_NEAR(flange->floorFilletRadius, 2, 1e-6);
    EXPECT_EQ(flange->filletFaces.size(), 4u);  // the boss's foot only
}

namespace {

// A 100 x 40 x 20 block with a step on it from x = 0 to 60 at its foot, its side sloping back to
// x = 54 at its top, 10 higher.
TopoDS_Shape blockWithStepLeaningBack() {
    BRepBuilderAPI_MakePolygon side;
    for (const gp_Pnt& p : {gp_Pnt(0, 0, 20), gp_Pnt(60, 0, 20), gp_Pnt(54, 0, 30), gp_Pnt(0, 0, 30)}) side.Add(p);
    side.Close();
    const TopoDS_Shape step = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(side.Wire()).Face(), gp_Vec(0, 40, 0)).Shape();
    return BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(100, 40, 20).Shape(), step).Shape();
}

}  // namespace

// A wall leaning back from the floor (a step whose side slopes up and away) holds the most
// material at the floor: the region stops there, or a tool clearing the floor cuts into the
// slope. The slice half-way up would put the wall 3 mm further back.
TEST(Recognition, RegionStopsAtTheFootOfAWallLeaningBack) {
    TopoDS_Shape part = blockWithStepLeaningBack();
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    const DomainElement* floor = nullptr;
    for (const DomainElement& e : t.elements)
        if (std::fabs(e.level - 20) < 1e-6) floor = &e;
    ASSERT_NE(floor, nullptr);
    double xmin = HUGE_VAL;
    for (const auto& p : floor->contour) xmin = std::min(xmin, p[0]);
    EXPECT_NEAR(xmin, 60, 0.02);
}

// The same wall leaning back from the floor, with a boss on that floor whose foot is filleted
// (R2): the level is sliced over the fillets, 2 above the floor, where the slope stands 1.2 mm
// further back than at its foot (milled_002's bevel beside its blends). The region still stops
// at the foot.
TEST(Recognition, RegionStopsAtTheFootOfAWallLeaningBackBesideFloorFillets) {
    TopoDS_Shape part = blockWithStepLeaningBack();
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(gp_Pnt(75, 10, 20), 15, 20, 10).Shape()).Shape();
    part = filletEdgesAt(part, 20, 75, 10, 90, 30, 2);
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    const DomainElement* floor = nullptr;
    for (const DomainElement& e : t.elements)
        if (std::fabs(e.level - 20) < 1e-6) floor = &e;
    ASSERT_NE(floor, nullptr);
    ASSERT_NEAR(floor->floorFilletRadius, 2, 1e-6);  // sliced over the fillets
    double xmin = HUGE_VAL;
    for (const auto& p : floor->contour) xmin = std::min(xmin, p[0]);
    EXPECT_NEAR(xmin, 60, 0.02);
}

// A rib across a plate whose feet are blended by B-spline curves (a quarter circle R4
// approximated), as CAD systems write variable or conic blends: no radius can be given the
// cutter's corner, and the slice stands over them (at the rib's walls, 4 from its foot). The
// flange's region stops where the blend meets the floor, not under the blend.
TEST(Recognition, RegionStopsAtTheFootOfASplineFloorBlend) {
    auto blend = [](double cx, double cz, double from, double to) {
        TColgp_Array1OfPnt pts(1, 9);
        for (int k = 0; k < 9; ++k) {
            const double a = from + (to - from) * k / 8;
            pts.SetValue(k + 1, gp_Pnt(cx + 4 * std::cos(a), 0, cz + 4 * std::sin(a)));
        }
        return BRepBuilderAPI_MakeEdge(GeomAPI_PointsToBSpline(pts, 3, 3, GeomAbs_C2, 1e-7).Curve()).Edge();
    };
    // The rib's section in XZ: 40..60 wide, 10..20 high, the blends from 36 and to 64 on the floor.
    auto line = [](double x0, double z0, double x1, double z1) {
        return BRepBuilderAPI_MakeEdge(gp_Pnt(x0, 0, z0), gp_Pnt(x1, 0, z1)).Edge();
    };
    BRepBuilderAPI_MakeWire w;
    w.Add(line(64, 10, 36, 10));
    w.Add(blend(36, 14, -M_PI / 2, 0));
    w.Add(line(40, 14, 40, 20));
    w.Add(line(40, 20, 60, 20));
    w.Add(line(60, 20, 60, 14));
    w.Add(blend(64, 14, M_PI, 3 * M_PI / 2));
    ASSERT_TRUE(w.IsDone());
    const TopoDS_Shape rib = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(w.Wire()).Face(), gp_Vec(0, 60, 0)).Shape();
    const TopoDS_Shape part = BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(100, 60, 10).Shape(), rib).Shape();
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    const DomainElement* left = nullptr;
    for (const DomainElement& e : t.elements) {
        if (std::fabs(e.level - 10) > 1e-6) continue;
        double x0 = HUGE_VAL;
        for (const auto& p : e.contour) x0 = std::min(x0, p[0]);
        if (x0 < 10) left = &e;
    }
    ASSERT_NE(left, nullptr);
    double xmax = -HUGE_VAL;
    for (const auto& p : left->contour) xmax = std::max(xmax, p[0]);
    EXPECT_GT(xmax, 36 - 0.05);
    // Sampled 0.01 over the floor, where the blend stands 0.28 from its foot line (0.01 deep).
    EXPECT_LT(xmax, 36 + 0.3);
}

// A ring groove (R5 outside, R3 boss inside, 2 deep, the boss's top flush with the block's, a
// mark engraved in its middle 1.5 deep): its concave cylinder is a hole's wall over the face
// adjacency, open above along its axis through the mark, but a boss stands in it. The element
// is the pocket round the boss; a hole of the whole circle would mill the boss away
// (milled_003's E38: 0.52 mm into its boss, whose letters open its axis).
TEST(Recognition, RingGrooveIsAPocketRoundItsBossNotAHole) {
    TopoDS_Shape part =
        cut(BRepPrimAPI_MakeBox(60, 40, 20).Shape(),
            BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, 18), gp::DZ()), 5, 3).Shape());
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(30, 20, 18), gp::DZ()), 3, 2).Shape()).Shape();
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(29.5, 19.5, 18.5), 1, 1, 2).Shape());
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    const DomainElement* groove = nullptr;
    for (const DomainElement& e : t.elements) {
        EXPECT_FALSE(e.type == ElementType::Hole && std::fabs(e.level - 18) < 1e-6) << "a hole at the groove's floor";
        if (std::fabs(e.level - 18) < 1e-6 && e.type != ElementType::Hole) groove = &e;
    }
    ASSERT_NE(groove, nullptr);
    EXPECT_EQ(groove->islands.size(), 1u);
    EXPECT_FALSE(groove->contourFaces.empty());
}

// A boss on a plate whose sides lean out as they rise (20 x 20 at the plate's top, 10, and
// 24 x 24 at its own, 30: a drafted island wider at the top, as CTC-02's bosses round its
// flange). A tool from above clearing the plate's top must keep off the boss's top edge: the
// island of the region there is the boss seen from above, not its section at the slice (that
// put the roughing 0.1 mm and the finishing 1.1 mm into CTC-02's bosses).
TEST(Recognition, IslandWiderAtItsTopIsItsOutlineFromAbove) {
    auto square = [](double half, double z) {
        BRepBuilderAPI_MakePolygon p;
        for (const gp_Pnt& q : {gp_Pnt(50 - half, 30 - half, z), gp_Pnt(50 + half, 30 - half, z),
                                gp_Pnt(50 + half, 30 + half, z), gp_Pnt(50 - half, 30 + half, z)})
            p.Add(q);
        p.Close();
        return p.Wire();
    };
    BRepOffsetAPI_ThruSections boss(true, true);
    boss.AddWire(square(10, 10));
    boss.AddWire(square(12, 30));
    boss.Build();
    ASSERT_TRUE(boss.IsDone());
    const TopoDS_Shape part = BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(100, 60, 10).Shape(), boss.Shape()).Shape();
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    const DomainElement* flange = nullptr;
    for (const DomainElement& e : t.elements)
        if (std::fabs(e.level - 10) < 1e-6 && e.islands.size() == 1) flange = &e;
    ASSERT_NE(flange, nullptr);
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    for (const auto& p : flange->islands[0])
        x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    EXPECT_LT(x0, 38 + 0.02);
    EXPECT_GT(x1, 62 - 0.02);
    EXPECT_LT(y0, 18 + 0.02);
    EXPECT_GT(y1, 42 - 0.02);
    // Not much wider than the top either.
    EXPECT_GT(x0, 38 - 0.5);
    EXPECT_LT(x1, 62 + 0.5);
}

namespace {
// The element over a 100 x 60 x 10 block's top with one island standing on it about (50, 30):
// the least and the largest distance of the island's outline from that axis; (inf, 0) when
// there is no such element.
std::pair<double, double> roundIslandRadii(const DomainTree& t) {
    double r0 = HUGE_VAL, r1 = 0;
    for (const DomainElement& e : t.elements) {
        if (!(std::fabs(e.level - 10) < 1e-6 && e.islands.size() == 1)) continue;
        for (const auto& p : e.islands[0]) {
            const double r = std::hypot(p[0] - 50, p[1] - 30);
            r0 = std::min(r0, r), r1 = std::max(r1, r);
        }
    }
    return {r0, r1};
}
}  // namespace

// A dome on a neck (FTC-06's): a sphere R10 whose centre stands 12.6 above the floor, on a
// cylinder R6 it meets 4.6 above the floor. The slice over the floor cuts only the neck, and the
// sphere reaches below its equator: seen from above the island is the equator's circle, not the
// neck's, nor the sphere's section at the heights sampled evenly over its span (9.95 at best).
TEST(Recognition, DomeWiderThanItsNeckIsItsEquatorFromAbove) {
    const TopoDS_Shape block = BRepPrimAPI_MakeBox(100, 60, 10).Shape();
    const TopoDS_Shape neck = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(50, 30, 10), gp::DZ()), 6, 10).Shape();
    const TopoDS_Shape dome = BRepPrimAPI_MakeSphere(gp_Pnt(50, 30, 22.6), 10).Shape();
    const TopoDS_Shape part =
        BRepAlgoAPI_Fuse(BRepAlgoAPI_Fuse(block, neck).Shape(), dome).Shape();
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    const auto [r0, r1] = roundIslandRadii(t);
    ASSERT_GT(r1, 0) << "no element at the block's top with one island";
    EXPECT_GT(r0, 10 - 0.01);  // no point of the outline inside the equator
    EXPECT_LT(r1, 10 + 0.5);
}

// A boss narrowing upwards (a cone from R12 at the floor to R8 at 20 above, FTC-06's): the
// slice over the floor cuts it narrower than its foot; the island is its foot's circle.
TEST(Recognition, ConeWiderAtItsFootIsItsFootFromAbove) {
    const TopoDS_Shape block = BRepPrimAPI_MakeBox(100, 60, 10).Shape();
    const TopoDS_Shape boss = BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(50, 30, 10), gp::DZ()), 12, 8, 20).Shape();
    const DomainTree t =
        recognise(validatedSolid(BRepAlgoAPI_Fuse(block, boss).Shape(), "test"), along({{0, 0, 1}}));
    const auto [r0, r1] = roundIslandRadii(t);
    ASSERT_GT(r1, 0) << "no element at the block's top with one island";
    EXPECT_GT(r0, 12 - 0.005);
    EXPECT_LT(r1, 12 + 0.5);
}

// A slot whose floor rounds (R5, as deep as the slot is wide less its 3 mm floor) rise to 1 mm
// under the top (milled_005's six slots): sliced at 12, where another pocket's floor lies, the
// top millimetre is a region without a floor whose walls end at 12, and a ray down its middle
// runs 5 mm to the slot's floor. The rounds continue its walls below: no opening leaves the part
// there (the chain broke openings through by 2 mm into the rounds), but a pocket down to 12 over
// the slot.
TEST(Recognition, RegionOverTheRoundsOfAPocketBelowIsNoOpening) {
    TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 60, 13).Shape(), roundedBox(30, 20, 7, 40.5, 13, 10, 5));
    part = filletEdgesAt(part, 7, 30, 20, 70.5, 33, 5);
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(10, 40, 12), 15, 10, 5).Shape());  // a floor at 12
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    const DomainElement* over = nullptr;
    for (const DomainElement& e : t.elements) {
        EXPECT_NE(e.type, ElementType::Opening) << "E" << e.id << " at " << e.level;
        double x0 = HUGE_VAL;
        for (const auto& p : e.contour) x0 = std::min(x0, p[0]);
        if (std::fabs(e.level - 12) < 1e-6 && std::fabs(x0 - 30) < 0.01) over = &e;
    }
    ASSERT_NE(over, nullptr);
    EXPECT_EQ(over->type, ElementType::ClosedPocket);
    EXPECT_TRUE(over->floorFaces.empty());
    // The slot below is its child, down to the slot's floor.
    ASSERT_EQ(over->children.size(), 1u);
    EXPECT_NEAR(t.elements[static_cast<std::size_t>(over->children[0])].level, 7, 1e-6);
}

// A bore (24 mm, 9 deep) whose wall a cross hole pierces on its way out to a step: at the slice
// over the bore's floor the bore joins the region outside the part through the cross hole.
// Trimming what lies under material (the cross hole's vault) cuts the bore off again; the
// region left (the air over the step) holds none of the bore's floor and is no pocket at 31
// (on milled_005 it was one, and its profiles ran round the part's end face).
TEST(Recognition, RegionCutOffFromItsFloorByTheUndercutTrimIsNoPocket) {
    TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 60, 40).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(70, 0, 20), 30, 60, 20).Shape());
    part = cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(35, 30, 31), gp_Dir(0, 0, 1)), 12, 10).Shape());
    part = cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(35, 30, 32), gp_Dir(1, 0, 0)), 3, 40).Shape());
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    for (const DomainElement& e : t.elements) {
        if (std::fabs(e.level - 31) > 1e-6) continue;
        // Only the bore itself ends there.
        double x0 = HUGE_VAL, x1 = -HUGE_VAL;
        for (const auto& p : e.contour) x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
        if (e.hole) continue;
        EXPECT_GT(x0, 35 - 12 - 0.1) << "E" << e.id << " reaches x " << x0;
        EXPECT_LT(x1, 35 + 12 + 0.1) << "E" << e.id << " reaches x " << x1;
    }
}

// A body standing on a ledge with an R10 fillet between them along X, and a 45-degree bevel
// on the body's end edge (milled_005's ends). Seen along the bevel's normal the fillet is a wall
// across the axis whose section moves with the height: at the bevel's level its foot stands
// further into the region outside the part than at the slice. The region keeps off it: no point
// of the contour at the level lies inside the part (it did by up to 0.4 mm here; on milled_005
// the finishing profiles cut the fillet by 0.05 mm).
TEST(Recognition, RegionKeepsOffAFilletAcrossATiltedAxis) {
    TopoDS_Shape part = BRepAlgoAPI_Fuse(BRepPrimAPI_MakeBox(100, 60, 15).Shape(),
                                         BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 15), 100, 20, 25).Shape())
                            .Shape();
    {
        BRepFilletAPI_MakeFillet f(part);
        for (TopExp_Explorer e(part, TopAbs_EDGE); e.More(); e.Next()) {
            TopoDS_Vertex v1, v2;
            TopExp::Vertices(TopoDS::Edge(e.Current()), v1, v2);
            const gp_Pnt a = BRep_Tool::Pnt(v1), b = BRep_Tool::Pnt(v2);
            if (std::fabs(a.Y() - 20) + std::fabs(b.Y() - 20) + std::fabs(a.Z() - 15) + std::fabs(b.Z() - 15) < 1e-9)
                f.Add(10, TopoDS::Edge(e.Current()));
        }
        part = f.Shape();
    }
    BRepBuilderAPI_MakePolygon corner;
    for (const gp_Pnt& p : {gp_Pnt(-1, 16, 25), gp_Pnt(-1, 21, 25), gp_Pnt(4, 21, 25)}) corner.Add(p);
    corner.Close();
    part = cut(part, BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(corner.Wire()).Face(), gp_Vec(0, 0, 16)).Shape());
    const Vec3 d{-std::sqrt(0.5), std::sqrt(0.5), 0};
    const TopoDS_Shape solid = validatedSolid(part, "test");
    const DomainTree t = recognise(solid, along({d}));
    const DomainElement* bevel = nullptr;
    for (const DomainElement& e : t.elements)
        if (!e.floorFaces.empty() && std::fabs(e.level - 17 * std::sqrt(0.5)) < 1e-6) bevel = &e;
    ASSERT_NE(bevel, nullptr);
    double deepest = 0;
    for (std::size_t i = 0; i < bevel->contour.size(); ++i) {
        const auto& a = bevel->contour[i];
        const auto& b = bevel->contour[(i + 1) % bevel->contour.size()];
        for (int k = 0; k < 4; ++k) {
            const gp_Pnt p(a[0] + (b[0] - a[0]) * k / 4, a[1] + (b[1] - a[1]) * k / 4, a[2] + (b[2] - a[2]) * k / 4);
            BRepClass3d_SolidClassifier in(solid, p, 1e-6);
            if (in.State() != TopAbs_IN) continue;
            BRepExtrema_DistShapeShape dist(BRepBuilderAPI_MakeVertex(p).Vertex(),
                                            TopExp_Explorer(solid, TopAbs_SHELL).Current());
            deepest = std::max(deepest, dist.Value());
        }
    }
    EXPECT_LT(deepest, 0.01);
}

// A hole whose mouth a bridge partly covers from above: a ray down its axis is clear, but a
// drill as wide as the hole would meet the bridge. Blind, it is overhung; through, it is made
// from below, where its mouth is clear.
TEST(Recognition, HoleUnderABridgeIsOverhungOrMadeFromTheClearSide) {
    TopoDS_Shape bridged = BRepPrimAPI_MakeBox(100, 60, 20).Shape();
    bridged = BRepAlgoAPI_Fuse(bridged, BRepPrimAPI_MakeBox(gp_Pnt(90, 0, 20), 10, 60, 20).Shape()).Shape();
    bridged = BRepAlgoAPI_Fuse(bridged, BRepPrimAPI_MakeBox(gp_Pnt(52, 0, 30), 48, 60, 10).Shape()).Shape();
    auto holeOf = [](const DomainTree& t) -> const DomainElement* {
        for (const DomainElement& e : t.elements)
            if (e.hole && std::fabs(e.hole->diameter - 10) < 1e-6) return &e;
        return nullptr;
    };
    const TopoDS_Shape blind =
        validatedSolid(cut(bridged, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(50, 30, 10), gp_Dir(0, 0, 1)), 5, 11).Shape()),
                       "blind");
    const DomainElement* h = nullptr;
    const DomainTree top = recognise(blind, along({{0, 0, 1}}));
    h = holeOf(top);
    ASSERT_NE(h, nullptr);
    EXPECT_TRUE(h->hole->overhung);
    const TopoDS_Shape through =
        validatedSolid(cut(bridged, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(50, 30, -1), gp_Dir(0, 0, 1)), 5, 22).Shape()),
                       "through");
    const DomainTree both = recognise(through, along({{0, 0, 1}, {0, 0, -1}}));
    h = holeOf(both);
    ASSERT_NE(h, nullptr);
    EXPECT_FALSE(h->hole->overhung);
    EXPECT_NEAR(h->hole->axis[2], -1, 1e-9);
}

// On a tilted axis the corner of the blank box stands above the part's top: an element open to
// the blank starts there, or its first cuts and rapids meet that corner.
TEST(Recognition, ElementOpenToTheBlankStartsAtTheBlanksHighestCorner) {
    const double a = M_PI / 180;  // 1 degree
    const gp_Dir d(0, std::sin(a), std::cos(a));
    // A block whose top is square to d through (50, 30, 25).
    const gp_Pln top(gp_Pnt(50, 30, 25), d);
    TopoDS_Shape above = BRepPrimAPI_MakeBox(gp_Pnt(-500, -500, 0), 1000, 1000, 500).Shape();
    gp_Trsf tr;
    tr.SetTransformation(gp_Ax3(top.Location(), d), gp_Ax3(gp::XOY()));
    above = BRepBuilderAPI_Transform(above, tr).Shape();
    // A boss on it, its top 30 mm high at the low-y end: the part's highest point in the frame.
    const TopoDS_Shape boss = BRepAlgoAPI_Common(BRepPrimAPI_MakeBox(gp_Pnt(60, 0, 0), 40, 20, 30).Shape(), above).Shape();
    const TopoDS_Shape part = BRepAlgoAPI_Fuse(cut(BRepPrimAPI_MakeBox(100, 60, 30).Shape(), above), boss).Shape();
    Bnd_Box bb;
    BRepBndLib::Add(part, bb, false);
    double x0, y0, z0, x1, y1, z1;
    bb.Get(x0, y0, z0, x1, y1, z1);
    x0 += bb.GetGap(), y0 += bb.GetGap(), z0 += bb.GetGap(), x1 -= bb.GetGap(), y1 -= bb.GetGap(), z1 -= bb.GetGap();
    RecogniseOptions o = along({{d.X(), d.Y(), d.Z()}});
    o.blank = Blank{{x0, y0, z0}, {x1, y1, z1}};
    const DomainTree t = recognise(validatedSolid(part, "test"), o);
    const double floor = 30 * d.Y() + 25 * d.Z();
    const double bossTop = 20 * d.Y() + 30 * d.Z();
    const double blankTop = y1 * d.Y() + z1 * d.Z();
    ASSERT_NEAR(z1, 30, 1e-6);
    ASSERT_GT(blankTop, bossTop + 0.5);
    const DomainElement* face = nullptr;
    for (const DomainElement& e : t.elements)
        if (!e.floorFaces.empty()) face = &e;
    ASSERT_NE(face, nullptr);
    EXPECT_NEAR(face->level, floor, 1e-6);
    EXPECT_NEAR(face->top, blankTop, 1e-6);
}

TEST(Recognition, PocketWithIslandAndHoleInFloor) {
    TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(120, 100, 30).Shape(), roundedBox(10, 10, 10, 100, 80, 25, 8));
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(gp_Pnt(20, 20, 10), 20, 20, 15).Shape()).Shape();  // island
    part = cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(80, 50, -1), gp_Dir(0, 0, 1)), 6, 40).Shape());
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    ASSERT_EQ(t.elements.size(), 2u);
    const DomainElement* pocket = nullptr;
    const DomainElement* hole = nullptr;
    for (auto& e : t.elements) (e.hole ? hole : pocket) = &e;
    ASSERT_TRUE(pocket && hole);
    EXPECT_EQ(pocket->type, ElementType::ClosedPocket);
    EXPECT_EQ(pocket->islandFaces.size(), 1u);  // the block; the hole lies below the floor
    EXPECT_EQ(hole->type, ElementType::Hole);
    EXPECT_EQ(hole->parent, pocket->id);
    EXPECT_TRUE(hole->hole->through);
    EXPECT_NEAR(hole->hole->diameter, 12, 1e-6);
    EXPECT_NEAR(hole->hole->depth, 10, 1e-6);
    EXPECT_NEAR(pocket->minWidth, 10, 0.05);  // between the island and the wall
}

// The fast section of round faces (a cross hole square to the axis, a torus and a sphere
// about it, the floor fillets of a pocket) gives the elements and roles OCCT's section gives.
TEST(Recognition, FastSectionOfRoundFacesAgreesWithGeneralSection) {
    TopoDS_Shape part = BRepPrimAPI_MakeBox(120, 100, 40).Shape();
    // A pocket with 3 mm floor fillets: cylinders square to Z along the floor's edges.
    {
        TopoDS_Shape tool = BRepPrimAPI_MakeBox(gp_Pnt(10, 10, 25), 40, 30, 20).Shape();
        BRepFilletAPI_MakeFillet f(tool);
        for (TopExp_Explorer e(tool, TopAbs_EDGE); e.More(); e.Next()) {
            TopoDS_Vertex v1, v2;
            TopExp::Vertices(TopoDS::Edge(e.Current()), v1, v2);
            if (std::fabs(BRep_Tool::Pnt(v1).Z() - 25) < 1e-9 && std::fabs(BRep_Tool::Pnt(v2).Z() - 25) < 1e-9)
                f.Add(3, TopoDS::Edge(e.Current()));
        }
        part = cut(part, f.Shape());
    }
    // Sharp pockets whose levels are sliced through the round faces below.
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(10, 55, 12), 30, 30, 30).Shape());  // floor at 12
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(80, 30, 33), 20, 15, 10).Shape());  // floor at 33
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(70, 62, 36), 15, 15, 10).Shape());  // floor at 36
    // A cross hole along X (z 10 to 16) through the first of them.
    part = cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-1, 70, 13), gp_Dir(1, 0, 0)), 3, 122).Shape());
    // A ball-ended recess (sphere about Z, z 30 to 40) and a ring groove (torus about Z, z 35
    // to 40), each breaking into the side of one of those pockets.
    part = cut(part, BRepPrimAPI_MakeSphere(gp_Pnt(95, 25, 40), 10).Shape());
    part = cut(part, BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(95, 75, 40), gp_Dir(0, 0, 1)), 12, 5).Shape());
    const TopoDS_Shape solid = validatedSolid(part, "test");
    const RecogniseOptions o = along({{0, 0, 1}, {1, 0, 0}});
    const DomainTree fast = recognise(solid, o);
    setenv("AERONC_GENERAL_SECTION", "1", 1);
    const DomainTree general = recognise(solid, o);
    unsetenv("AERONC_GENERAL_SECTION");
    ASSERT_GE(fast.elements.size(), 5u);  // four pockets and the hole
    ASSERT_EQ(fast.elements.size(), general.elements.size());
    for (std::size_t k = 0; k < fast.elements.size(); ++k) {
        EXPECT_EQ(fast.elements[k].type, general.elements[k].type) << k;
        EXPECT_NEAR(fast.elements[k].level, general.elements[k].level, 1e-9) << k;
        EXPECT_NEAR(fast.elements[k].area, general.elements[k].area, 0.05) << k;
        EXPECT_EQ(fast.elements[k].contourFaces, general.elements[k].contourFaces) << k;
    }
    EXPECT_EQ(fast.faceRoles, general.faceRoles);
    EXPECT_EQ(fast.faceElement, general.faceElement);
    EXPECT_EQ(fast.warnings, general.warnings);  // no section chain left open
}

// Faces written as B-splines, as many CAD systems export swept walls: a pocket whose wall is
// a spline swept along Z, held as a B-spline surface, is cut along its iso-curves and gives
// the elements and roles of OCCT's section.
TEST(Recognition, FastSectionOfRuledSplinesAgreesWithGeneralSection) {
    TColgp_Array1OfPnt pts(1, 7);
    const double xy[7][2] = {{20, 20}, {60, 12}, {90, 30}, {85, 60}, {50, 70}, {25, 55}, {20, 20}};
    for (int k = 0; k < 7; ++k) pts.SetValue(k + 1, gp_Pnt(xy[k][0], xy[k][1], -1));
    const Handle(Geom_BSplineCurve) outline = GeomAPI_PointsToBSpline(pts, 3, 3, GeomAbs_C2, 1e-6).Curve();
    const TopoDS_Face lid = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(outline)).Wire());
    // Through the block with B-spline walls, then closed from below by a plate: floor at 12.
    const TopoDS_Shape tool = BRepBuilderAPI_NurbsConvert(BRepPrimAPI_MakePrism(lid, gp_Vec(0, 0, 32)).Shape()).Shape();
    TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(110, 90, 30).Shape(), tool);
    part = BRepAlgoAPI_Fuse(part, BRepPrimAPI_MakeBox(gp_Pnt(5, 5, 0), 95, 75, 12).Shape()).Shape();
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(-1, -1, 22), 10, 102, 10).Shape());  // a step along one side
    // A slot from the +X side ending at x = 50: its level along +X cuts the wall across.
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(50, 78, 25), 61, 8, 10).Shape());
    const TopoDS_Shape solid = validatedSolid(part, "test");
    int splines = 0;
    for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next())
        splines += BRepAdaptor_Surface(TopoDS::Face(e.Current())).GetType() == GeomAbs_BSplineSurface;
    ASSERT_GE(splines, 1);
    const RecogniseOptions o = along({{0, 0, 1}, {1, 0, 0}});
    const DomainTree fast = recognise(solid, o);
    setenv("AERONC_GENERAL_SECTION", "1", 1);
    const DomainTree general = recognise(solid, o);
    unsetenv("AERONC_GENERAL_SECTION");
    ASSERT_GE(fast.elements.size(), 3u);  // the pocket, the step and the slot
    ASSERT_EQ(fast.elements.size(), general.elements.size());
    for (std::size_t k = 0; k < fast.elements.size(); ++k) {
        EXPECT_EQ(fast.elements[k].type, general.elements[k].type) << k;
        EXPECT_NEAR(fast.elements[k].level, general.elements[k].level, 1e-9) << k;
        // Both outlines are polylines within the 0.01 mm chord tolerance of a 200 mm spline.
        EXPECT_NEAR(fast.elements[k].area, general.elements[k].area, 2.0) << k;
        EXPECT_EQ(fast.elements[k].contourFaces, general.elements[k].contourFaces) << k;
    }
    EXPECT_EQ(fast.faceRoles, general.faceRoles);
    EXPECT_EQ(fast.warnings, general.warnings);
}

TEST(Recognition, StepAtEdgeIsOpenPocket) {
    const TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 80, 20).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(-1, -1, 12), 102, 21, 10).Shape());
    const DomainTree t = recognise(validatedSolid(part, "test"), along({{0, 0, 1}}));
    ASSERT_EQ(t.elements.size(), 1u);
    EXPECT_EQ(t.elements[0].type, ElementType::OpenPocket);
    EXPECT_FALSE(t.elements[0].openEdges.empty());
    EXPECT_NEAR(t.elements[0].level, 12, 1e-6);
    EXPECT_EQ(t.elements[0].contourFaces.size(), 1u);
}

TEST(Recognition, DoubleSidedAndRotationStable) {
    TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 80, 20).Shape(), roundedBox(10, 10, 12, 30, 30, 10, 4));
    part = cut(part, roundedBox(50, 20, -1, 30, 40, 7, 3));  // -Z pocket, floor at z = 6
    RecogniseOptions autoDirs;
    const DomainTree t = recognise(validatedSolid(part, "test"), autoDirs);
    ASSERT_EQ(t.elements.size(), 2u);
    ASSERT_EQ(t.setups.size(), 2u);
    for (auto& e : t.elements) {
        const Vec3 d = t.setups[static_cast<std::size_t>(e.setup)].direction;
        if (d[2] > 0.5) EXPECT_NEAR(e.level, 12, 1e-6);
        else EXPECT_NEAR(e.level, -6, 1e-6);
        EXPECT_EQ(e.type, ElementType::ClosedPocket);
    }
    // Rotated part: the same elements, with the same depths.
    gp_Trsf rot;
    rot.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 2, 3)), 0.7);
    const DomainTree r = recognise(validatedSolid(part.Moved(TopLoc_Location(rot)), "test"), autoDirs);
    ASSERT_EQ(r.elements.size(), 2u);
    std::vector<double> a{t.elements[0].depth, t.elements[1].depth}, b{r.elements[0].depth, r.elements[1].depth};
    std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
    EXPECT_NEAR(a[0], b[0], 1e-5);
    EXPECT_NEAR(a[1], b[1], 1e-5);
}

// The case of a 30 mm plate with a 74 x 74 mm closed pocket (corner radii 8 mm) whose floor
// is 2 mm thick, and a through hole of 16 mm in the middle of that floor.
TopoDS_Shape pocketWithFloorHole(bool upsideDown) {
    const double floorZ = upsideDown ? -1 : 2, pocketTop = upsideDown ? 28 : 31;
    TopoDS_Shape part =
        cut(BRepPrimAPI_MakeBox(120, 120, 30).Shape(), roundedBox(23, 23, floorZ, 74, 74, pocketTop - floorZ, 8));
    return cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(60, 60, -1), gp_Dir(0, 0, 1)), 8, 32).Shape());
}

void expectPocketOverHole(const DomainTree& t, const Vec3& pocketSide) {
    ASSERT_EQ(t.elements.size(), 2u);
    const DomainElement* pocket = nullptr;
    const DomainElement* hole = nullptr;
    for (auto& e : t.elements) (e.hole ? hole : pocket) = &e;
    ASSERT_TRUE(pocket && hole);
    EXPECT_EQ(pocket->type, ElementType::ClosedPocket);
    EXPECT_EQ(dot(t.setups[static_cast<std::size_t>(pocket->setup)].direction, pocketSide), 1.0);
    EXPECT_NEAR(pocket->depth, 28, 1e-6);
    EXPECT_EQ(pocket->contourFaces.size(), 8u);
    EXPECT_TRUE(hole->hole->through);
    EXPECT_NEAR(hole->hole->diameter, 16, 1e-6);
    // Every face inside the blank is machined by one of them.
    EXPECT_TRUE(t.unclaimedFaces.empty());
    int claimed = 0;
    for (int e : t.faceElement) claimed += e >= 0;
    EXPECT_EQ(claimed, 8 + 1 + 1);  // walls and corners, floor, hole wall
}

TEST(Recognition, PocketWithThroughHoleInThinFloor) {
    expectPocketOverHole(recognise(validatedSolid(pocketWithFloorHole(false), "test"), along({{0, 0, 1}, {0, 0, -1}})),
                         {0, 0, 1});
    expectPocketOverHole(recognise(validatedSolid(pocketWithFloorHole(false), "test"), RecogniseOptions{}), {0, 0, 1});
}

// Seen from the floor's side, the pocket is a cavity capped by its floor except where the
// hole pierces it: no opening there.
TEST(Recognition, PocketWithFloorHoleSeenFromTheFloorSide) {
    const TopoDS_Shape part = validatedSolid(pocketWithFloorHole(true), "test");
    expectPocketOverHole(recognise(part, along({{0, 0, 1}, {0, 0, -1}})), {0, 0, -1});
    expectPocketOverHole(recognise(part, RecogniseOptions{}), {0, 0, -1});
}

// A cross hole along X, with +Z as the only setup: no element machines its wall, and the
// result says so by face number; the faces on the blank's boundary are not reported.
TEST(Recognition, FaceInsideTheBlankThatNoElementClaimsIsReported) {
    TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 80, 20).Shape(), roundedBox(30, 25, 10, 40, 30, 15, 5));
    part = cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-1, 12, 5), gp_Dir(1, 0, 0)), 3, 102).Shape());
    const TopoDS_Shape solid = validatedSolid(part, "test");
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    int bore = -1;
    for (int i = 1; i <= faces.Extent(); ++i)
        if (BRepAdaptor_Surface(TopoDS::Face(faces(i))).GetType() == GeomAbs_Cylinder &&
            BRepAdaptor_Surface(TopoDS::Face(faces(i))).Cylinder().Radius() == 3)
            bore = i;
    ASSERT_GT(bore, 0);
    const DomainTree t = recognise(solid, along({{0, 0, 1}}));
    ASSERT_EQ(t.elements.size(), 1u);
    EXPECT_EQ(t.unclaimedFaces, std::vector<int>{bore});
    bool warned = false;
    for (const std::string& w : t.warnings) warned |= w.find("Face" + std::to_string(bore)) != std::string::npos;
    EXPECT_TRUE(warned) << "no warning names Face" << bore;
}

// A STEP import can hold free faces and shells besides the solid. Face numbers then follow
// the whole shape (FreeCAD's FaceN of the imported object), wherever the free shapes lie.
TEST(Recognition, FreeShapesBesideTheSolidKeepTheShapesFaceNumbers) {
    const TopoDS_Shape solid =
        validatedSolid(cut(BRepPrimAPI_MakeBox(100, 80, 20).Shape(), roundedBox(30, 25, 10, 40, 30, 15, 5)), "test");
    const TopoDS_Shape freeFace = BRepBuilderAPI_MakeFace(gp_Pln(gp_Pnt(0, 0, 50), gp_Dir(0, 0, 1)), 0, 10, 0, 10).Face();
    TopoDS_Shape freeShell;
    for (TopExp_Explorer e(BRepPrimAPI_MakeBox(gp_Pnt(200, 0, 0), 5, 5, 5).Shape(), TopAbs_SHELL); e.More(); e.Next())
        freeShell = e.Current();
    TopoDS_Compound all;
    BRep_Builder b;
    b.MakeCompound(all);
    b.Add(all, freeFace);  // first, so that the solid's faces do not start at Face1
    b.Add(all, solid);
    b.Add(all, freeShell);
    TopTools_IndexedMapOfShape allFaces, solidFaces;
    TopExp::MapShapes(all, TopAbs_FACE, allFaces);
    TopExp::MapShapes(solid, TopAbs_FACE, solidFaces);
    ASSERT_EQ(allFaces.Extent(), solidFaces.Extent() + 7);

    const DomainTree alone = recognise(solid, along({{0, 0, 1}}));
    const DomainTree t = recogniseShape(all, "import", along({{0, 0, 1}}));
    EXPECT_EQ(t.faceCount, allFaces.Extent());
    ASSERT_EQ(t.faceRoles.size(), static_cast<std::size_t>(allFaces.Extent()));
    ASSERT_EQ(t.elements.size(), alone.elements.size());
    // Each face of the solid has the role it has alone, under the whole shape's number.
    for (int i = 1; i <= solidFaces.Extent(); ++i) {
        const int n = allFaces.FindIndex(solidFaces(i));
        EXPECT_EQ(t.faceRoles[static_cast<std::size_t>(n - 1)], alone.faceRoles[static_cast<std::size_t>(i - 1)]);
        EXPECT_EQ(t.faceElement[static_cast<std::size_t>(n - 1)], alone.faceElement[static_cast<std::size_t>(i - 1)]);
    }
    std::vector<int> floors;
    for (int f : alone.elements[0].floorFaces) floors.push_back(allFaces.FindIndex(solidFaces(f)));
    EXPECT_EQ(t.elements[0].floorFaces, floors);
    // The free faces: no element, listed and named.
    std::vector<int> leftOut{allFaces.FindIndex(freeFace)};
    for (TopExp_Explorer e(freeShell, TopAbs_FACE); e.More(); e.Next()) leftOut.push_back(allFaces.FindIndex(e.Current()));
    std::sort(leftOut.begin(), leftOut.end());
    EXPECT_EQ(t.leftOutFaces, leftOut);
    for (int f : leftOut) EXPECT_EQ(t.faceElement[static_cast<std::size_t>(f - 1)], -1);
    bool named = false;
    for (const std::string& w : t.warnings) named |= w.find("Face" + std::to_string(leftOut.back())) != std::string::npos;
    EXPECT_TRUE(named);
    // The numbers survive the JSON.
    EXPECT_EQ(fromJson(toJson(t)).leftOutFaces, leftOut);
    // A solid alone keeps its own numbering.
    EXPECT_EQ(toJson(recogniseShape(solid, "solid", along({{0, 0, 1}}))), toJson(alone));
}

// A chamfer along an edge of the block is a chamfer, not the floor of an open pocket seen
// along its own normal: no setup is tilted to it, and the pocket beside it is found from +Z.
TEST(Recognition, EdgeChamferOfTheBlockIsAChamfer) {
    TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 80, 30).Shape(), roundedBox(20, 20, 15, 40, 30, 20, 4));
    // A 45 degree chamfer, 12 mm, along the edge y = 80, z = 30 (the whole length in x).
    BRepBuilderAPI_MakePolygon tri(gp_Pnt(-1, 80 - 12, 30), gp_Pnt(-1, 81, 30), gp_Pnt(-1, 81, 30 - 13), gp_Pnt(-1, 80, 30 - 12),
                                   true);
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(tri.Wire()).Face();
    part = cut(part, BRepPrimAPI_MakePrism(face, gp_Vec(102, 0, 0)).Shape());
    const TopoDS_Shape solid = validatedSolid(part, "test");
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    int chamfer = -1;
    for (int i = 1; i <= faces.Extent(); ++i) {
        BRepAdaptor_Surface s(TopoDS::Face(faces(i)));
        if (s.GetType() == GeomAbs_Plane && std::fabs(std::fabs(s.Plane().Axis().Direction().Z()) - M_SQRT1_2) < 1e-6)
            chamfer = i;
    }
    ASSERT_GT(chamfer, 0);
    const DomainTree t = recognise(solid);
    for (const SetupDirection& s : t.setups)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::fabs(s.direction[k]), std::round(std::fabs(s.direction[k])), 1e-9) << s.name;
    EXPECT_EQ(t.faceRoles[static_cast<std::size_t>(chamfer - 1)], FaceRole::Chamfer);
    int pockets = 0;
    for (const DomainElement& e : t.elements) pockets += e.type == ElementType::ClosedPocket;
    EXPECT_EQ(pockets, 1);
    EXPECT_TRUE(std::find(t.unclaimedFaces.begin(), t.unclaimedFaces.end(), chamfer) == t.unclaimedFaces.end());
}

TEST(BadInput, NotAPartFile) {
    EXPECT_THROW(loadPart(tmpFile("aeronc_not_step.txt", "hello world\n")), Error);
    EXPECT_THROW(loadPart(tmpFile("aeronc_empty.step", "")), Error);
    EXPECT_THROW(loadPart("/nonexistent/part.step"), Error);
    try {
        loadPart(tmpFile("aeronc_empty2.step", ""));
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos);
    }
}

TEST(BadInput, OpenShellAndSeveralSolids) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(10, 10, 10).Shape();
    TopoDS_Shape shell;
    for (TopExp_Explorer e(box, TopAbs_SHELL); e.More(); e.Next()) shell = e.Current();
    BRepBuilderAPI_Sewing sew;
    int n = 0;
    for (TopExp_Explorer e(box, TopAbs_FACE); e.More() && n < 5; e.Next(), ++n) sew.Add(e.Current());
    sew.Perform();
    EXPECT_THROW(validatedSolid(sew.SewedShape(), "open"), Error);
    TopoDS_Compound two;
    BRep_Builder b;
    b.MakeCompound(two);
    b.Add(two, box);
    b.Add(two, BRepPrimAPI_MakeBox(gp_Pnt(20, 0, 0), 5, 5, 5).Shape());
    try {
        validatedSolid(two, "two");
        FAIL() << "two solids accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("2 solids"), std::string::npos);
    }
    EXPECT_THROW(partFromBrepText("not brep"), Error);
}

TEST(BadInput, SelfIntersectingBrep) {
    // A prism over a figure-eight outline: a closed shell whose faces cross themselves.
    BRepBuilderAPI_MakePolygon eight;
    for (auto [x, y] : std::vector<std::pair<double, double>>{{0, 0}, {10, 10}, {10, 0}, {0, 10}})
        eight.Add(gp_Pnt(x, y, 0));
    eight.Close();
    const TopoDS_Face base = BRepBuilderAPI_MakeFace(eight.Wire(), true);
    const TopoDS_Shape prism = BRepPrimAPI_MakePrism(base, gp_Vec(0, 0, 5)).Shape();
    try {
        validatedSolid(prism, "figure eight");
        FAIL() << "a self-intersecting B-rep was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("invalid"), std::string::npos) << e.what();
    }
}

TEST(BadInput, NoFaceNormalToDirection) {
    const TopoDS_Shape part = validatedSolid(BRepPrimAPI_MakeBox(10, 10, 10).Shape(), "box");
    try {
        recognise(part, along({{1, 1, 0}}));
        FAIL() << "accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no planar face normal"), std::string::npos);
    }
}
