// The OCCT adapter and real parts: B-rep solids meshed, tagged with FreeCAD's face numbers and
// rasterised to the volume OCCT computes for them.
#include <aeronc/brep/PartIO.h>
#include <aeronc/verify/PartDexels.h>
#include <aeronc/brep/ShapeMesh.h>
#include <aeronc/verify/Simulation.h>

#include "Fixtures.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp_Face.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

using namespace aeronc;
using namespace aeronc::verify;
using namespace aeronc::verify::test;

namespace {

double occtVolume(const TopoDS_Shape& s) {
    GProp_GProps p;
    BRepGProp::VolumeProperties(s, p);
    return p.Mass();
}

// The plate of the simulation tests, built by OCCT: a 60 x 40 x 20 box less a 40 x 20 pocket
// 12 deep whose vertical corners are rounded to 4.
TopoDS_Shape occtPocketPlate() {
    const TopoDS_Shape plate = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 60, 40, 20).Shape();
    const TopoDS_Shape tool = BRepPrimAPI_MakeBox(gp_Pnt(10, 10, 8), 40, 20, 20).Shape();
    BRepFilletAPI_MakeFillet fillet(tool);
    for (TopExp_Explorer e(tool, TopAbs_EDGE); e.More(); e.Next()) {
        TopoDS_Vertex a, b;
        TopExp::Vertices(TopoDS::Edge(e.Current()), a, b);
        const gp_Pnt pa = BRep_Tool::Pnt(a), pb = BRep_Tool::Pnt(b);
        if (std::abs(pa.X() - pb.X()) < 1e-9 && std::abs(pa.Y() - pb.Y()) < 1e-9) fillet.Add(4, TopoDS::Edge(e.Current()));
    }
    return BRepAlgoAPI_Cut(plate, fillet.Shape()).Shape();
}

std::vector<std::string> realParts() {
    std::vector<std::string> out;
    const std::filesystem::path dir = std::filesystem::path(AERONC_SHARED_DATA) / "nist";
    if (std::filesystem::exists(dir))
        for (const auto& e : std::filesystem::directory_iterator(dir))
            if (e.path().extension() == ".stp") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    out.push_back(std::string(AERONC_RESOURCES) + "/samples/sample_panel.step");
    return out;
}

}  // namespace

TEST(ShapeMesh, TrianglesCarryTheirFreeCadFaceNumbers) {
    const TopoDS_Shape part = occtPocketPlate();
    const TriangleMesh mesh = meshShape(part, 0.005);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    ASSERT_EQ(faces.Extent(), 6 + 1 + 8);
    // Every triangle lies on the face its number names.
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const int f = mesh.faces[t];
        ASSERT_GE(f, 1);
        ASSERT_LE(f, faces.Extent());
        Bnd_Box box;
        BRepBndLib::Add(faces(f), box);
        box.Enlarge(1e-6);
        for (int k : mesh.triangles[t]) {
            const auto& v = mesh.vertices[k];
            ASSERT_FALSE(box.IsOut(gp_Pnt(v[0], v[1], v[2]))) << "triangle " << t << " face " << f;
        }
    }
    EXPECT_NEAR(signedVolume(mesh), occtVolume(part), 1e-3 * occtVolume(part));

    // The pocket floor is the plane at z 8; the dexels end on it inside the pocket.
    int floor = 0;
    for (int f = 1; f <= faces.Extent(); ++f) {
        BRepAdaptor_Surface s(TopoDS::Face(faces(f)));
        if (s.GetType() == GeomAbs_Plane && std::abs(s.Plane().Location().Z() - 8) < 1e-9) floor = f;
    }
    ASSERT_NE(floor, 0);
    const Grid g = gridCovering(0, 0, 60, 40, 0.5);
    const PartDexels d = rasterise(mesh, g);
    EXPECT_EQ(d.inconsistentColumns, 0u);
    const std::size_t c = g.index(60, 40);  // (30.25, 20.25)
    ASSERT_EQ(d.end(c) - d.begin(c), 1);
    EXPECT_EQ(d.begin(c)->face1, floor);
    EXPECT_NEAR(d.begin(c)->z1, 8, 1e-9);
}

