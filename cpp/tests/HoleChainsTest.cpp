// Holes found over the face adjacency: on any axis, opening onto any face, cut in part by
// other features; with their counterbores and countersinks as the slicing gives them.
#include <aeronc/brep/PartIO.h>
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/testparts/HoleTruth.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <gp_Ax2.hxx>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace aeronc;
using namespace aeronc::recognition;

namespace {

constexpr double kPi = 3.14159265358979323846;

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) { return BRepAlgoAPI_Cut(a, b).Shape(); }
TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b) { return BRepAlgoAPI_Fuse(a, b).Shape(); }

TopoDS_Shape drill(const gp_Pnt& at, const gp_Dir& into, double diameter, double depth) {
    return BRepPrimAPI_MakeCylinder(gp_Ax2(at, into), diameter / 2, depth).Shape();
}

RecogniseOptions along(std::initializer_list<Vec3> dirs) {
    RecogniseOptions o;
    o.directions = dirs;
    return o;
}

// The holes of a tree whose axis is d (the tool's side), by diameter.
std::vector<const DomainElement*> holesAlong(const DomainTree& t, const Vec3& d) {
    std::vector<const DomainElement*> out;
    for (const DomainElement& e : t.elements)
        if (e.hole && dot(e.hole->axis, d) > 1 - 1e-6) out.push_back(&e);
    return out;
}

// Every hole wall by geometry has the role hole_wall, and only those.
void expectEveryHoleWall(const TopoDS_Shape& solid, const DomainTree& t) {
    const std::vector<bool> truth = testparts::holeWallsByGeometry(solid);
    ASSERT_EQ(truth.size(), t.faceRoles.size());
    for (std::size_t i = 0; i < truth.size(); ++i)
        EXPECT_EQ(truth[i], t.faceRoles[i] == FaceRole::HoleWall)
            << "Face" << i + 1 << " is " << (truth[i] ? "" : "not ") << "a hole wall, role " << toString(t.faceRoles[i]);
}

}  // namespace

// A cross hole along X through a block pocketed from +Z: found along X with the setups given
// as +Z only it is reported; found with automatic setups.
TEST(HoleChains, CrossHoleAlongX) {
    TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 60, 40).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(20, 15, 25), 60, 30, 20).Shape());
    part = cut(part, drill(gp_Pnt(-1, 30, 12), gp_Dir(1, 0, 0), 10, 102));
    const TopoDS_Shape solid = validatedSolid(part, "test");
    const DomainTree t = recognise(solid);
    std::vector<const DomainElement*> h = holesAlong(t, {1, 0, 0});
    const std::vector<const DomainElement*> back = holesAlong(t, {-1, 0, 0});
    h.insert(h.end(), back.begin(), back.end());
    ASSERT_EQ(h.size(), 1u);
    EXPECT_NEAR(h[0]->hole->diameter, 10, 1e-6);
    EXPECT_TRUE(h[0]->hole->through);
    EXPECT_NEAR(h[0]->depth, 100, 1e-6);
    expectEveryHoleWall(solid, t);
}

// A blind hole with a drill point on a recessed face (the floor of a step at the edge), and
// one drilled into the side face of the step, under the overhang.
TEST(HoleChains, HolesOnRecessedAndSideFaces) {
    TopoDS_Shape part = cut(BRepPrimAPI_MakeBox(100, 60, 40).Shape(), BRepPrimAPI_MakeBox(gp_Pnt(-1, -1, 20), 41, 62, 21).Shape());
    // On the step's floor (z = 20): 8 mm, 15 deep, 118 degree point.
    const double r = 4, point = r / std::tan(59 * kPi / 180);
    TopoDS_Shape bit = fuse(drill(gp_Pnt(20, 30, 5), gp_Dir(0, 0, 1), 8, 16),
                            BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(20, 30, 5), gp_Dir(0, 0, -1)), r, 0, point).Shape());
    part = cut(part, bit);
    // Into the step's side wall (x = 40, facing -X), under the overhang: 6 mm, 20 deep, flat bottom.
    part = cut(part, drill(gp_Pnt(40, 45, 30), gp_Dir(1, 0, 0), 6, 20));
    const TopoDS_Shape solid = validatedSolid(part, "test");

    const DomainTree t = recognise(solid, along({{0, 0, 1}, {-1, 0, 0}}));
    const auto z = holesAlong(t, {0, 0, 1});
    ASSERT_EQ(z.size(), 1u);
    EXPECT_NEAR(z[0]->hole->diameter, 8, 1e-6);
    EXPECT_FALSE(z[0]->hole->through);
    EXPECT_NEAR(z[0]->level, 5, 1e-6);
    EXPECT_NEAR(z[0]->top, 20, 1e-6);
    EXPECT_EQ(z[0]->floorFaces.size(), 1u);  // the drill point
    const auto x = holesAlong(t, {-1, 0, 0});
    ASSERT_EQ(x.size(), 1u);
    EXPECT_NEAR(x[0]->hole->diameter, 6, 1e-6);
    EXPECT_FALSE(x[0]->hole->through);
    EXPECT_NEAR(x[0]->depth, 20, 1e-6);
    EXPECT_EQ(x[0]->floorFaces.size(), 1u);  // the flat bottom
    expectEveryHoleWall(solid, t);
}

