// Tests of the impeller test-part generator: a valid solid whose truth names every face once and
// agrees with the geometry.
#include <aeronc/core/Error.h>
#include <aeronc/testparts/ImpellerGenerator.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

#include "ErrorOf.h"

using namespace aeronc::testparts;

namespace {

constexpr double kPi = 3.14159265358979323846;

double area(const TopTools_IndexedMapOfShape& faces, int i) {
    GProp_GProps g;
    BRepGProp::SurfaceProperties(faces(i), g);
    return g.Mass();
}

void checkGenerated(const ImpellerSpec& spec) {
    const Impeller imp = makeImpeller(spec);
    ASSERT_TRUE(BRepCheck_Analyzer(imp.shape).IsValid());
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(imp.shape, TopAbs_FACE, faces);
    const ImpellerTruth& t = imp.truth;

    // Every face has one role.
    std::set<int> named;
    auto name = [&](int f) {
        ASSERT_GE(f, 1);
        ASSERT_LE(f, faces.Extent());
        EXPECT_TRUE(named.insert(f).second) << "face " << f << " named twice";
    };
    name(t.hub), name(t.bore), name(t.rim);
    for (int p : t.planes) name(p);
    const int perBlade = spec.filletRadius > 0 ? 9 : 5;
    const size_t blades = spec.bladeCount * (spec.splitters ? 2 : 1) - (spec.omitSplitter >= 0 ? 1 : 0);
    ASSERT_EQ(t.blades.size(), blades);
    for (const auto& b : t.blades) {
        name(b.pressure), name(b.suction), name(b.leading), name(b.trailing), name(b.shroud);
        for (int f : b.fillets) name(f);
        EXPECT_EQ(static_cast<int>(b.fillets.size()), perBlade - 5);
    }
    EXPECT_EQ(static_cast<int>(named.size()), faces.Extent());

    // The roles agree with the geometry.
    auto type = [&](int f) { return BRepAdaptor_Surface(TopoDS::Face(faces(f))).GetType(); };
    EXPECT_EQ(type(t.bore), GeomAbs_Cylinder);
    EXPECT_NEAR(BRepAdaptor_Surface(TopoDS::Face(faces(t.bore))).Cylinder().Radius(), spec.boreDiameter / 2, 1e-9);
    EXPECT_NEAR(BRepAdaptor_Surface(TopoDS::Face(faces(t.rim))).Cylinder().Radius(), spec.outerRadius, 1e-9);
    for (int p : t.planes) EXPECT_EQ(type(p), GeomAbs_Plane);
    // Copies of a blade have the same areas; main and splitter shrouds differ.
    const auto& main0 = t.blades[0];
    for (const auto& b : t.blades) {
        const auto& ref = b.splitter ? t.blades[1] : main0;
        EXPECT_NEAR(area(faces, b.shroud), area(faces, ref.shroud), 1e-3 * area(faces, ref.shroud));
        EXPECT_NEAR(area(faces, b.pressure), area(faces, ref.pressure), 1e-3 * area(faces, ref.pressure));
    }
    if (spec.splitters) {
        EXPECT_TRUE(t.blades[1].splitter);
        EXPECT_LT(area(faces, t.blades[1].shroud), 0.9 * area(faces, main0.shroud));
    }
    EXPECT_DOUBLE_EQ(t.bladeHeight, spec.bladeHeight);
    EXPECT_DOUBLE_EQ(t.boreDepth, spec.noseHeight);
    // The channel is narrower than the pitch at the outlet and wider than zero.
    const double pitchArc = 2 * kPi * spec.trailingRadius / blades;
    EXPECT_GT(t.minChannelWidth, 0.5);
    EXPECT_LT(t.minChannelWidth, pitchArc - spec.bladeThickness);

    const auto json = nlohmann::json::parse(truthToJson(t));
    EXPECT_EQ(json["blades"].size(), blades);
    EXPECT_EQ(json["hub"], t.hub);
}

}  // namespace

TEST(ImpellerGenerator, DefaultNineAndNine) { checkGenerated(ImpellerSpec{}); }

TEST(ImpellerGenerator, SevenBladesWithoutSplitters) {
    ImpellerSpec s;
    s.bladeCount = 7;
    s.splitters = false;
    s.wrapDeg = 12, s.leanDeg = 5, s.filletRadius = 1.5, s.bladeThickness = 2.5;
    checkGenerated(s);
}

TEST(ImpellerGenerator, UnfilletedAndDefective) {
    ImpellerSpec s;
    s.bladeCount = 5;
    s.filletRadius = 0;
    checkGenerated(s);
    s.filletRadius = 2;
    s.omitSplitter = 3;
    checkGenerated(s);
}

TEST(ImpellerGenerator, RefusesImpossibleSpecs) {
    using aeronc::test::inputErrorOf;
    ImpellerSpec s;
    s.leadingRadius = 21;  // the leading edge fillet would run off the hub
    EXPECT_NE(inputErrorOf([&] { makeImpeller(s); }).find("inside the hub"), std::string::npos);
    s = ImpellerSpec{};
    s.wrapDeg = 40;  // nine blade pairs wrapped this far leave no meridian for the hub's seam
    EXPECT_NE(inputErrorOf([&] { makeImpeller(s); }).find("seam"), std::string::npos);
    s = ImpellerSpec{};
    s.bladeCount = 2;
    EXPECT_NE(inputErrorOf([&] { makeImpeller(s); }).find("blade count"), std::string::npos);
    s = ImpellerSpec{};
    s.offPitchBlade = 1;
    s.offPitchDeg = 3;  // beyond an exporter's error: blades that really differ
    EXPECT_NE(inputErrorOf([&] { makeImpeller(s); }).find("off its pitch"), std::string::npos);
}