TEST(ShapeMesh, OcctPocketIsMachinedByTheCorrectPath) {
    const TopoDS_Shape part = occtPocketPlate();
    const TriangleMesh mesh = meshShape(part, 0.005);
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    Program p;
    p.hasBlank = true;
    p.blank = {0, 0, 0, 60, 40, 20};
    Operation op;
    op.label = "pocket";
    op.cutter = Cutter::fromDiameter(6, 0);
    op.moves = pocketPath({10, 10, 50, 30, 4, 8}, 3, 2.4, 8, 25, 48);
    p.operations = {op};
    // The pocket's faces: everything within its box below the top.
    for (int f = 1; f <= faces.Extent(); ++f) {
        Bnd_Box b;
        BRepBndLib::Add(faces(f), b);
        double x0, y0, z0, x1, y1, z1;
        b.Get(x0, y0, z0, x1, y1, z1);
        if (x0 > 9.99 && x1 < 50.01 && y0 > 9.99 && y1 < 30.01 && z0 > 7.99 && z0 < 19) p.finishedFaces.push_back(f);
    }
    ASSERT_EQ(p.finishedFaces.size(), 9u);  // floor, 4 walls, 4 rounded corners
    const SimulationReport r = simulate(mesh, p);
    EXPECT_EQ(r.gouges.moves, 0u) << (r.gouges.worst ? r.gouges.worst->depth : 0);
    EXPECT_EQ(r.collisions.moves, 0u);
    for (const auto& f : r.coverage.faces) {
        EXPECT_TRUE(f.measured()) << f.face;
        EXPECT_DOUBLE_EQ(f.uncoveredArea, 0) << f.face;
    }
}

class RealPartDexels : public ::testing::TestWithParam<std::string> {};

// Z-dexels see a plate best lying flat, as its setup puts it: the thinnest extent goes along Z
// (the axes cycle, a rotation). At 0.25 mm cells; at 0.5 mm thin walls of some NIST parts alias
// by up to 1.3 % (docs/verification.md).
TEST_P(RealPartDexels, DexelVolumeMatchesOcct) {
    const TopoDS_Shape part = aeronc::loadPart(GetParam());
    TriangleMesh mesh = meshShape(part, 0.05);
    auto b = bounds(mesh);
    const double ex = b[3] - b[0], ey = b[4] - b[1], ez = b[5] - b[2];
    if (ez > ex || ez > ey)
        for (auto& v : mesh.vertices) v = ey <= ex ? Point3{v[2], v[0], v[1]} : Point3{v[1], v[2], v[0]};
    b = bounds(mesh);
    const PartDexels d = rasterise(mesh, gridCovering(b[0], b[1], b[3], b[4], 0.25));
    const double exact = occtVolume(part);
    EXPECT_NEAR(d.volume(), exact, 0.01 * exact);
    EXPECT_EQ(d.inconsistentColumns, 0u);
}

INSTANTIATE_TEST_SUITE_P(Parts, RealPartDexels, ::testing::ValuesIn(realParts()), [](const auto& info) {
    std::string n = std::filesystem::path(info.param).stem().string();
    std::replace_if(n.begin(), n.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
    return n;
});

namespace {

// milled_004 (a curved bar standing on a plate) turned so that its setup's axis, +Y, is +Z.
TopoDS_Shape milled004AlongZ() {
    const TopoDS_Shape part = aeronc::loadPart(std::string(AERONC_SHARED_DATA) + "/real/milled_004.stp");
    gp_Trsf turn;
    turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 0, 0)), M_PI / 2);  // (x, y, z) -> (x, -z, y)
    return BRepBuilderAPI_Transform(part, turn, true).Shape();
}

}  // namespace

