// Tests of the integral-panel test-part generator (geometry and ground truth only).
#include <aeronc/core/Error.h>
#include <aeronc/testparts/PanelGenerator.h>

#include <BRepCheck_Analyzer.hxx>
#include <BRepClass3d_SolidClassifier.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <gp_Pnt.hxx>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace aeronc::testparts;

namespace {

constexpr double kPi = 3.14159265358979323846;

PanelSpec allOff() {
    PanelSpec s;
    s.lowerRibs = s.islands = s.openings = s.lighteningHoles = false;
    s.boltHoles = s.joggles = s.flange = s.bottomPockets = false;
    s.floorFillet = 0;
    return s;
}

int countSolids(const TopoDS_Shape& s) {
    TopTools_IndexedMapOfShape m;
    TopExp::MapShapes(s, TopAbs_SOLID, m);
    return m.Extent();
}

double volume(const TopoDS_Shape& s) {
    GProp_GProps g;
    BRepGProp::VolumeProperties(s, g);
    return g.Mass();
}

double panelLength(const PanelSpec& s) {
    return 2 * s.border + s.pocketsX * s.pitch - s.ribThickness;
}
double panelWidth(const PanelSpec& s) {
    return 2 * s.border + s.pocketsY * s.pitch - s.ribThickness;
}

std::map<std::string, int> countNotes(const Panel& p) {
    std::map<std::string, int> n;
    for (const auto& e : p.truth) ++n[e.note];
    return n;
}

// Every truth point is in empty space; for elements with a floor, a point just below the
// floor (along the setup direction) is material.
void checkTruthPoints(const Panel& p) {
    BRepClass3d_SolidClassifier classifier;
    classifier.Load(p.shape);
    auto classify = [&](double x, double y, double z) {
        classifier.Perform(gp_Pnt(x, y, z), 1e-6);
        return classifier.State();
    };
    for (const auto& e : p.truth) {
        SCOPED_TRACE("truth " + std::to_string(e.id) + " " + e.note);
        const auto& q = e.point;
        EXPECT_EQ(classify(q[0], q[1], q[2]), TopAbs_OUT);
        // The point is just above the level along the setup direction.
        const double h = e.setup == 0 ? q[2] : -q[2];
        EXPECT_NEAR(h - e.level, 0.5, 1e-9);
        if (e.through) continue;
        const double below = e.setup == 0 ? e.level - 0.5 : -(e.level - 0.5);
        EXPECT_EQ(classify(q[0], q[1], below), TopAbs_IN);
    }
}

// ids, parents and per-kind relations of the truth.
void checkTruthStructure(const Panel& p) {
    const int n = static_cast<int>(p.truth.size());
    std::map<int, int> children;
    for (int i = 0; i < n; ++i) {
        const auto& e = p.truth[i];
        SCOPED_TRACE("truth " + std::to_string(i) + " " + e.note);
        EXPECT_EQ(e.id, i);
        EXPECT_TRUE(e.type == "closed_pocket" || e.type == "open_pocket" ||
                    e.type == "opening" || e.type == "hole");
        EXPECT_TRUE(e.setup == 0 || e.setup == 1);
        ASSERT_GE(e.parent, -1);
        ASSERT_LT(e.parent, n);
        EXPECT_NE(e.parent, i);
        if (e.parent >= 0) {
            ++children[e.parent];
            EXPECT_EQ(p.truth[e.parent].setup, e.setup);
        }
        if (e.type == "opening" || (e.type == "hole" && e.through)) {
            EXPECT_EQ(e.setup, 0);
            EXPECT_DOUBLE_EQ(e.level, 0);
            EXPECT_TRUE(e.through);
        }
        if (e.note == "pocket") {
            EXPECT_EQ(e.type, "closed_pocket");
            if (e.parent >= 0) EXPECT_EQ(p.truth[e.parent].note, "lowered rib");
        } else if (e.note == "joggle" || e.note == "opening" || e.note == "lightening hole") {
            ASSERT_GE(e.parent, 0);
            EXPECT_EQ(p.truth[e.parent].note, "pocket");
        } else if (e.note == "bottom pocket") {
            EXPECT_EQ(e.setup, 1);
            EXPECT_EQ(e.parent, -1);
            EXPECT_LT(e.level, 0);
        } else if (e.note == "bolt hole") {
            EXPECT_NEAR(e.diameter, 6.6, 1e-9);
            if (e.parent >= 0) {
                EXPECT_EQ(p.truth[e.parent].note, "counterbore");
                EXPECT_NEAR(e.counterboreDiameter, 11, 1e-9);
            }
        } else if (e.note == "counterbore") {
            EXPECT_EQ(e.type, "hole");
            EXPECT_FALSE(e.through);
            EXPECT_NEAR(e.diameter, 11, 1e-9);
            EXPECT_EQ(e.parent, -1);
        } else if (e.note == "countersunk bolt hole") {
            EXPECT_NEAR(e.countersinkDiameter, 12, 1e-9);
            EXPECT_EQ(e.parent, -1);
        } else if (e.note == "flange") {
            EXPECT_EQ(e.type, "open_pocket");
            EXPECT_EQ(e.parent, -1);
        } else if (e.note == "lowered rib") {
            EXPECT_EQ(e.type, "closed_pocket");
        }
    }
    for (const auto& e : p.truth) {
        if (e.note == "lowered rib") EXPECT_EQ(children[e.id], 2);
        if (e.note == "counterbore") EXPECT_EQ(children[e.id], 1);
    }
}

// Expected counts of each note for a spec, from the documented pattern.
std::map<std::string, int> expectedNotes(const PanelSpec& s) {
    std::map<std::string, int> n;
    const int nx = s.pocketsX, ny = s.pocketsY;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            ++n["pocket"];
            const int k = (i + 3 * j) % 5;
            if (k == 2 && s.openings) ++n["opening"];
            if (k == 3 && s.lighteningHoles) ++n["lightening hole"];
            if (k == 4 && s.joggles) ++n["joggle"];
            if ((k == 0 || k == 1) && s.bottomPockets) ++n["bottom pocket"];
        }
    if (s.lowerRibs) n["lowered rib"] = ((ny + 1) / 2) * (nx / 2);
    if (s.flange) n["flange"] = 1;
    if (s.boltHoles) {
        const int holes = 2 + (nx - 1) + 2 * (ny - 1);
        const int cb = (holes + 1) / 3, csk = holes / 3;
        n["counterbore"] = cb;
        n["countersunk bolt hole"] = csk;
        n["bolt hole"] = holes - csk;  // plain ones and the through holes under counterbores
    }
    for (auto it = n.begin(); it != n.end();) it = it->second == 0 ? n.erase(it) : ++it;
    return n;
}

}  // namespace

