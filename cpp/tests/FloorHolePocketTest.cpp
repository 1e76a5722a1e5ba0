// Pockets with a lightening hole or a cut-out through their floor, the most common feature of
// an integral panel. The plates are built here by plain boolean cuts from a box (a prism of a
// rounded rectangle for each pocket, a cylinder or a prism through its floor), independently
// of the panel generator, and every expectation comes from that construction.
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeSegment.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gp_Circ.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

using namespace aeronc;
using namespace aeronc::recognition;

namespace {

constexpr double kThickness = 30;  // the plate: z from 0 to 30

// A prism of the w x l rectangle centred on (cx, cy) with corners rounded to r, from z0 to z1.
TopoDS_Shape roundedPrism(double cx, double cy, double w, double l, double r, double z0, double z1) {
    const double x0 = cx - w / 2, x1 = cx + w / 2, y0 = cy - l / 2, y1 = cy + l / 2;
    BRepBuilderAPI_MakeWire wire;
    auto line = [&](double ax, double ay, double bx, double by) {
        wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeSegment(gp_Pnt(ax, ay, z0), gp_Pnt(bx, by, z0)).Value()).Edge());
    };
    auto arc = [&](double ccx, double ccy, double a0) {  // a quarter circle from angle a0, counter-clockwise
        const gp_Circ c(gp_Ax2(gp_Pnt(ccx, ccy, z0), gp_Dir(0, 0, 1)), r);
        wire.Add(BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(c, a0, a0 + M_PI / 2, true).Value()).Edge());
    };
    line(x0 + r, y0, x1 - r, y0);
    if (r > 0) arc(x1 - r, y0 + r, -M_PI / 2);
    line(x1, y0 + r, x1, y1 - r);
    if (r > 0) arc(x1 - r, y1 - r, 0);
    line(x1 - r, y1, x0 + r, y1);
    if (r > 0) arc(x0 + r, y1 - r, M_PI / 2);
    line(x0, y1 - r, x0, y0 + r);
    if (r > 0) arc(x0 + r, y0 + r, M_PI);
    return BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(wire.Wire()).Face(), gp_Vec(0, 0, z1 - z0)).Shape();
}

// What goes through a pocket's floor: a round hole of diameter d, or a w x l cut-out with
// corners rounded to r.
struct Cutout {
    bool round = true;
    double d = 16;
    double w = 0, l = 0, r = 0;
    double area() const { return round ? M_PI * d * d / 4 : w * l - (4 - M_PI) * r * r; }
};

// A pocket opening on the +Z (side 1) or -Z (side -1) face of the plate, its floor `floor`
// thick, with a cut-out through the floor's middle.
struct FloorPocket {
    int side = 1;
    double cx = 87, cy = 87, w = 74, l = 74, r = 8;
    double floor = 2;
    Cutout cut;
    double floorZ() const { return side > 0 ? floor : kThickness - floor; }
    double floorArea() const { return w * l - (4 - M_PI) * r * r - cut.area(); }
};

TopoDS_Shape plate(double x, double y, const std::vector<FloorPocket>& pockets) {
    TopoDS_Shape part = BRepPrimAPI_MakeBox(x, y, kThickness).Shape();
    for (const FloorPocket& p : pockets) {
        const double z0 = p.side > 0 ? p.floorZ() : -1, z1 = p.side > 0 ? kThickness + 1 : p.floorZ();
        part = BRepAlgoAPI_Cut(part, roundedPrism(p.cx, p.cy, p.w, p.l, p.r, z0, z1)).Shape();
        const TopoDS_Shape through =
            p.cut.round ? BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(p.cx, p.cy, -1), gp_Dir(0, 0, 1)), p.cut.d / 2,
                                                   kThickness + 2)
                              .Shape()
                        : roundedPrism(p.cx, p.cy, p.cut.w, p.cut.l, p.cut.r, -1, kThickness + 1);
        part = BRepAlgoAPI_Cut(part, through).Shape();
    }
    return validatedSolid(part, "test plate");
}

struct FaceBox {
    double x0, y0, z0, x1, y1, z1;
    bool horizontalPlane;
};