// Face 26 of milled_004 is a vertical wall extruded from a B-spline, 23 mm high. BRepMesh left
// slivers across its curve whose middles lay up to 0.17 mm off it at a deflection of 0.002 mm;
// every point of the mesh must now lie within the gate's tolerance (0.01 mm) of the face.
TEST(ShapeMesh, MeshOfAnExtrudedBSplineWallStaysOnTheWall) {
    if (!std::filesystem::exists(std::string(AERONC_SHARED_DATA) + "/real/milled_004.stp")) GTEST_SKIP();
    const TopoDS_Shape part = milled004AlongZ();
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    ASSERT_GE(faces.Extent(), 26);
    const TopoDS_Face wall = TopoDS::Face(faces(26));
    ASSERT_EQ(BRepAdaptor_Surface(wall).GetType(), GeomAbs_BSplineSurface);
    const TriangleMesh mesh = meshShape(part, 0.002);
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(wall);
    double u0, u1, v0, v1;
    surface->Bounds(u0, u1, v0, v1);
    // The wall is its section curve extruded along Z: a point's distance to it is the distance
    // to that curve in the curve's plane.
    const Handle(Geom_Curve) section = surface->VIso(v0);
    const double zs = section->Value(section->FirstParameter()).Z();
    ASSERT_NEAR(section->Value(section->LastParameter()).Z(), zs, 1e-9);
    ASSERT_NEAR(surface->Value(u0, v1).X(), surface->Value(u0, v0).X(), 1e-9);
    ASSERT_NEAR(surface->Value(u0, v1).Y(), surface->Value(u0, v0).Y(), 1e-9);
    GeomAPI_ProjectPointOnCurve project;
    project.Init(section, section->FirstParameter(), section->LastParameter());
    double worst = 0;
    std::size_t checked = 0;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (mesh.faces[t] != 26) continue;
        const auto& a = mesh.vertices[std::size_t(mesh.triangles[t][0])];
        const auto& b = mesh.vertices[std::size_t(mesh.triangles[t][1])];
        const auto& c = mesh.vertices[std::size_t(mesh.triangles[t][2])];
        const double w[4][3] = {{1. / 3, 1. / 3, 1. / 3}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
        for (const auto& k : w) {
            const gp_Pnt p(k[0] * a[0] + k[1] * b[0] + k[2] * c[0], k[0] * a[1] + k[1] * b[1] + k[2] * c[1], zs);
            project.Perform(p);
            // Beyond the curve's ends (the wall's vertical edges) no foot is orthogonal.
            const double d = project.NbPoints() > 0 ? project.LowerDistance()
                                                    : std::min(p.Distance(section->Value(section->FirstParameter())),
                                                               p.Distance(section->Value(section->LastParameter())));
            worst = std::max(worst, d);
            ++checked;
        }
    }
    ASSERT_GT(checked, 1000u);
    EXPECT_LT(worst, 0.01);
}

// The gate on that wall: a D10 end mill going down beside its concave stretch (where the
// slivers were) 0.02 mm off it does not gouge; 0.05 mm into it does, by about 0.05 mm.
TEST(ShapeMesh, GateJudgesCuttersBesideAnExtrudedBSplineWallByTheWall) {
    if (!std::filesystem::exists(std::string(AERONC_SHARED_DATA) + "/real/milled_004.stp")) GTEST_SKIP();
    const TopoDS_Shape part = milled004AlongZ();
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    const TopoDS_Face wall = TopoDS::Face(faces(26));
    const TriangleMesh mesh = meshShape(part, 0.002);
    Bnd_Box box;
    BRepBndLib::Add(part, box);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    BRepAdaptor_Surface surface(wall);
    BRepGProp_Face normals(wall);
    const double R = 5;
    auto run = [&](double gap) {
        Program p;
        p.cellSize = 0.1;
        p.hasBlank = true;
        p.blank = {x0 - 1, y0 - 1, z0, x1 + 1, y1 + 1, z1};
        Operation op;
        op.label = "beside face 26";
        op.cutter = Cutter::fromDiameter(2 * R, 0);
        // u from 0.004 to 0.06: the first 12 mm of the wall, where it turns fastest.
        for (double u = 0.004; u <= 0.06; u += 0.004) {
            const double v = 0.5 * (surface.FirstVParameter() + surface.LastVParameter());
            gp_Pnt on;
            gp_Vec n;
            normals.Normal(u, v, on, n);
            EXPECT_GT(n.Magnitude(), 1e-9);
            n.Normalize();
            EXPECT_LT(std::abs(n.Z()), 1e-6);  // a vertical wall
            const double x = on.X() + n.X() * (R + gap), y = on.Y() + n.Y() * (R + gap);
            op.moves.push_back({MoveKind::Rapid, x, y, z1 + 5});
            op.moves.push_back({MoveKind::Feed, x, y, 14});  // the wall stands from 12 to 35
            op.moves.push_back({MoveKind::Rapid, x, y, z1 + 5});
        }
        p.operations = {op};
        return simulate(mesh, p);
    };
    const SimulationReport clear = run(0.02);
    EXPECT_EQ(clear.gouges.moves, 0u) << (clear.gouges.worst ? clear.gouges.worst->depth : 0);
    const SimulationReport into = run(-0.05);
    EXPECT_GT(into.gouges.moves, 0u);
    ASSERT_TRUE(into.gouges.worst.has_value());
    EXPECT_GT(into.gouges.worst->depth, 0.03);
    EXPECT_LT(into.gouges.worst->depth, 0.07);
}
