// Rotational symmetry of impellers: the generated ones (each face's orbit its copies on the other
// blades, from the generator's truth) and the shared real impeller as exported, whose blade
// bodies differ by the exporter's approximation (face areas up to 1 % apart).
#include "impeller/FaceGraph.h"
#include "impeller/RotationalSymmetry.h"

#include <aeronc/brep/PartIO.h>
#include <aeronc/core/Error.h>
#include <aeronc/impeller/BodyFusion.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/testparts/ImpellerGenerator.h>

#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Lin.hxx>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "ErrorOf.h"

using namespace aeronc;
using namespace aeronc::impeller;

namespace {

const std::vector<int>& orbitOf(const RotationalSymmetry& s, int face) {
    for (const auto& o : s.orbits)
        if (std::find(o.begin(), o.end(), face) != o.end()) return o;
    throw std::logic_error("face in no orbit");
}

}  // namespace

// 5 + 5 generated: order 5 about +Z; each blade face's orbit is the same face on the 5 blades of
// its kind; the hub is an orbit of its own.
TEST(RotationalSymmetry, GeneratedOrbitsAreTheBladeCopies) {
    testparts::ImpellerSpec spec;
    spec.bladeCount = 5;
    const auto imp = testparts::makeImpeller(spec);
    const FaceGraph g(imp.shape);
    const auto s = findRotationalSymmetry(imp.shape, g, 0.1);
    ASSERT_EQ(s.order, 5);
    EXPECT_TRUE(s.axis.Direction().IsParallel(gp_Dir(0, 0, 1), 1e-9));
    EXPECT_LT(gp_Lin(s.axis).Distance(gp_Pnt(0, 0, 0)), 1e-9);
    EXPECT_TRUE(s.unmatched.empty());
    EXPECT_EQ(orbitOf(s, imp.truth.hub), std::vector<int>{imp.truth.hub});
    for (bool splitter : {false, true}) {
        std::set<int> pressures, shrouds;
        for (const auto& b : imp.truth.blades)
            if (b.splitter == splitter) pressures.insert(b.pressure), shrouds.insert(b.shroud);
        const int first = *pressures.begin();
        const auto& o = orbitOf(s, first);
        EXPECT_EQ(std::set<int>(o.begin(), o.end()), pressures);
        const auto& so = orbitOf(s, *shrouds.begin());
        EXPECT_EQ(std::set<int>(so.begin(), so.end()), shrouds);
    }
}

// The shared impeller's hub body and nine blade bodies, as exported: the nine-fold symmetry about
// the bore's axis (the model's Y axis through the origin), though no two blades have equal areas.
TEST(RotationalSymmetry, SharedImpellerBodiesAreNineFold) {
    const auto path = std::filesystem::path(AERONC_SHARED_DATA) / "impeller" / "turbo3d_impeller.step";
    if (!std::filesystem::exists(path)) GTEST_SKIP() << "no " << path;
    const TopoDS_Shape shape = loadShape(path.string());
    ASSERT_EQ(solidCount(shape), 11);
    const FaceGraph g(shape);
    const auto s = findRotationalSymmetry(shape, g, 0.35);
    EXPECT_EQ(s.order, 9);
    EXPECT_TRUE(s.axis.Direction().IsParallel(gp_Dir(0, 1, 0), 1e-6));
    EXPECT_LT(gp_Lin(s.axis).Distance(gp_Pnt(0, 0, 0)), 1e-3);
}

// A splitter left out: the reason names faces next to the gap, not just the counts.
TEST(RotationalSymmetry, UnequalBladesNameTheFaces) {
    testparts::ImpellerSpec spec;
    spec.bladeCount = 5;
    spec.omitSplitter = 2;
    const auto imp = testparts::makeImpeller(spec);
    const std::string msg = test::inputErrorOf([&] { recogniseImpeller(imp.shape); });
    EXPECT_EQ(msg.rfind("unequal blade groups: the part repeats 5 times about its axis, but face", 0), 0u) << msg;
    EXPECT_NE(msg.find("have no copy 72 degrees on"), std::string::npos) << msg;
}

TEST(BodyFusion, OverlappingBodiesBecomeOneValidSolid) {
    TopoDS_Compound c;
    BRep_Builder b;
    b.MakeCompound(c);
    b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 40, 10).Shape());
    b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(5, 5, 9.9995), 10, 2, 20).Shape());   // touches to 5e-4 mm
    b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(20, 5, 5), 10, 2, 20).Shape());       // overlaps
    b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(30, 30, 10), 1e-3, 1e-3, 1e-3).Shape());  // a sliver
    const auto f = fuseBodies(c);
    EXPECT_EQ(f.bodies, 4);
    EXPECT_EQ(f.fused, 3);
    EXPECT_EQ(f.dropped, 1);
    EXPECT_EQ(solidCount(f.solid), 1);
    EXPECT_NO_THROW(validatedSolid(f.solid, "fused"));
}

TEST(BodyFusion, ApartBodiesAreRefused) {
    TopoDS_Compound c;
    BRep_Builder b;
    b.MakeCompound(c);
    b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), 40, 40, 10).Shape());
    b.Add(c, BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 30), 10, 10, 10).Shape());
    try {
        fuseBodies(c);
        FAIL() << "fused bodies that do not touch";
    } catch (const aeronc::Error& e) {
        EXPECT_NE(std::string(e.what()).find("body 2 of 2 (by volume) does not fuse with the others"), std::string::npos)
            << e.what();
    }
}