TEST(PanelGenerator, SimplePanelHasHandComputedVolume) {
    PanelSpec s = allOff();
    Panel p = makePanel(s);
    ASSERT_FALSE(p.shape.IsNull());
    EXPECT_TRUE(BRepCheck_Analyzer(p.shape).IsValid());
    EXPECT_EQ(countSolids(p.shape), 1);

    const double L = panelLength(s), W = panelWidth(s);
    EXPECT_DOUBLE_EQ(L, 200);
    EXPECT_DOUBLE_EQ(W, 140);
    const double pw = s.pitch - s.ribThickness, r = s.cornerRadius;
    const double pocketArea = pw * pw - (4 - kPi) * r * r;
    const double expected =
        L * W * s.thickness - s.pocketsX * s.pocketsY * pocketArea * (s.thickness - s.webZ);
    EXPECT_NEAR(volume(p.shape), expected, 1e-6 * expected);

    ASSERT_EQ(p.truth.size(), 6u);
    for (const auto& e : p.truth) {
        EXPECT_EQ(e.type, "closed_pocket");
        EXPECT_EQ(e.setup, 0);
        EXPECT_DOUBLE_EQ(e.level, s.webZ);
        EXPECT_EQ(e.parent, -1);
        EXPECT_EQ(e.islands, 0);
    }
    checkTruthPoints(p);
    checkTruthStructure(p);
}

