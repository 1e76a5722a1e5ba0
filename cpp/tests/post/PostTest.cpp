// The posts end to end: FreeCAD-style Path text with tool axes -> NC text -> independent
// readback -> forward kinematics -> the input tip and axis again (1e-6 mm, 1e-9 rad).
#include "kinematics/Fixtures.h"
#include "NcReadback.h"
#include "ErrorOf.h"

#include <aeronc/post/Post.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <regex>

using namespace aeronc::kinematics;
using namespace aeronc::kinematics::test;
using namespace aeronc::post;

namespace {

struct InputPose {
    Vec3 tip, axis;
};

// FreeCAD Path text of one operation, and the poses it asks for, read back the way the post
// reads them (FreeCAD's F is mm/s).
class PathText {
public:
    static double exact(double v) {
        char b[64];
        std::snprintf(b, sizeof b, "%.15g", v);
        return std::strtod(b, nullptr);
    }
    static std::string n(double v) {
        char b[64];
        std::snprintf(b, sizeof b, "%.15g", v);
        return b;
    }
    void move(const char* g, const Vec3& tip, const Vec3& axis, double feedPerSecond = 20) {
        std::string l = g;
        if (std::string(g) != "G0") l += " F" + n(feedPerSecond);
        l += " U" + n(axis.x()) + " V" + n(axis.y()) + " W" + n(axis.z());
        l += " X" + n(tip.x()) + " Y" + n(tip.y()) + " Z" + n(tip.z());
        text += l + "\n";
        record(tip, axis);
    }
    void record(const Vec3& tip, const Vec3& axis) {
        poses.push_back({Vec3(exact(tip.x()), exact(tip.y()), exact(tip.z())),
                         Vec3(exact(axis.x()), exact(axis.y()), exact(axis.z())).normalized()});
    }
    void line(const std::string& l) { text += l + "\n"; }
    std::string text;
    std::vector<InputPose> poses;
};

std::vector<PathSection> job(const std::string& gcode, double toolLength = 120) {
    PathSection tc;
    tc.kind = PathSection::Kind::ToolChange;
    tc.label = "TC: 10 mm end mill";
    tc.tool.number = 3;
    tc.tool.name = "EM10";
    tc.tool.diameter = 10;
    tc.tool.length = toolLength;
    tc.rpm = 12000;
    tc.spindleDir = 1;
    PathSection op;
    op.label = "Op";
    op.gcode = gcode;
    op.coolant = "flood";
    PathSection fixture;
    fixture.kind = PathSection::Kind::WorkOffset;
    fixture.label = "G54";
    fixture.gcode = "G54\nG0 Z80.000000\n";
    return {fixture, tc, op};
}

NcOptions exactOptions(Dialect d, bool vectors = false) {
    NcOptions o;
    o.dialect = d;
    o.vectors = vectors;
    o.precision = 9;
    o.anglePrecision = 10;
    o.vectorPrecision = 13;
    o.programName = "TEST";
    return o;
}

std::vector<readback::Pose> readBack(const std::string& nc, const MachineModel& m, const NcOptions& o, double toolLength = 120) {
    MachineSetup setup;
    setup.toolLength = toolLength;
    const Kinematics kin(m, setup);
    return o.dialect == Dialect::LinuxCnc ? readback::readLinuxCnc(nc, kin) : readback::readSinumerik(nc, kin, o.vectors);
}

// Every input pose appears in order among the full read-back poses; the others are moves the
// post added (retract / reposition, arc points, drilling approaches), at most `extras` of them.
void expectRoundTrip(const std::vector<InputPose>& in, const std::vector<readback::Pose>& out, size_t extras,
                     readback::Kind lastKind = readback::Kind::Feed) {
    std::vector<const readback::Pose*> full;
    for (const auto& p : out)
        if (p.full) full.push_back(&p);
    size_t j = 0, skipped = 0;
    for (size_t i = 0; i < in.size(); ++i) {
        while (j < full.size() && !((full[j]->tip - in[i].tip).norm() < 1e-6 && angleBetween(full[j]->axis, in[i].axis) < 1e-9))
            ++j, ++skipped;
        ASSERT_LT(j, full.size()) << "input pose " << i << " (" << in[i].tip.transpose() << " / " << in[i].axis.transpose()
                                  << ") not found in the posted program";
        ++j;
    }
    skipped += full.size() - j;
    EXPECT_LE(skipped, extras);
    (void)lastKind;
}

std::string post(const std::vector<PathSection>& sections, const std::string& machineName, const NcOptions& o,
                 PostSummary* summary = nullptr) {
    PostSummary s = postFreeCad(sections, machine(machineName), o, {});
    if (summary) *summary = s;
    return s.text;
}

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

}  // namespace

