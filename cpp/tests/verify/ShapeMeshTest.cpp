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
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
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
