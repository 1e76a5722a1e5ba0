// Features of prismatic blocks, the kinds a labelled set such as MFCAD holds: steps cut across
// an edge of the block, slanted faces larger than the block's sides, passages crossing each
// other. Each part is built here, so the answer is known.
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

using namespace aeronc;
using namespace aeronc::recognition;

namespace {

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) { return BRepAlgoAPI_Cut(a, b).Shape(); }

// A prism: the polygon pts (closed) swept along v.
TopoDS_Shape prism(const std::vector<gp_Pnt>& pts, const gp_Vec& v) {
    BRepBuilderAPI_MakePolygon poly;
    for (const gp_Pnt& p : pts) poly.Add(p);
    poly.Close();
    return BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(poly.Wire()).Face(), v).Shape();
}

RecogniseOptions along(std::initializer_list<Vec3> dirs) {
    RecogniseOptions o;
    o.directions = dirs;
    return o;
}

// FaceN (1-based) of the planar faces whose outward normal n passes test(n).
std::vector<int> planesWhere(const TopoDS_Shape& solid, const std::function<bool(const gp_Dir&)>& test) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    std::vector<int> out;
    for (int i = 1; i <= faces.Extent(); ++i) {
        const TopoDS_Face f = TopoDS::Face(faces(i));
        BRepAdaptor_Surface s(f);
        if (s.GetType() != GeomAbs_Plane) continue;
        gp_Dir n = s.Plane().Axis().Direction();
        if (f.Orientation() == TopAbs_REVERSED) n.Reverse();
        if (test(n)) out.push_back(i);
    }
    return out;
}

const DomainElement* elementOf(const DomainTree& t, int face) {
    const int e = t.faceElement[static_cast<std::size_t>(face - 1)];
    return e < 0 ? nullptr : &t.elements[static_cast<std::size_t>(e)];
}

FaceRole roleOf(const DomainTree& t, int face) { return t.faceRoles[static_cast<std::size_t>(face - 1)]; }

bool isBoxAxis(const Vec3& d) {
    for (int k = 0; k < 3; ++k)
        if (std::fabs(std::fabs(d[k]) - std::round(std::fabs(d[k]))) > 1e-9) return false;
    return true;
}

}  // namespace

// A triangular step cut across the edge y = 0, z = 30 from x = 60 to the end: its slanted wall
// reaches both sides of the box like an edge chamfer, but it rises from the step's floor
// (x = 60), so it is the wall of an open pocket machined from +X, not a chamfer.
TEST(BlockRecognition, BlindStepAcrossAnEdgeIsAnOpenPocket) {
    TopoDS_Shape part = BRepPrimAPI_MakeBox(100, 80, 30).Shape();
    part = cut(part, prism({{60, -1, 30 - 13}, {60, -1, 31}, {60, 13, 31}}, gp_Vec(41, 0, 0)));
    const TopoDS_Shape solid = validatedSolid(part, "test");
    const std::vector<int> slanted =
        planesWhere(solid, [](const gp_Dir& n) { return std::fabs(n.X()) < 1e-9 && std::fabs(n.Z()) > 0.1 && std::fabs(n.Z()) < 0.9; });
    const std::vector<int> floor = planesWhere(solid, [](const gp_Dir& n) { return n.X() > 0.999; });
    ASSERT_EQ(slanted.size(), 1u);
    ASSERT_EQ(floor.size(), 2u);  // the step's floor and the block's end
    const DomainTree t = recognise(solid);
    EXPECT_EQ(roleOf(t, slanted[0]), FaceRole::Wall);
    const DomainElement* e = elementOf(t, slanted[0]);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->type, ElementType::OpenPocket);
    EXPECT_EQ(t.setups[static_cast<std::size_t>(e->setup)].name, "+X");
    int floors = 0;
    for (int f : floor) floors += roleOf(t, f) == FaceRole::Floor && elementOf(t, f) == e;
    EXPECT_EQ(floors, 1);
    for (const SetupDirection& s : t.setups) EXPECT_TRUE(isBoxAxis(s.direction)) << s.name;
}