TEST(Post, RandomSimultaneousPosesRoundTripInEveryDialect) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-60, 60), az(-180, 180);
    for (const auto& [name, maxTilt] : {std::pair<std::string, double>{"AC-5AX", 110}, {"AC-HEAD", 95}}) {
        std::uniform_real_distribution<double> tilt(0, maxTilt);
        PathText p;
        for (int i = 0; i < 400; ++i) p.move(i % 10 == 0 ? "G0" : "G1", {coord(rng), coord(rng), coord(rng)}, axisAt(tilt(rng), az(rng)));
        for (int variant = 0; variant < 3; ++variant) {
            if (name == "AC-HEAD" && variant == 2) continue;  // LinuxCNC: table-table only
            const NcOptions o = variant == 2 ? exactOptions(Dialect::LinuxCnc) : exactOptions(Dialect::Sinumerik840D, variant == 1);
            PostSummary s;
            const std::string nc = post(job(p.text), name, o, &s);
            SCOPED_TRACE(name + " variant " + std::to_string(variant));
            expectRoundTrip(p.poses, readBack(nc, machine(name), o), 2 * s.branchChanges);
            if (o.dialect == Dialect::Sinumerik840D) {
                EXPECT_EQ(count(nc, "\nTRAORI\n"), 1);
                EXPECT_EQ(count(nc, "\nM30"), 1);
                EXPECT_EQ(nc.rfind("%_N_TEST_MPF", 0), 0u);
            }
        }
    }
}

TEST(Post, APathThroughThePoleKeepsC) {
    PathText p;
    // The tool axis swings through vertical along one great circle: -40 .. +40 degrees.
    for (int k = -40; k <= 40; k += 2) p.move("G1", {k * 1.0, 5, 10}, k < 0 ? axisAt(-k, 180 + 30) : axisAt(k, 30));
    for (Dialect d : {Dialect::LinuxCnc, Dialect::Sinumerik840D}) {
        const NcOptions o = exactOptions(d);
        PostSummary s;
        const std::string nc = post(job(p.text), "AC-5AX", o, &s);
        EXPECT_EQ(s.branchChanges, 0);
        const auto back = readBack(nc, machine("AC-5AX"), o);
        expectRoundTrip(p.poses, back, 0);
        if (d == Dialect::LinuxCnc) {
            double c0 = 0, aPrev = 0;
            bool first = true;
            for (const auto& b : back) {
                if (!b.full || b.kind != readback::Kind::Feed) continue;
                if (first) c0 = b.c, aPrev = b.a, first = false;
                EXPECT_NEAR(b.c, c0, 1e-9) << "C moved at NC line " << b.line;
                EXPECT_LE(std::abs(b.a - aPrev), 2.0 + 1e-6);  // A passes through zero, no flip
                aPrev = b.a;
            }
        }
    }
}

