// Impeller recognition and dimension analysis against the generator's truth, on several
// parameter sets, a moved part, and parts that are not impellers (generated and real).
#include <aeronc/brep/PartIO.h>
#include <aeronc/core/Error.h>
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/testparts/ImpellerGenerator.h>
#include <aeronc/testparts/PanelGenerator.h>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Bnd_Box.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>
#include <set>

#include "ErrorOf.h"
#include "ImpellerTruthChecks.h"

using namespace aeronc;
using namespace aeronc::impeller;
using testparts::ImpellerSpec;

namespace {

using truthchecks::expectMatchesTruth;
using truthchecks::kDimTol;

void checkSpec(const ImpellerSpec& spec) {
    const auto imp = testparts::makeImpeller(spec);
    const auto f = recogniseImpeller(imp.shape);
    const auto d = measureImpeller(imp.shape, f);
    EXPECT_NEAR(f.axisDirection[2], 1, 1e-9);
    EXPECT_NEAR(d.outerRadius, spec.outerRadius, kDimTol);
    Bnd_Box box;  // tight box of the exact geometry: the part's extent along Z
    BRepBndLib::AddOptimal(imp.shape, box, false, false);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    EXPECT_NEAR(d.axialLength, z1 - z0, 1e-2);
    expectMatchesTruth(f, d, imp.truth, spec.splitters);
    const auto json = nlohmann::json::parse(impellerToJson(f, d));
    EXPECT_EQ(json["blades"].size(), imp.truth.blades.size());
    EXPECT_EQ(json["hub"], imp.truth.hub);
    EXPECT_DOUBLE_EQ(json["dimensions"]["filletRadius"].get<double>(), d.filletRadius);
}

ImpellerSpec smallSpec() {
    ImpellerSpec s;
    s.bladeCount = 5;
    return s;
}

}  // namespace

TEST(ImpellerRecognition, DefaultNineAndNine) { checkSpec(ImpellerSpec{}); }

TEST(ImpellerRecognition, SevenBladesWithoutSplitters) {
    ImpellerSpec s;
    s.bladeCount = 7;
    s.splitters = false;
    s.wrapDeg = 12, s.leanDeg = 5, s.filletRadius = 1.5, s.bladeThickness = 2.5;
    s.boreDiameter = 16, s.bladeHeight = 10;
    checkSpec(s);
}

TEST(ImpellerRecognition, SixAndSixWrappedAndLeaning) {
    ImpellerSpec s;
    s.bladeCount = 6;
    s.wrapDeg = 15, s.leanDeg = 6, s.filletRadius = 1.8;
    s.boreDiameter = 24, s.bladeHeight = 14, s.splitterStart = 0.35;
    checkSpec(s);
}

// The same part turned and moved: the same faces and sizes, the axis moved with it.
TEST(ImpellerRecognition, MovedPart) {
    const auto imp = testparts::makeImpeller(smallSpec());
    gp_Trsf turn, shift;
    turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 2, 0.5)), 0.7);
    shift.SetTranslation(gp_Vec(15, -40, 120));
    const gp_Trsf move = shift * turn;
    const TopoDS_Shape moved = BRepBuilderAPI_Transform(imp.shape, move, true).Shape();
    const auto f = recogniseImpeller(moved);
    const auto d = measureImpeller(moved, f);
    expectMatchesTruth(f, d, imp.truth, true);
    const gp_Dir z = gp_Dir(0, 0, 1).Transformed(move);
    EXPECT_NEAR(f.axisDirection[0], z.X(), 1e-9);
    EXPECT_NEAR(f.axisDirection[1], z.Y(), 1e-9);
    EXPECT_NEAR(f.axisDirection[2], z.Z(), 1e-9);
}