TEST(PanelGenerator, BoltAndLighteningHolesHaveHandComputedVolume) {
    PanelSpec s = allOff();
    s.boltHoles = true;
    s.lighteningHoles = true;
    Panel p = makePanel(s);
    EXPECT_TRUE(BRepCheck_Analyzer(p.shape).IsValid());
    EXPECT_EQ(countSolids(p.shape), 1);

    const double T = s.thickness;
    const double pw = s.pitch - s.ribThickness, r = s.cornerRadius;
    double expected = panelLength(s) * panelWidth(s) * T -
                      s.pocketsX * s.pocketsY * (pw * pw - (4 - kPi) * r * r) * (T - s.webZ);
    auto disk = [](double d) { return kPi * d * d / 4; };
    for (const auto& e : p.truth) {
        if (e.note == "lightening hole") {
            expected -= disk(e.diameter) * s.webZ;
        } else if (e.note == "counterbore") {
            expected -= disk(e.diameter) * (T - e.level);
        } else if (e.note == "bolt hole" && e.parent >= 0) {
            expected -= disk(e.diameter) * p.truth[e.parent].level;
        } else if (e.note == "bolt hole") {
            expected -= disk(e.diameter) * T;
        } else if (e.note == "countersunk bolt hole") {
            const double r1 = e.diameter / 2, r2 = e.countersinkDiameter / 2, h = r2 - r1;
            expected -= disk(e.diameter) * (T - h) + kPi * h / 3 * (r1 * r1 + r1 * r2 + r2 * r2);
        }
    }
    EXPECT_NEAR(volume(p.shape), expected, 1e-6 * expected);
    checkTruthPoints(p);
    checkTruthStructure(p);
}

// The widest lightening hole in a thin floor of a pocket with corner radii near half its width.
TEST(PanelGenerator, WideLighteningHoleInThinFloor) {
    PanelSpec s = allOff();
    s.pocketsX = 1, s.pocketsY = 2;  // the second cell holds the hole
    s.lighteningHoles = true;
    s.webZ = 1;
    const double pw = s.pitch - s.ribThickness;
    s.cornerRadius = 0.5 * pw - 0.25;
    s.lighteningDiameter = pw - s.cornerRadius;
    Panel p = makePanel(s);
    EXPECT_TRUE(BRepCheck_Analyzer(p.shape).IsValid());
    const double r = s.cornerRadius, D = s.lighteningDiameter;
    const double expected = panelLength(s) * panelWidth(s) * s.thickness -
                            2 * (pw * pw - (4 - kPi) * r * r) * (s.thickness - s.webZ) - kPi * D * D / 4 * s.webZ;
    EXPECT_NEAR(volume(p.shape), expected, 1e-6 * expected);
    checkTruthPoints(p);
    checkTruthStructure(p);
}

TEST(PanelGenerator, DefaultPanelHasEveryFeatureOnce) {
    PanelSpec s;
    Panel p = makePanel(s);
    ASSERT_FALSE(p.shape.IsNull());
    EXPECT_TRUE(BRepCheck_Analyzer(p.shape).IsValid());
    EXPECT_EQ(countSolids(p.shape), 1);

    const auto notes = countNotes(p);
    EXPECT_EQ(notes, expectedNotes(s));
    EXPECT_EQ(notes.at("pocket"), 6);
    for (const char* kind : {"opening", "lightening hole", "joggle", "bottom pocket",
                             "lowered rib", "flange", "counterbore", "countersunk bolt hole"})
        EXPECT_GE(notes.count(kind) ? notes.at(kind) : 0, 1) << kind;
    int islands = 0, bottomSetup = 0, open = 0, openings = 0;
    for (const auto& e : p.truth) {
        if (e.note == "pocket") islands += e.islands;
        bottomSetup += e.setup == 1;
        open += e.type == "open_pocket";
        openings += e.type == "opening";
    }
    EXPECT_EQ(islands, 1);
    EXPECT_EQ(bottomSetup, 3);
    EXPECT_EQ(open, 1);
    EXPECT_EQ(openings, 1);
    checkTruthPoints(p);
    checkTruthStructure(p);

    // All features together remove more than the plain pockets alone.
    EXPECT_LT(volume(p.shape), volume(makePanel(allOff()).shape));
}

TEST(PanelGenerator, FloorFilletsKeepThePanelValid) {
    PanelSpec s;
    s.floorFillet = 3;
    Panel p = makePanel(s);
    EXPECT_TRUE(BRepCheck_Analyzer(p.shape).IsValid());
    EXPECT_EQ(countSolids(p.shape), 1);
    EXPECT_EQ(countNotes(p), expectedNotes(s));
    checkTruthPoints(p);
    checkTruthStructure(p);

    // Floor fillets leave material in the pocket edges.
    PanelSpec plain = allOff(), filleted = allOff();
    filleted.floorFillet = 3;
    EXPECT_GT(volume(makePanel(filleted).shape), volume(makePanel(plain).shape) + 1);
}