TEST(Post, CircingThePartUnwindsCWithRetractAndReentry) {
    PathText p;
    // Three turns around the part at a 35 degree tilt: C must unwind within +-360.
    for (int k = 0; k <= 3 * 72; ++k) {
        const double az = 5.0 * k;
        p.move("G1", {40 * std::cos(toRadians(az)), 40 * std::sin(toRadians(az)), -5}, axisAt(35, az));
    }
    const NcOptions o = exactOptions(Dialect::LinuxCnc);
    PostSummary s;
    const std::string nc = post(job(p.text), "AC-5AX", o, &s);
    EXPECT_GE(s.branchChanges, 1);
    const auto back = readBack(nc, machine("AC-5AX"), o);
    expectRoundTrip(p.poses, back, 2 * s.branchChanges);
    for (const auto& b : back) {
        EXPECT_LE(std::abs(b.c), 360 + 1e-9);
        EXPECT_LE(std::abs(b.a), 120 + 1e-9);
    }
    // Each branch change: a rapid up the old axis by the retract distance, a rapid to above the
    // next point along the new axis, then the feed back in.
    int seen = 0;
    for (size_t i = 2; i < back.size(); ++i) {
        if (back[i - 2].kind != readback::Kind::Rapid || back[i - 1].kind != readback::Kind::Rapid || back[i].kind != readback::Kind::Feed)
            continue;
        if (i < 3) continue;
        const auto& before = back[i - 3];
        EXPECT_LT((back[i - 2].tip - (before.tip + 50 * before.axis)).norm(), 1e-6);
        EXPECT_LT((back[i - 1].tip - (back[i].tip + 50 * back[i].axis)).norm(), 1e-6);
        EXPECT_LT(angleBetween(back[i - 1].axis, back[i].axis), 1e-9);
        ++seen;
    }
    EXPECT_EQ(seen, s.branchChanges);
}

TEST(Post, IndexedPlaneWithArcs) {
    // A 3+2 pocket contour on a face tilted 30 degrees: lines and arcs in that plane.
    const Vec3 u = axisAt(30, 60);
    const Vec3 e1 = u.cross(Vec3::UnitZ()).normalized(), e2 = u.cross(e1);
    auto at = [&](double a, double b, double h) { return Vec3(Vec3(5, -3, 2) + a * e1 + b * e2 + h * u); };
    PathText p;
    p.move("G0", at(0, -20, 10), u);
    p.move("G1", at(0, -20, 0), u);
    p.move("G1", at(20, -20, 0), u);
    // Quarter arc counter-clockwise about (20, 0) in the plane: G3 with the centre offset as I J K.
    const Vec3 start = at(20, -20, 0), end = at(40, 0, -1), centre = at(20, 0, 0);
    const Vec3 off = centre - start;
    // (20,-20) -> (40,0) about (20,0) turns counter-clockwise seen from the spindle when
    // e1 x e2 = +u.
    ASSERT_GT(e1.cross(e2).dot(u), 0.0);
    p.line("G3 F10 I" + PathText::n(off.x()) + " J" + PathText::n(off.y()) + " K" + PathText::n(off.z()) +
           " X" + PathText::n(end.x()) + " Y" + PathText::n(end.y()) + " Z" + PathText::n(end.z()));
    p.record(end, u);
    p.move("G1", at(40, 20, -1), u);
    p.move("G0", at(40, 20, 30), u);
    for (Dialect d : {Dialect::Sinumerik840D, Dialect::LinuxCnc}) {
        const NcOptions o = exactOptions(d);
        const std::string nc = post(job(p.text), "AC-5AX", o);
        EXPECT_EQ(count(nc, "\nTRAORI\n"), 0);
        EXPECT_EQ(count(nc, "G3"), 1) << nc;
        // The work offset's clearance move runs in the zero plane, the contour in the tilted one.
        if (d == Dialect::Sinumerik840D) EXPECT_EQ(count(nc, "CYCLE800(1,"), 2);
        expectRoundTrip(p.poses, readBack(nc, machine("AC-5AX"), o), 0);
    }
}