// The faces of `solid` in FaceN order (index + 1), with their boxes.
std::vector<FaceBox> faceBoxes(const TopoDS_Shape& solid) {
    TopTools_IndexedMapOfShape map;
    TopExp::MapShapes(solid, TopAbs_FACE, map);
    std::vector<FaceBox> out;
    for (int i = 1; i <= map.Extent(); ++i) {
        Bnd_Box b;
        BRepBndLib::AddOptimal(map(i), b, false, false);
        FaceBox f{};
        b.Get(f.x0, f.y0, f.z0, f.x1, f.y1, f.z1);
        f.horizontalPlane = BRepAdaptor_Surface(TopoDS::Face(map(i))).GetType() == GeomAbs_Plane && f.z1 - f.z0 < 1e-6;
        out.push_back(f);
    }
    return out;
}

// The faces, by construction, of one pocket: its floor, its walls and corners, and the walls
// of the cut-out through its floor.
struct PocketFaces {
    int floor = -1;
    std::set<int> walls, cutWalls;
};

PocketFaces facesOf(const FloorPocket& p, const std::vector<FaceBox>& boxes) {
    const double e = 1e-4;
    auto within = [&](const FaceBox& f, double w, double l) {
        return f.x0 > p.cx - w / 2 - e && f.x1 < p.cx + w / 2 + e && f.y0 > p.cy - l / 2 - e && f.y1 < p.cy + l / 2 + e;
    };
    const double cw = p.cut.round ? p.cut.d : p.cut.w, cl = p.cut.round ? p.cut.d : p.cut.l;
    // The pocket spans from its floor to the plate's face on its side, the cut-out the rest.
    const double pz0 = p.side > 0 ? p.floorZ() : 0, pz1 = p.side > 0 ? kThickness : p.floorZ();
    const double cz0 = p.side > 0 ? 0 : p.floorZ(), cz1 = p.side > 0 ? p.floorZ() : kThickness;
    PocketFaces out;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const FaceBox& f = boxes[i];
        const int id = static_cast<int>(i) + 1;
        if (!within(f, p.w, p.l)) continue;
        if (f.horizontalPlane) {
            if (std::fabs(f.z0 - p.floorZ()) < e) out.floor = id;
        } else if (std::fabs(f.z0 - pz0) < e && std::fabs(f.z1 - pz1) < e) {
            out.walls.insert(id);
        } else if (within(f, cw, cl) && std::fabs(f.z0 - cz0) < e && std::fabs(f.z1 - cz1) < e) {
            out.cutWalls.insert(id);
        }
    }
    return out;
}

std::set<int> asSet(const std::vector<int>& v) { return {v.begin(), v.end()}; }

// The element with `floor` among its floors, or null.
const DomainElement* elementWithFloor(const DomainTree& t, int floor) {
    for (const DomainElement& e : t.elements)
        if (std::find(e.floorFaces.begin(), e.floorFaces.end(), floor) != e.floorFaces.end()) return &e;
    return nullptr;
}

const DomainElement* elementWithWalls(const DomainTree& t, const std::set<int>& walls) {
    for (const DomainElement& e : t.elements)
        if (asSet(e.contourFaces) == walls) return &e;
    return nullptr;
}

