// Every number that reaches an NC word is checked: finite, positive where it must be, within the
// machine's limits and the word's range, and refused with a message naming the line. Never
// clamped, wrapped or written from an unfinished buffer. Each case below once produced a wrong
// word (raw buffer bytes, F0, Q0, a hole of depth 0, T-2147483648, G4 F-5, M5 for a reversed
// spindle).
#include "ErrorOf.h"
#include "kinematics/Fixtures.h"

#include <aeronc/post/Post.h>

#include <gtest/gtest.h>

using namespace aeronc::kinematics;
using namespace aeronc::kinematics::test;
using namespace aeronc::post;
using aeronc::test::inputErrorOf;

namespace {

NcOptions options(Dialect d) {
    NcOptions o;
    o.dialect = d;
    return o;
}

const Dialect kDialects[] = {Dialect::Sinumerik840D, Dialect::LinuxCnc};

std::string postAptText(const std::string& apt, Dialect d) {
    return postApt(apt, machine("AC-5AX"), options(d), {}).text;
}

// A short APT program: `lines` are inserted after the tool call (line 2 on).
std::string apt(const std::string& lines) {
    return "LOADTL/1\n" + lines + "RAPID\nGOTO/0,0,50\nFINI\n";
}

// A drilling program whose CYCLE statement is line 5 and hole GOTO line 6.
std::string drilling(const std::string& cycle) {
    return "LOADTL/1\nSPINDL/3000,CLW\nRAPID\nGOTO/0,0,50\n" + cycle + "\nGOTO/10,0,0\nCYCLE/OFF\nFINI\n";
}

void expectRefused(const std::string& text, const std::string& where, const std::string& what) {
    for (const Dialect d : kDialects) {
        const std::string e = inputErrorOf([&] { postAptText(text, d); });
        EXPECT_NE(e.find(where), std::string::npos) << "expected '" << where << "' in: " << e << "\n" << text;
        EXPECT_NE(e.find(what), std::string::npos) << "expected '" << what << "' in: " << e << "\n" << text;
    }
}

std::vector<PathSection> job(const std::string& gcode, double rpm = 8000, int tool = 3) {
    PathSection tc;
    tc.kind = PathSection::Kind::ToolChange;
    tc.label = "TC: 10 mm end mill";
    tc.tool.number = tool;
    tc.tool.name = "EM10";
    tc.tool.diameter = 10;
    tc.rpm = rpm;
    tc.spindleDir = 1;
    PathSection op;
    op.label = "Op";
    op.gcode = gcode;
    return {tc, op};
}

}  // namespace

TEST(NcWordRange, HugeAptValuesAreRefusedNamingTheLine) {
    // ~1e64 once overflowed the number buffer: the program held raw stack bytes.
    const std::string feedMove = "LOADTL/1\nSPINDL/3000\nFEDRAT/1e64\nGOTO/0,0,50\nFINI\n";
    expectRefused(feedMove, "APT line 4", "feed");
    expectRefused(apt("SPINDL/1e64,CLW\n"), "APT line 2", "spindle speed");
    expectRefused(apt("DELAY/1e64\n"), "APT line 2", "dwell");
    expectRefused(drilling("CYCLE/DRILL,FEDTO,5,RAPTO,2,MMPM,1e64"), "APT line 6", "feed");
    expectRefused(drilling("CYCLE/DRILL,FEDTO,5,RAPTO,2,MMPM,100,DWELL,1e64"), "APT line 6", "dwell");
    expectRefused(drilling("CYCLE/DEEP,FEDTO,5,RAPTO,2,MMPM,100,STEP,1e64"), "APT line 6", "peck");
    // Beyond the machine's spindle (18000 r/min) and feed (30000 mm/min) limits.
    expectRefused(apt("SPINDL/20000,CLW\n"), "APT line 2", "18000");
    expectRefused("LOADTL/1\nFEDRAT/40000\nGOTO/0,0,50\nFINI\n", "APT line 3", "30000");
}