TEST(Post, The840DHeaderListsEachToolOnceByNumber) {
    // Tools come back in the change order (T3, T5, T3 again): the header is the magazine list.
    const std::string gcode = "(Op)\nG0 Z15.000000\nG1 F5.000000 X10.000000 Y0.000000 Z-2.000000\nG0 Z15.000000\n";
    std::vector<PathSection> sections = job(gcode);
    std::vector<PathSection> again = job(gcode);
    again[1].tool.number = 5;
    again[1].tool.name = "EM6";
    again[1].tool.diameter = 6;
    sections.insert(sections.end(), again.begin() + 1, again.end());
    std::vector<PathSection> third = job(gcode);
    sections.insert(sections.end(), third.begin() + 1, third.end());
    NcOptions o = exactOptions(Dialect::Sinumerik840D);
    o.comments = true;
    const std::string nc = post(sections, "AC-5AX", o);
    EXPECT_EQ(count(nc, "; T3 EM10  diameter 10.000\n"), 1) << nc;
    EXPECT_EQ(count(nc, "; T5 EM6  diameter 6.000\n"), 1) << nc;
    EXPECT_LT(nc.find("; T3 EM10"), nc.find("; T5 EM6"));
    EXPECT_EQ(count(nc, "T3 D1 M6"), 2) << nc;  // the changes themselves stay
}

TEST(Post, FreeCadThreeAxisOperationPostsAsAPlainPlane) {
    // FreeCAD's own operations carry no tool axis: the post keeps them 3-axis.
    const std::string gcode =
        "(Profile)\nG0 Z15.000000\nG0 X10.000000 Y0.000000\nG1 F5.000000 Z-2.000000\n"
        "G2 F5.000000 I-10.000000 J0.000000 X-10.000000 Y0.000000 Z-2.000000\nG1 X-10.000000 Y-5.000000\nG0 Z15.000000\n";
    for (Dialect d : {Dialect::Sinumerik840D, Dialect::LinuxCnc}) {
        NcOptions o = exactOptions(d);
        o.precision = 3;
        const std::string nc = post(job(gcode), "AC-5AX", o);
        EXPECT_EQ(count(nc, "\nTRAORI\n"), 0);
        EXPECT_NE(nc.find("G2 X-10 I-10 J0\n"), std::string::npos) << nc;
        if (d == Dialect::Sinumerik840D) {
            EXPECT_NE(nc.find("CYCLE800(1,\"TC1\",0,57,0,0,0,0,0,0,0,0,0,1,100,1)"), std::string::npos) << nc;
            EXPECT_NE(nc.find("T3 D1 M6"), std::string::npos);
            EXPECT_NE(nc.find("S12000 M3"), std::string::npos);
            EXPECT_NE(nc.find("M8"), std::string::npos);
        } else {
            EXPECT_NE(nc.find("G0 Z15 A0 C0"), std::string::npos) << nc;
        }
    }
}

TEST(Post, DrillingNormalToASurface) {
    // Holes on a curved surface, each along its own normal, with G0 moves between them.
    PathText p;
    std::vector<InputPose> bottoms;
    p.line("G99");
    for (int h = 0; h < 6; ++h) {
        const Vec3 u = axisAt(10.0 * h, 40.0 * h);
        const Vec3 bottom = Vec3(10.0 * h - 25, 3.0 * h, -1.0 * h) - 8 * u;
        p.move("G0", bottom + 30 * u, u);
        const char* g = h % 2 ? "G83" : "G81";
        p.line(std::string(g) + " F2 U" + PathText::n(u.x()) + " V" + PathText::n(u.y()) + " W" + PathText::n(u.z()) +
               " X" + PathText::n(bottom.x()) + " Y" + PathText::n(bottom.y()) + " Z" + PathText::n(bottom.z()) +
               " R" + PathText::n(bottom.z() + 10) + (h % 2 ? " Q3" : ""));
        p.record(bottom, u);
    }
    p.line("G80");
    for (Dialect d : {Dialect::Sinumerik840D, Dialect::LinuxCnc}) {
        const NcOptions o = exactOptions(d);
        const std::string nc = post(job(p.text), "AC-5AX", o);
        const auto back = readBack(nc, machine("AC-5AX"), o);
        int holes = 0;
        for (const auto& b : back) holes += b.kind == readback::Kind::HoleBottom;
        EXPECT_EQ(holes, 6);
        // G99 returns to R: each hole's approach is its R point, 10 along the axis (one added move each).
        expectRoundTrip(p.poses, back, 6);
        if (d == Dialect::Sinumerik840D) {
            EXPECT_EQ(count(nc, "CYCLE81("), 3);
            EXPECT_EQ(count(nc, "CYCLE83("), 3);
            EXPECT_EQ(count(nc, "CYCLE800(1,"), 1 + 6);  // the work offset's zero plane, then one per hole axis
            EXPECT_EQ(count(nc, "\nTRAORI\n"), 0);
        } else {
            EXPECT_EQ(count(nc, "G81"), 3);
            EXPECT_EQ(count(nc, "G83"), 3);
        }
    }
}