// A hole whose wall a slot cuts across, and a hole that breaks into a pocket's wall: their
// cylinders are in pieces, yet they are holes.
TEST(HoleChains, HolesCutByOtherFeatures) {
    TopoDS_Shape part = BRepPrimAPI_MakeBox(120, 60, 30).Shape();
    part = cut(part, drill(gp_Pnt(30, 30, -1), gp_Dir(0, 0, 1), 12, 32));
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(26, -1, 10), 8, 62, 21).Shape());  // slot across the hole
    part = cut(part, BRepPrimAPI_MakeBox(gp_Pnt(70, 10, 15), 40, 40, 16).Shape());  // pocket
    part = cut(part, drill(gp_Pnt(68, 30, -1), gp_Dir(0, 0, 1), 10, 32));          // breaks into its wall
    const TopoDS_Shape solid = validatedSolid(part, "test");
    const DomainTree t = recognise(solid, along({{0, 0, 1}, {0, 0, -1}}));
    std::vector<double> diameters;
    for (const DomainElement& e : t.elements)
        if (e.hole) diameters.push_back(e.hole->diameter);
    std::sort(diameters.begin(), diameters.end());
    EXPECT_EQ(diameters, (std::vector<double>{10, 12}));
    expectEveryHoleWall(solid, t);
}

// A counterbored through hole stays one counterbore and its hole, made from the counterbore's
// side, whichever setup comes first; a countersunk one keeps its countersink.
TEST(HoleChains, CounterboreAndCountersinkFromTheirSide) {
    TopoDS_Shape part = BRepPrimAPI_MakeBox(80, 40, 20).Shape();
    part = cut(part, drill(gp_Pnt(20, 20, -1), gp_Dir(0, 0, 1), 6.6, 22));
    part = cut(part, drill(gp_Pnt(20, 20, 14), gp_Dir(0, 0, 1), 11, 7));  // counterbore 6 deep
    part = cut(part, drill(gp_Pnt(60, 20, -1), gp_Dir(0, 0, 1), 6.6, 22));
    part = cut(part, BRepPrimAPI_MakeCone(gp_Ax2(gp_Pnt(60, 20, 20 - 2.7 - 0.5), gp_Dir(0, 0, 1)), 3.3 - 0.5, 6.5, 3.7).Shape());
    const TopoDS_Shape solid = validatedSolid(part, "test");
    for (const RecogniseOptions& o : {along({{0, 0, -1}, {0, 0, 1}}), RecogniseOptions{}}) {
        const DomainTree t = recognise(solid, o);
        const auto up = holesAlong(t, {0, 0, 1});
        ASSERT_EQ(up.size(), 3u);
        int counterbored = 0, countersunk = 0;
        for (const DomainElement* e : up) {
            counterbored += e->hole->counterboreDiameter == 11 && e->hole->diameter == 6.6 && e->hole->through;
            countersunk += e->hole->countersinkDiameter > 12 && e->hole->through;
        }
        EXPECT_EQ(counterbored, 1);
        EXPECT_EQ(countersunk, 1);
        EXPECT_TRUE(holesAlong(t, {0, 0, -1}).empty());
        expectEveryHoleWall(solid, t);
    }
}

// Radial holes in a turned part: each axis is found and proposes its own setup.
TEST(HoleChains, RadialHolesInATurnedPart) {
    TopoDS_Shape part = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 30, 40).Shape();
    const std::vector<double> angles{0, 60, 135};
    for (double a : angles) {
        const gp_Dir out(std::cos(a * kPi / 180), std::sin(a * kPi / 180), 0);
        part = cut(part, drill(gp_Pnt(0, 0, 20).Translated(gp_Vec(out) * 31), out.Reversed(), 6, 16));
    }
    const TopoDS_Shape solid = validatedSolid(part, "test");
    const DomainTree t = recognise(solid);
    for (double a : angles) {
        const Vec3 out{std::cos(a * kPi / 180), std::sin(a * kPi / 180), 0};
        const auto h = holesAlong(t, out);
        ASSERT_EQ(h.size(), 1u) << "hole at " << a << " degrees";
        EXPECT_NEAR(h[0]->hole->diameter, 6, 1e-6);
        EXPECT_FALSE(h[0]->hole->through);
        EXPECT_NEAR(h[0]->depth, 15, 0.2);  // from where the wall meets the round outside
    }
    expectEveryHoleWall(solid, t);
}