TEST(NcWordRange, ValuesThatRoundToZeroAreRefused) {
    expectRefused("LOADTL/1\nFEDRAT/1e-320\nGOTO/0,0,50\nFINI\n", "APT line 3", "feed");
    expectRefused(drilling("CYCLE/DEEP,FEDTO,5,RAPTO,2,MMPM,100,STEP,1e-320"), "APT line 6", "peck");
    expectRefused(drilling("CYCLE/DRILL,FEDTO,1e-320,MMPM,100"), "APT line 6", "depth");
    expectRefused(drilling("CYCLE/DRILL,FEDTO,5,RAPTO,2,MMPM,1e-320"), "APT line 6", "feed");
}

TEST(NcWordRange, AptToolNumbersSpindleAndDwellOutOfRangeAreRefused) {
    expectRefused(apt("") .replace(0, 8, "LOADTL/1e10"), "APT line 1", "tool number");
    expectRefused(apt("").replace(0, 8, "LOADTL/-3"), "APT line 1", "tool number");
    expectRefused(apt("").replace(0, 8, "LOADTL/2.5"), "APT line 1", "tool number");
    expectRefused(apt("DELAY/-5\n"), "APT line 2", "dwell");
    expectRefused(apt("SPINDL/-8000\n"), "APT line 2", "spindle speed");
    expectRefused(apt("SPINDL/0,CLW\n"), "APT line 2", "spindle speed");
    // The largest tool number that fits the word is still posted as written.
    for (const Dialect d : kDialects)
        EXPECT_NE(postAptText(apt("").replace(0, 8, "LOADTL/2147483647"), d).find("T2147483647"), std::string::npos);
}

TEST(NcWordRange, PathToolNumbersAndSpeedsOutOfRangeAreRefused) {
    const std::string moves = "G0 X0 Y0 Z50\n";
    for (const Dialect d : kDialects) {
        const MachineModel m = machine("AC-5AX");
        std::string e = inputErrorOf([&] { postFreeCad(job(moves + "M6 T1e10\n"), m, options(d), {}); });
        EXPECT_NE(e.find("operation 'Op', move 2 (M6 T1e10)"), std::string::npos) << e;
        EXPECT_NE(e.find("tool number"), std::string::npos) << e;
        e = inputErrorOf([&] { postFreeCad(job(moves + "M3 S-8000\n"), m, options(d), {}); });
        EXPECT_NE(e.find("move 2 (M3 S-8000)"), std::string::npos) << e;
        e = inputErrorOf([&] { postFreeCad(job(moves, 1e100), m, options(d), {}); });
        EXPECT_NE(e.find("TC: 10 mm end mill"), std::string::npos) << e;
        EXPECT_NE(e.find("spindle speed"), std::string::npos) << e;
        e = inputErrorOf([&] { postFreeCad(job(moves, -8000), m, options(d), {}); });
        EXPECT_NE(e.find("TC: 10 mm end mill"), std::string::npos) << e;
        e = inputErrorOf([&] { postFreeCad(job(moves, 8000, -1), m, options(d), {}); });
        EXPECT_NE(e.find("tool number"), std::string::npos) << e;
        // G4 P-5, and a feed of 1000 mm/s (60000 mm/min) on a machine that takes 30000.
        e = inputErrorOf([&] { postFreeCad(job(moves + "G4 P-5\n"), m, options(d), {}); });
        EXPECT_NE(e.find("move 2 (G4 P-5)"), std::string::npos) << e;
        e = inputErrorOf([&] { postFreeCad(job(moves + "G1 F1000 X1 Y0 Z50\n"), m, options(d), {}); });
        EXPECT_NE(e.find("operation 'Op', move 2: feed 60000 mm/min exceeds the machine's maximum feed 30000 mm/min"), std::string::npos) << e;
    }
}

TEST(NcWordRange, GAndMCodesThatAreNoNumberAreRefused) {
    // NaN and infinity once fell through the code switch as G1 (a feed move in place of a
    // drilling cycle) and M0 (a programme stop).
    for (const std::string bad : {"Gnan X1 Y0 Z-5 R2 F1", "GNaN X1 Y0 Z-5 R2 F1", "Ginf X1", "G-inf X1", "G1e308 X1",
                                  "G81e300 X1", "Minf", "Mnan", "M1e10", "G1.05 X1", "G-1 X1", "G 1 X1"}) {
        const std::string e =
            inputErrorOf([&] { postFreeCad(job("G0 X0 Y0 Z50\n" + bad + "\n"), machine("AC-5AX"), options(Dialect::LinuxCnc), {}); });
        EXPECT_NE(e.find("operation 'Op', move 2 (" + bad + ")"), std::string::npos) << e;
    }
}