TEST(Post, ArcsInASimultaneousOperationAreLinearisedFor840D) {
    PathText p;
    p.move("G1", {10, 0, 0}, Vec3::UnitZ());
    p.line("G3 F10 I-10 J0 X0 Y10 Z0");  // quarter circle, vertical axis
    p.record({0, 10, 0}, Vec3::UnitZ());
    p.move("G1", {0, 20, 0}, axisAt(20, 90));  // then the axis tilts while cutting
    const NcOptions o = exactOptions(Dialect::Sinumerik840D);
    const std::string nc = post(job(p.text), "AC-5AX", o);
    EXPECT_EQ(count(nc, "\nTRAORI\n"), 1);
    EXPECT_EQ(count(nc, "G3"), 0);
    const auto back = readBack(nc, machine("AC-5AX"), o);
    // Arc points lie on the circle within the chord tolerance.
    size_t onCircle = 0;
    for (const auto& b : back)
        if (b.full && std::abs(b.tip.z()) < 1e-9 && b.tip.x() > 1e-9 && b.tip.y() > 1e-9) {
            EXPECT_NEAR(b.tip.head<2>().norm(), 10, 1e-9);
            ++onCircle;
        }
    EXPECT_GE(onCircle, 10u);  // 0.001 mm chord on r=10 needs ~18 pieces per quarter
    expectRoundTrip(p.poses, back, onCircle);
}

TEST(Post, AptRoundTripPostsTheSameProgram) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coord(-50, 50), az(-180, 180), tilt(0, 90);
    PathText p;
    for (int i = 0; i < 100; ++i) p.move(i % 7 ? "G1" : "G0", {coord(rng), coord(rng), coord(rng)}, axisAt(tilt(rng), az(rng)));
    p.line("G81 F2 U0 V0 W1 X1 Y2 Z-3 R2");
    p.line("G3 F10 I-1 J0 X0 Y3 Z2");  // leaves the hole's return point on a vertical arc
    const auto sections = job(p.text);
    const ClProgram direct = readFreeCadPath(sections, "APT");
    const std::string apt = writeApt(direct);
    EXPECT_NE(apt.find("GOTO/"), std::string::npos);
    EXPECT_NE(apt.find("CYCLE/DRILL,FEDTO,5,RAPTO,0,RTRCTO,"), std::string::npos) << apt;
    EXPECT_NE(apt.find("CIRCLE/"), std::string::npos);
    const ClProgram back = readApt(apt);
    std::vector<const ClRecord*> a, b;
    for (const auto& r : direct.records)
        if ((r.kind == ClKind::Move && r.tipKnown()) || r.kind == ClKind::Cycle) a.push_back(&r);
    for (const auto& r : back.records)
        if (r.kind == ClKind::Move || r.kind == ClKind::Cycle) b.push_back(&r);
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i]->kind, b[i]->kind);
        EXPECT_EQ(a[i]->motion, b[i]->motion);
        EXPECT_LT((a[i]->tip - b[i]->tip).norm(), 1e-9);
        EXPECT_LT(angleBetween(a[i]->axis, b[i]->axis), 1e-9);
        EXPECT_NEAR(a[i]->feed, b[i]->feed, 1e-4);
    }
    for (Dialect d : {Dialect::Sinumerik840D, Dialect::LinuxCnc}) {
        const NcOptions o = exactOptions(d);
        const std::string viaApt = postApt(apt, machine("AC-5AX"), o, {}).text;
        expectRoundTrip(p.poses, readBack(viaApt, machine("AC-5AX"), o), 2 * 100 + 4);
    }
}