// Checks pocket p of a recognised plate: a closed pocket on its side with its floor (the face
// with the cut-out in it) and all its walls, and the cut-out a hole or an opening through the
// floor, under the pocket when `underPocket`. Every face of both belongs to one of them.
void expectFloorPocket(const DomainTree& t, const std::vector<FaceBox>& boxes, const FloorPocket& p,
                       bool underPocket = true) {
    const PocketFaces f = facesOf(p, boxes);
    ASSERT_GT(f.floor, 0) << "construction: no floor face found";
    ASSERT_EQ(f.walls.size(), p.r > 0 ? 8u : 4u) << "construction: pocket walls";
    ASSERT_EQ(f.cutWalls.size(), p.cut.round ? 1u : (p.cut.r > 0 ? 8u : 4u)) << "construction: cut-out walls";

    const DomainElement* pocket = elementWithFloor(t, f.floor);
    ASSERT_NE(pocket, nullptr) << "no element has the floor Face" << f.floor;
    const Vec3 dir = t.setups[static_cast<std::size_t>(pocket->setup)].direction;
    EXPECT_EQ(pocket->type, ElementType::ClosedPocket);
    EXPECT_NEAR(dir[2], p.side, 1e-9);
    EXPECT_NEAR(pocket->level, p.side > 0 ? p.floor : -(kThickness - p.floor), 1e-6);
    EXPECT_NEAR(pocket->depth, kThickness - p.floor, 1e-6);
    EXPECT_EQ(pocket->floorFaces, std::vector<int>{f.floor});
    EXPECT_NEAR(pocket->floorArea, p.floorArea(), 1e-3 * p.floorArea());
    EXPECT_NEAR(pocket->area, p.w * p.l - (4 - M_PI) * p.r * p.r, 0.5);  // the region above the floor
    EXPECT_EQ(asSet(pocket->contourFaces), f.walls);
    EXPECT_TRUE(pocket->islandFaces.empty());  // the cut-out lies below the floor
    EXPECT_NEAR(pocket->minCornerRadius, p.r, 1e-6);

    const DomainElement* cut = elementWithWalls(t, f.cutWalls);
    ASSERT_NE(cut, nullptr) << "no element has the cut-out's walls";
    EXPECT_NEAR(cut->depth, p.floor, 1e-6);
    if (underPocket) {
        EXPECT_EQ(cut->setup, pocket->setup);
        EXPECT_EQ(cut->parent, pocket->id);
        EXPECT_NE(std::find(pocket->children.begin(), pocket->children.end(), cut->id), pocket->children.end());
    }
    if (p.cut.round) {
        EXPECT_EQ(cut->type, ElementType::Hole);
        ASSERT_TRUE(cut->hole.has_value());
        EXPECT_NEAR(cut->hole->diameter, p.cut.d, 1e-6);
        EXPECT_TRUE(cut->hole->through);
        EXPECT_NEAR(cut->hole->depth, p.floor, 1e-6);
    } else {
        EXPECT_EQ(cut->type, ElementType::Opening);
        EXPECT_NEAR(cut->area, p.cut.area(), 0.5);
    }

    for (int id : f.walls) EXPECT_EQ(t.faceElement[static_cast<std::size_t>(id - 1)], pocket->id) << "Face" << id;
    EXPECT_EQ(t.faceElement[static_cast<std::size_t>(f.floor - 1)], pocket->id);
    EXPECT_EQ(t.faceRoles[static_cast<std::size_t>(f.floor - 1)], FaceRole::Floor);
    for (int id : f.cutWalls) EXPECT_EQ(t.faceElement[static_cast<std::size_t>(id - 1)], cut->id) << "Face" << id;
}

// Recognised as a user would (setups found from the part) and as the main job does (the
// part's box stated as the blank): the same pockets either way.
std::vector<DomainTree> recogniseBothWays(const TopoDS_Shape& part, double x, double y) {
    RecogniseOptions job;
    job.blank = Blank{{0, 0, 0}, {x, y, kThickness}};
    return {recognise(part, RecogniseOptions{}), recognise(part, job)};
}

// The plate as built, and as read back from the STEP file a user would hand over.
std::vector<TopoDS_Shape> asBuiltAndFromStep(const TopoDS_Shape& part, const std::string& name) {
    const std::string path = (std::filesystem::temp_directory_path() / ("aeronc_floorhole_" + name + ".step")).string();
    writeStep(part, path);
    const TopoDS_Shape read = loadPart(path);
    std::filesystem::remove(path);
    return {part, read};
}

void expectPlate(double x, double y, const std::vector<FloorPocket>& pockets) {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    for (const TopoDS_Shape& part : asBuiltAndFromStep(plate(x, y, pockets), name)) {
        const std::vector<FaceBox> boxes = faceBoxes(part);
        for (const DomainTree& t : recogniseBothWays(part, x, y)) {
            EXPECT_EQ(t.elements.size(), 2 * pockets.size());
            EXPECT_TRUE(t.unclaimedFaces.empty());
            for (const FloorPocket& p : pockets) expectFloorPocket(t, boxes, p);
        }
    }
}

Cutout window(double w, double l, double r) {
    Cutout c;
    c.round = false, c.w = w, c.l = l, c.r = r;
    return c;
}

FloorPocket pocket(int side, double floor, double r, const Cutout& cut, double cx = 87, double cy = 87) {
    FloorPocket p;
    p.side = side, p.floor = floor, p.r = r, p.cut = cut, p.cx = cx, p.cy = cy;
    return p;
}

}  // namespace

// 174 x 174 x 30 plate, a 74 x 74 pocket with R8 corners, floor at z = 2, a 16 mm hole
// through the floor's middle.
TEST(FloorHolePocket, ThinFloorRoundHoleFromTop) { expectPlate(174, 174, {pocket(1, 2, 8, Cutout{})}); }

TEST(FloorHolePocket, ThickFloorRoundHoleSmallCorners) { expectPlate(174, 174, {pocket(1, 8, 3, Cutout{})}); }