// A flat block whose largest face is a slanted step under it (a slot splits the top in two):
// the block is still clamped along its box axes first, the slanted floor has a setup of its
// own, and the faces on the box's sides stay stock instead of being walls and chamfers of a
// tilted setup.
TEST(BlockRecognition, SlantedFaceLargerThanTheBoxSidesKeepsTheBoxAxes) {
    TopoDS_Shape part = BRepPrimAPI_MakeBox(100, 100, 40).Shape();
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(40, -1, 30), 20, 102, 11).Shape());  // slot across the top
    // Step under the block from x = 20 on: a wall 25 high at x = 20, a floor falling to 5 at x = 100.
    part = cut(part, prism({{20, -1, -1}, {20, -1, 25}, {101, -1, 5 - 0.25}, {101, -1, -1}}, gp_Vec(0, 102, 0)));
    const TopoDS_Shape solid = validatedSolid(part, "test");
    const std::vector<int> slanted =
        planesWhere(solid, [](const gp_Dir& n) { return std::fabs(n.X()) > 0.1 && std::fabs(n.X()) < 0.9; });
    ASSERT_EQ(slanted.size(), 1u);
    // The faces on the box's sides: the top in two, what is left of the bottom, four sides.
    auto onSide = [](double c, double hi) { return std::fabs(c) < 1e-6 || std::fabs(c - hi) < 1e-6; };
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(solid, TopAbs_FACE, faces);
    std::vector<int> sides;
    for (int i = 1; i <= faces.Extent(); ++i) {
        BRepAdaptor_Surface s(TopoDS::Face(faces(i)));
        if (s.GetType() != GeomAbs_Plane) continue;
        const gp_Pnt p = s.Plane().Location();
        const gp_Dir n = s.Plane().Axis().Direction();
        if ((std::fabs(n.X()) > 0.999 && onSide(p.X(), 100)) || (std::fabs(n.Y()) > 0.999 && onSide(p.Y(), 100)) ||
            (std::fabs(n.Z()) > 0.999 && onSide(p.Z(), 40)))
            sides.push_back(i);
    }
    ASSERT_EQ(sides.size(), 7u);
    const DomainTree t = recognise(solid);
    ASSERT_FALSE(t.setups.empty());
    EXPECT_TRUE(isBoxAxis(t.setups[0].direction)) << t.setups[0].name;
    for (int f : sides) EXPECT_TRUE(roleOf(t, f) == FaceRole::Stock || roleOf(t, f) == FaceRole::Top) << "Face" << f;
    EXPECT_EQ(roleOf(t, slanted[0]), FaceRole::Floor);  // the step is machined
}

// A diamond passage along Z crossed by a square passage along Y: seen from Y the diamond's
// walls are slanted faces beside the square passage's walls, but they bevel nothing (no face
// square to Y meets them), so they are the walls of the diamond passage, found from Z.
TEST(BlockRecognition, CrossingPassagesKeepTheirOwnWalls) {
    TopoDS_Shape part = BRepPrimAPI_MakeBox(100, 80, 60).Shape();
    part = cut(part, prism({{50, 20, -1}, {70, 40, -1}, {50, 60, -1}, {30, 40, -1}}, gp_Vec(0, 0, 62)));
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(42, -1, 20), 16, 82, 20).Shape());
    const TopoDS_Shape solid = validatedSolid(part, "test");
    const std::vector<int> diamond = planesWhere(
        solid, [](const gp_Dir& n) { return std::fabs(n.Z()) < 1e-9 && std::fabs(std::fabs(n.X()) - M_SQRT1_2) < 1e-6; });
    ASSERT_GE(diamond.size(), 4u);
    const DomainTree t = recognise(solid, along({{0, 1, 0}, {0, 0, 1}}));
    for (int f : diamond) {
        EXPECT_EQ(roleOf(t, f), FaceRole::Wall) << "Face" << f;
        const DomainElement* e = elementOf(t, f);
        ASSERT_NE(e, nullptr) << "Face" << f;
        EXPECT_EQ(e->type, ElementType::Opening);
        EXPECT_EQ(t.setups[static_cast<std::size_t>(e->setup)].name, "+Z") << "Face" << f;
    }
}

// A pocket 60 x 30, floor at 10 in a 30 mm block, with a blind hole (radius 4, axis at z 13)
// drilled from its -X wall 15 mm into the block: at the pocket's slicing level the hole's
// chord is a notch in the contour, but material stands over it up to the top. From +Z that
// notch is an undercut: it stays out of the pocket's region, with a warning.
TEST(BlockRecognition, UndercutUnderAWallStaysOutOfThePocket) {
    TopoDS_Shape block = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(100, 60, 30)).Shape();
    block = cut(block, BRepPrimAPI_MakeBox(gp_Pnt(20, 15, 10), gp_Pnt(80, 45, 31)).Shape());
    const gp_Ax2 axis(gp_Pnt(5, 30, 13), gp_Dir(1, 0, 0));
    block = cut(block, BRepPrimAPI_MakeCylinder(axis, 4, 16).Shape());
    const TopoDS_Shape part = validatedSolid(block, "block");
    const DomainTree t = recognise(part, along({{0, 0, 1}}));
    const DomainElement* pocket = nullptr;
    for (const DomainElement& e : t.elements)
        if (e.type == ElementType::ClosedPocket && std::abs(e.level - 10) < 1e-6) pocket = &e;
    ASSERT_NE(pocket, nullptr);
    // The drive loop stays on the pocket's walls: nothing west of x = 20.
    double west = 1e9;
    for (const Vec3& p : pocket->contour) west = std::min(west, p[0]);
    EXPECT_NEAR(west, 20, 1e-3);
    EXPECT_NEAR(pocket->area, 60 * 30, 1);
    // Its walls are the four planes: the hole's wall is no wall of the pocket.
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    EXPECT_EQ(pocket->contourFaces.size(), 4u);
    for (int f : pocket->contourFaces)
        EXPECT_EQ(BRepAdaptor_Surface(TopoDS::Face(faces(f))).GetType(), GeomAbs_Plane) << "face " << f;
    // Said once, naming the setup whose level it is.
    int said = 0;
    for (const std::string& w : t.warnings)
        if (w.find("undercut") != std::string::npos) {
            ++said;
            EXPECT_EQ(w.rfind("setup +Z, level ", 0), 0u) << w;
        }
    EXPECT_EQ(said, 1);
}