TEST(PanelGenerator, LargerGridFollowsThePattern) {
    PanelSpec s;
    s.pocketsX = 7;
    s.pocketsY = 5;
    s.floorFillet = 2;
    Panel p = makePanel(s);
    EXPECT_TRUE(BRepCheck_Analyzer(p.shape).IsValid());
    EXPECT_EQ(countSolids(p.shape), 1);
    const auto notes = countNotes(p);
    EXPECT_EQ(notes, expectedNotes(s));
    EXPECT_EQ(notes.at("pocket"), 35);
    EXPECT_EQ(notes.at("lowered rib"), 9);
    checkTruthPoints(p);
    checkTruthStructure(p);
}

TEST(PanelGenerator, VariedSpecsStayValid) {
    std::vector<PanelSpec> specs(5);
    specs[0].floorFillet = 5.5;  // just under the corner radius
    specs[1].pitch = 40;         // small pockets
    specs[1].cornerRadius = 4;
    specs[1].floorFillet = 2;
    specs[2].border = 20;        // wide frame, thick panel, deep pockets underneath
    specs[2].thickness = 30;
    specs[2].webZ = 12;
    specs[2].bottomDepth = 10;
    specs[2].lowerRibBy = 8;
    specs[3].pocketsX = 5;       // wide ribs, sharp corners
    specs[3].pocketsY = 3;
    specs[3].ribThickness = 8;
    specs[3].cornerRadius = 0;
    specs[4].pocketsX = 1;       // single pocket
    specs[4].pocketsY = 1;
    for (size_t i = 0; i < specs.size(); ++i) {
        SCOPED_TRACE("spec " + std::to_string(i));
        Panel p = makePanel(specs[i]);
        EXPECT_TRUE(BRepCheck_Analyzer(p.shape).IsValid());
        EXPECT_EQ(countSolids(p.shape), 1);
        EXPECT_EQ(countNotes(p), expectedNotes(specs[i]));
        checkTruthPoints(p);
        checkTruthStructure(p);
    }
}

TEST(PanelGenerator, OptionsTurnFeaturesOff) {
    PanelSpec s;
    s.islands = s.openings = s.joggles = false;
    Panel p = makePanel(s);
    EXPECT_EQ(countSolids(p.shape), 1);
    const auto notes = countNotes(p);
    EXPECT_EQ(notes, expectedNotes(s));
    EXPECT_EQ(notes.count("opening"), 0u);
    EXPECT_EQ(notes.count("joggle"), 0u);
    for (const auto& e : p.truth) EXPECT_EQ(e.islands, 0);
    checkTruthPoints(p);
}

TEST(PanelGenerator, RejectsImpossibleSpecs) {
    std::vector<PanelSpec> bad(6);
    bad[0].floorFillet = bad[0].cornerRadius;  // floor fillet must be under the corner radius
    bad[1].bottomDepth = bad[1].webZ - 0.5;    // web under the pockets would be 0.5 mm
    bad[2].pocketsX = 0;
    bad[3].webZ = bad[3].thickness;
    bad[4].lighteningDiameter = bad[4].pitch - bad[4].ribThickness - bad[4].cornerRadius + 0.1;  // wider than the floor
    bad[5].cornerRadius = 0.5 * (bad[5].pitch - bad[5].ribThickness);  // a round pocket: no corner left
    for (const auto& s : bad) {
        try {
            makePanel(s);
            ADD_FAILURE() << "no error";
        } catch (const aeronc::Error& e) {
            EXPECT_EQ(e.kind(), aeronc::Error::Kind::Input) << e.what();
        }
    }
}

TEST(PanelGenerator, TruthJsonRoundTrips) {
    Panel p = makePanel(PanelSpec{});
    const auto j = nlohmann::json::parse(truthToJson(p));
    ASSERT_TRUE(j.contains("elements"));
    ASSERT_EQ(j["elements"].size(), p.truth.size());
    for (size_t i = 0; i < p.truth.size(); ++i) {
        const auto& e = p.truth[i];
        const auto& o = j["elements"][i];
        EXPECT_EQ(o["id"].get<int>(), e.id);
        EXPECT_EQ(o["type"].get<std::string>(), e.type);
        EXPECT_EQ(o["setup"].get<int>(), e.setup);
        EXPECT_EQ(o["parent"].get<int>(), e.parent);
        EXPECT_EQ(o["note"].get<std::string>(), e.note);
        EXPECT_DOUBLE_EQ(o["level"].get<double>(), e.level);
        EXPECT_EQ(o["through"].get<bool>(), e.through);
        ASSERT_EQ(o["point"].size(), 3u);
        for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(o["point"][k].get<double>(), e.point[k]);
        for (const auto& c : o["children"]) EXPECT_EQ(p.truth[c.get<int>()].parent, e.id);
    }
}