TEST(FloorHolePocket, RectangularCutOut) {
    expectPlate(174, 174, {pocket(1, 2, 3, window(30, 20, 3))});
    expectPlate(174, 174, {pocket(1, 8, 8, window(40, 24, 0))});  // sharp-cornered window
}

TEST(FloorHolePocket, FromBelow) {
    expectPlate(174, 174, {pocket(-1, 2, 8, Cutout{})});
    expectPlate(174, 174, {pocket(-1, 8, 3, window(30, 20, 3))});
}

TEST(FloorHolePocket, TwoPocketsOnOnePlate) {
    expectPlate(300, 174, {pocket(1, 2, 8, Cutout{}, 80, 87), pocket(1, 8, 3, window(30, 20, 3), 210, 87)});
}

// Pockets on both faces: the -Z pocket's cut-out opens on the plate's top face too, so the
// first setup (+Z) makes it through to that pocket; each pocket keeps its floor and walls.
TEST(FloorHolePocket, PocketsOnBothSides) {
    const std::vector<FloorPocket> pockets{pocket(1, 2, 8, Cutout{}, 80, 87), pocket(-1, 8, 3, window(30, 20, 3), 210, 87)};
    const TopoDS_Shape part = plate(300, 174, pockets);
    const std::vector<FaceBox> boxes = faceBoxes(part);
    for (const DomainTree& t : recogniseBothWays(part, 300, 174)) {
        EXPECT_EQ(t.elements.size(), 4u);
        EXPECT_TRUE(t.unclaimedFaces.empty());
        expectFloorPocket(t, boxes, pockets[0]);
        expectFloorPocket(t, boxes, pockets[1], false);
    }
}

// Corners rounded to the floor fillet's radius meet the floor in a ball corner. A ball end
// caps a hole; a ball corner does not: the pocket goes on below it to its floor. Taken for a
// drill point, it put a level at the fillets' top where the pocket above looked like an
// opening, and the pocket kept only its fillet band.
TEST(FloorHolePocket, BallCornersAreNoDrillPoints) {
    for (const double rf : {3.0, 8.0}) {
        const double floor = 2;
        TopoDS_Shape tool = roundedPrism(87, 87, 74, 74, 0, floor, kThickness + 10);
        BRepFilletAPI_MakeFillet f(tool);  // every edge below the plate's top: the walls' and the floor's
        for (TopExp_Explorer e(tool, TopAbs_EDGE); e.More(); e.Next()) {
            TopoDS_Vertex a, b;
            TopExp::Vertices(TopoDS::Edge(e.Current()), a, b);
            if (std::min(BRep_Tool::Pnt(a).Z(), BRep_Tool::Pnt(b).Z()) < kThickness) f.Add(rf, TopoDS::Edge(e.Current()));
        }
        TopoDS_Shape part = BRepAlgoAPI_Cut(BRepPrimAPI_MakeBox(174, 174, kThickness).Shape(), f.Shape()).Shape();
        part = BRepAlgoAPI_Cut(part, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(87, 87, -1), gp_Dir(0, 0, 1)), 8, 40).Shape())
                   .Shape();
        const DomainTree t = recognise(validatedSolid(part, "test"), RecogniseOptions{});
        ASSERT_EQ(t.elements.size(), 2u) << "fillet " << rf;
        const DomainElement* pocket = nullptr;
        const DomainElement* hole = nullptr;
        for (const DomainElement& e : t.elements) (e.hole ? hole : pocket) = &e;
        ASSERT_TRUE(pocket && hole);
        EXPECT_EQ(pocket->type, ElementType::ClosedPocket);
        EXPECT_NEAR(pocket->level, floor, 1e-6);
        EXPECT_NEAR(pocket->depth, kThickness - floor, 1e-6);
        EXPECT_NEAR(pocket->minCornerRadius, rf, 1e-6);
        EXPECT_NEAR(pocket->floorFilletRadius, rf, 1e-6);
        const double flat = 74 - 2 * rf;
        EXPECT_NEAR(pocket->floorArea, flat * flat - M_PI * 64, 1e-3);
        EXPECT_EQ(pocket->contourFaces.size(), 8u);
        EXPECT_EQ(pocket->filletFaces.size(), 8u);  // four floor fillets, four ball corners
        EXPECT_EQ(hole->parent, pocket->id);
        EXPECT_NEAR(hole->hole->diameter, 16, 1e-6);
        EXPECT_TRUE(t.unclaimedFaces.empty());
    }
}