TEST(Post, InverseTimeFeedsMatchTheTipPath) {
    PathText p;
    p.move("G1", {0, 0, 0}, Vec3::UnitZ(), 10);
    for (int k = 1; k <= 10; ++k) p.move("G1", {3.0 * k, 0, 0}, axisAt(3.0 * k, 90), 10);  // 600 mm/min
    NcOptions o = exactOptions(Dialect::LinuxCnc);
    o.inverseTime = true;
    const std::string nc = post(job(p.text), "AC-5AX", o);
    const auto back = readBack(nc, machine("AC-5AX"), o);
    int checked = 0;
    for (size_t i = 1; i < back.size(); ++i) {
        if (back[i].inverseTimeF == 0) continue;
        const double minutes = (back[i].tip - back[i - 1].tip).norm() / 600.0;  // 3 mm at 600 mm/min
        EXPECT_NEAR(back[i].inverseTimeF, 1.0 / minutes, 1e-3);
        ++checked;
    }
    EXPECT_EQ(checked, 10);
}

TEST(Post, BadInputIsAClearErrorNamingTheOperationAndMove) {
    struct Case {
        std::string gcode;
        std::string machine;
        Dialect dialect;
        std::string expect;
    };
    const std::vector<Case> cases = {
        {"G0 X0 Y0 Z10\nG1 F5 Xnan Y0 Z0\n", "AC-5AX", Dialect::Sinumerik840D, "operation 'Op', move 2 (G1 F5 Xnan Y0 Z0): parameter X is not a finite number"},
        {"G0 X0 Y0 Z10\nG1 F5 X1 Y0 Z0 U0 V0\n", "AC-5AX", Dialect::Sinumerik840D, "operation 'Op', move 2 (G1 F5 X1 Y0 Z0 U0 V0): a tool axis needs all of U, V and W"},
        {"G0 X0 Y0 Z10\nG1 F5 X1 Y0 Z0 U0 V0.5 W0.5\n", "AC-5AX", Dialect::Sinumerik840D, "move 2 (G1 F5 X1 Y0 Z0 U0 V0.5 W0.5): the tool axis (U, V, W) has length 0.707"},
        {"G0 X0 Y0 Z10\nG1 F5 X1 Y0 Z0 U0 V0 W-1\n", "AC-5AX", Dialect::Sinumerik840D, "operation 'Op', move 2 (G1 to (1.000, 0.000, 0.000), tool axis (0.0000, 0.0000, -1.0000)): tool axis (0.000, 0.000, -1.000) is out of reach of machine AC-5AX"},
        {"G0 X0 Y0 Z10\nG1 F5 X1 Y0 Z0 U0 V-0.8191520 W-0.5735764\n", "AC-5AX", Dialect::LinuxCnc, "A outside [-120.000, 120.000]"},
        {"G0 X0 Y0 Z10\nG5.1 X1\n", "AC-5AX", Dialect::Sinumerik840D, "operation 'Op', move 2 (G5.1 X1): unsupported command"},
        {"G91\n", "AC-5AX", Dialect::Sinumerik840D, "incremental moves (G91) are not supported"},
        {"G0 X0 Y0 Z0\nG2 F5 I1 J0 K1 X2 Y0 Z0\n", "AC-5AX", Dialect::Sinumerik840D, "not in the plane normal to the tool axis"},
        {"G0 X0 Y0 Z10\nG1 F5 X900 Y0 Z0\n", "AC-5AX", Dialect::LinuxCnc, "X=900.000 is beyond the travel [-325.000, 325.000]"},
        {"G0 X0 Y0 Z10\n", "AC-HEAD", Dialect::LinuxCnc, "the LinuxCNC dialect is for table-table machines"},
        {"G0 X0 Y0 Z10\nG1 X1 Y1 Z1\n", "AC-5AX", Dialect::Sinumerik840D, "feed move without a feed rate"},
    };
    for (const auto& c : cases) {
        try {
            post(job(c.gcode), c.machine, exactOptions(c.dialect));
            ADD_FAILURE() << "no error for " << c.gcode;
        } catch (const aeronc::Error& e) {
            EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << e.what();
        }
    }
    // The travel is the machine's: a part zero 600 mm off the table's centre brings X 900 into
    // it and takes X 0 out of it.
    {
        PlanOptions shifted;
        shifted.partZero = Vec3(-600, 0, 0);
        const auto far = job("G0 X900 Y0 Z10\nG1 F5 X899 Y0 Z0\n");
        EXPECT_NO_THROW(postFreeCad(far, machine("AC-5AX"), exactOptions(Dialect::LinuxCnc), shifted));
        const std::string e = aeronc::test::inputErrorOf([&] {
            postFreeCad(job("G0 X0 Y0 Z10\nG1 F5 X1 Y0 Z0\n"), machine("AC-5AX"), exactOptions(Dialect::LinuxCnc), shifted);
        });
        EXPECT_NE(e.find("X=-600.000 is beyond the travel [-325.000, 325.000]"), std::string::npos) << e;
    }
    // An operation without a tool controller, and a work offset the 840D reads differently.
    auto sections = job("G0 X0 Y0 Z10\n");
    sections[2].hasToolController = false;
    EXPECT_THROW(
        {
            try {
                post(sections, "AC-5AX", exactOptions(Dialect::Sinumerik840D));
            } catch (const aeronc::Error& e) {
                EXPECT_NE(std::string(e.what()).find("operation 'Op', move 1: the operation has no tool controller"), std::string::npos)
                    << e.what();
                throw;
            }
        },
        aeronc::Error);
    sections = job("G0 X0 Y0 Z10\n");
    sections[0].gcode = "G58\n";
    EXPECT_THROW(post(sections, "AC-5AX", exactOptions(Dialect::Sinumerik840D)), aeronc::Error);
    EXPECT_NO_THROW(post(sections, "AC-5AX", exactOptions(Dialect::LinuxCnc)));
}

TEST(Post, AptBadInputNamesTheLine) {
    auto err = [](const std::string& apt) {
        try {
            postApt(apt, machine("AC-5AX"), exactOptions(Dialect::Sinumerik840D), {});
        } catch (const aeronc::Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(err("UNITS/MM\nGOTO/1,2,3\n").find("APT line 2: motion before any LOADTL"), std::string::npos);
    EXPECT_NE(err("LOADTL/1\nFEDRAT/100,IPM\n").find("APT line 2: feed unit IPM"), std::string::npos);
    EXPECT_NE(err("LOADTL/1\nRAPID\nGOTO/1,2,nan,0,0,1\n").find("APT line 3"), std::string::npos);
    EXPECT_NE(err("LOADTL/1\nWHATEVER/1\n").find("APT line 2: unsupported statement WHATEVER"), std::string::npos);
    EXPECT_NE(err("LOADTL/1\nRAPID\nGOTO/0,0,0,0,0,-1\n").find("APT line 3 (G0 to"), std::string::npos);
    EXPECT_NE(err("LOADTL/1\nRAPID\nGOTO/0,0,0,0,0,1\nFEDRAT/100\nGOTO/1,0,$\n0,0,0,1\n").find("no error"), std::string::npos);
}