TEST(ImpellerRecognition, UnequalBladeGroups) {
    ImpellerSpec s = smallSpec();
    s.omitSplitter = 2;
    const auto imp = testparts::makeImpeller(s);
    const std::string msg = test::inputErrorOf([&] { recogniseImpeller(imp.shape); });
    EXPECT_EQ(msg.rfind("unequal blade groups:", 0), 0u) << msg;
    EXPECT_NE(msg.find("a blade is missing or differs"), std::string::npos) << msg;
}

// Blades standing on the hub with sharp roots (nothing tangent to the hub, as exported models
// often are): the hub is the face of revolution carrying the blades' roots.
TEST(ImpellerRecognition, BladesWithoutRootFillets) {
    ImpellerSpec s = smallSpec();
    s.filletRadius = 0;
    checkSpec(s);
}

// Three main blades and three splitters that are their outer part: a turn of 60 degrees takes
// most of the part onto itself, but only a turn of 120 degrees takes every face onto a copy.
TEST(ImpellerRecognition, ThreeAndThreeWithoutFillets) {
    ImpellerSpec s;
    s.bladeCount = 3;
    s.filletRadius = 0;
    s.bladeHeight = 11;
    checkSpec(s);
}

// The wider families: 5 to 13 blades, with and without splitters and root fillets.
TEST(ImpellerRecognition, Families) {
    struct Family {
        int blades;
        bool splitters;
        double fillet, thickness;
    };
    for (const Family& fam : {Family{5, false, 0.0, 2.0}, Family{13, false, 1.0, 2.0}, Family{11, true, 0.0, 2.0}}) {
        SCOPED_TRACE(std::to_string(fam.blades) + (fam.splitters ? " + splitters" : "") + ", fillet " +
                     std::to_string(fam.fillet));
        ImpellerSpec s;
        s.bladeCount = fam.blades;
        s.splitters = fam.splitters;
        s.filletRadius = fam.fillet;
        s.bladeThickness = fam.thickness;
        checkSpec(s);
    }
}

TEST(ImpellerRecognition, NotAnImpeller) {
    // A panel: many faces of equal area, none repeated about an axis.
    const auto panel = testparts::makePanel(testparts::PanelSpec{});
    std::string msg = test::inputErrorOf([&] { recogniseImpeller(panel.shape); });
    EXPECT_EQ(msg.rfind("not an impeller: no rotational pattern", 0), 0u) << msg;
    // A plain disc with a bore: of revolution, but no pattern.
    BRepBuilderAPI_MakePolygon profile(gp_Pnt(10, 0, 0), gp_Pnt(50, 0, 0), gp_Pnt(50, 0, 20), gp_Pnt(10, 0, 20), true);
    const TopoDS_Shape disc = BRepPrimAPI_MakeRevol(BRepBuilderAPI_MakeFace(profile.Wire()).Face(),
                                                    gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)))
                                  .Shape();
    msg = test::inputErrorOf([&] { recogniseImpeller(disc); });
    EXPECT_EQ(msg.rfind("not an impeller: no rotational pattern", 0), 0u) << msg;
    msg = test::inputErrorOf([&] { recogniseImpeller(TopoDS_Shape()); });
    EXPECT_EQ(msg.rfind("not an impeller", 0), 0u) << msg;
}

// The real parts are no impellers: each is refused with one of the three reasons, none crashes.
TEST(ImpellerRecognition, RealPartsAreRefused) {
    int parts = 0;
    for (const char* sub : {"nist", "real"}) {
        for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(AERONC_SHARED_DATA) / sub)) {
            const auto ext = e.path().extension().string();
            if (ext != ".stp" && ext != ".step") continue;
            SCOPED_TRACE(e.path().string());
            const TopoDS_Shape part = loadPart(e.path().string());
            const std::string msg = test::inputErrorOf([&] { recogniseImpeller(part); });
            const bool known = msg.rfind("not an impeller", 0) == 0 || msg.rfind("unequal blade groups", 0) == 0 ||
                               msg.rfind("missing hub", 0) == 0;
            EXPECT_TRUE(known) << msg;
            ++parts;
        }
    }
    EXPECT_GE(parts, 10);
}