TEST(NcWordRange, CarriageReturnLineEndingsReadAsLines) {
    const std::string lf = "G0 X0 Y0 Z50\nG1 F10 X5 Y0 Z50\nG1 X5 Y5 Z50\n";
    std::string cr = lf, crlf;
    for (char& c : cr)
        if (c == '\n') c = '\r';
    for (char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const MachineModel m = machine("AC-5AX");
    const PostSummary a = postFreeCad(job(lf), m, options(Dialect::LinuxCnc), {});
    EXPECT_EQ(a.moves, 3u);
    for (const std::string& text : {cr, crlf}) {
        const PostSummary b = postFreeCad(job(text), m, options(Dialect::LinuxCnc), {});
        EXPECT_EQ(b.moves, a.moves);
        EXPECT_EQ(b.text, a.text);
    }
}

TEST(NcWordRange, TheLargestWrittenNumbersStillPost) {
    // Within range everything posts as before: 29999 mm/min, 17999 r/min, a dwell of 1e5 s.
    for (const Dialect d : kDialects) {
        const std::string nc =
            postAptText("LOADTL/7\nSPINDL/17999,CCLW\nDELAY/100000\nFEDRAT/29999\nGOTO/0,0,50\nFINI\n", d);
        EXPECT_NE(nc.find("S17999 M4"), std::string::npos) << nc;
        EXPECT_NE(nc.find("F29999"), std::string::npos) << nc;
        EXPECT_NE(nc.find("100000"), std::string::npos) << nc;
    }
}

TEST(NcWordRange, AppendNumberRefusesWhatItCannotWrite) {
    std::string out;
    appendNumber(out, 123456789.25, 12);
    EXPECT_EQ(out, "123456789.25");
    out.clear();
    appendNumber(out, -0.0000004, 6);
    EXPECT_EQ(out, "0");
    for (const double v : {1e9, -1e64, 1e300, std::numeric_limits<double>::infinity(), std::nan("")}) {
        out = "X";
        EXPECT_THROW(appendNumber(out, v, 3), aeronc::Error) << v;
        EXPECT_THROW(appendNumber(out, v, 15), aeronc::Error) << v;
        EXPECT_EQ(out, "X");
    }
}

TEST(NcWordRange, AWorkOffsetIsOneGCodeNeverABlockOfOtherWords) {
    // Found by fuzzing: the APT text after WORK OFFSET was written to the LinuxCNC program as
    // a block of its own, whatever it held.
    for (const std::string bad : {"G54 G0 X0", "G,120\x14", "M30", "G53", "G54.1.1"}) {
        const std::string text = "LOADTL/1\nPPRINT/WORK OFFSET " + bad + "\nRAPID\nGOTO/0,0,50\nFINI\n";
        for (const Dialect d : kDialects) {
            const std::string e = inputErrorOf([&] { postAptText(text, d); });
            EXPECT_NE(e.find("APT line 2: WORK OFFSET"), std::string::npos) << e;
        }
    }
    EXPECT_NE(postAptText("LOADTL/1\nPPRINT/WORK OFFSET g59.1\nRAPID\nGOTO/0,0,50\nFINI\n", Dialect::LinuxCnc).find("\nG59.1\n"),
              std::string::npos);
    // From FreeCAD's Path: the offset is written from its code, not copied from the line.
    const std::string nc = postFreeCad(job("G055 X1\nG0 X0 Y0 Z50\n"), machine("AC-5AX"), options(Dialect::LinuxCnc), {}).text;
    EXPECT_NE(nc.find("\nG55\n"), std::string::npos) << nc;
    EXPECT_EQ(nc.find("X1\n"), std::string::npos) << nc;
}

TEST(NcWordRange, ASpeedOrFeedARoundingErrorAboveTheMachineLimitPostsAtTheLimit) {
    // The optimiser and the knowledge base cap speeds and feeds at the machine's limits
    // (AC-5AX: 18000 r/min, 30000 mm/min); after unit conversions the value can sit a rounding
    // error above. That is the limit; 0.1 % above is not.
    char above[64];
    for (const double factor : {1.0, 1.0 + 2.220446e-16, 1.0 + 1e-12, 1.0 + 9e-10}) {
        std::snprintf(above, sizeof above, "SPINDL/%.17g,CLW\nFEDRAT/%.17g\n", 18000.0 * factor, 30000.0 * factor);
        for (const Dialect d : kDialects) {
            const std::string nc = postAptText("LOADTL/1\n" + std::string(above) + "GOTO/0,0,50\nFINI\n", d);
            EXPECT_NE(nc.find("S18000 M3"), std::string::npos) << factor << "\n" << nc;
            EXPECT_NE(nc.find("F30000\n"), std::string::npos) << factor << "\n" << nc;
        }
        // The same from FreeCAD's Path: the tool controller's speed, a feed of 500 mm/s.
        std::snprintf(above, sizeof above, "G1 X1 Y0 Z50 F%.17g\n", 500.0 * factor);
        for (const Dialect d : kDialects) {
            const std::string nc =
                postFreeCad(job(std::string("G0 X0 Y0 Z50\n") + above, 18000.0 * factor), machine("AC-5AX"), options(d), {}).text;
            EXPECT_NE(nc.find("S18000 M3"), std::string::npos) << factor << "\n" << nc;
            EXPECT_NE(nc.find("F30000\n"), std::string::npos) << factor << "\n" << nc;
        }
    }
    expectRefused(apt("SPINDL/18018,CLW\n"), "APT line 2: spindle speed 18018 r/min exceeds the machine's maximum spindle speed 18000", "r/min");
    expectRefused("LOADTL/1\nFEDRAT/30030\nGOTO/0,0,50\nFINI\n", "APT line 3: feed 30030 mm/min exceeds the machine's maximum feed 30000", "mm/min");
    for (const Dialect d : kDialects) {
        std::string e = inputErrorOf([&] { postFreeCad(job("G0 X0 Y0 Z50\n", 18018), machine("AC-5AX"), options(d), {}); });
        // Named by its tool controller (it was "operation 'Op', move 0", a move that does not exist).
        EXPECT_NE(e.find("tool controller 'TC: 10 mm end mill' of operation 'Op': spindle speed 18018 r/min exceeds the "
                         "machine's maximum spindle speed 18000"),
                  std::string::npos)
            << e;
        e = inputErrorOf([&] { postFreeCad(job("G0 X0 Y0 Z50\nG1 X1 Y0 Z50 F500.5\n"), machine("AC-5AX"), options(d), {}); });
        EXPECT_NE(e.find("operation 'Op', move 2: feed 30030 mm/min exceeds the machine's maximum feed 30000 mm/min"), std::string::npos) << e;
    }
}

TEST(NcWordRange, AnArcOfAbsurdRadiusIsRefusedNamingTheLine) {
    // Found by fuzzing: an arc whose centre is 1e110 mm away, in a 5-axis segment the 840D
    // post linearises, made the chord count infinite, converted to int (undefined; in a
    // release build one chord, a straight move for a full circle).
    const std::string text = "LOADTL/3\nSPINDL/8000,CLW\nRAPID\nGOTO/0,0,50,0,0,1\nFEDRAT/600\nGOTO/0,0,-2\n"
                             "GOTO/20,0,-2\nCIRCLE/20,1e110,-2,0,0,1,10\nGOTO/20,20,-2\n"
                             "GOTO/10,20,-2,0.2588190451,0,0.9659258263\nFINI\n";
    std::string e = inputErrorOf([&] { postAptText(text, Dialect::Sinumerik840D); });
    EXPECT_NE(e.find("APT line 9"), std::string::npos) << e;
    EXPECT_NE(e.find("the arc (radius 1e+110 mm"), std::string::npos) << e;
    e = inputErrorOf([&] { postAptText(text, Dialect::LinuxCnc); });
    EXPECT_NE(e.find("APT line 9"), std::string::npos) << e;
    // The same arc with its centre 10 mm away posts.
    std::string sane = text;
    sane.replace(sane.find("1e110"), 5, "10");
    for (const Dialect d : kDialects) EXPECT_NO_THROW(postAptText(sane, d));
}
