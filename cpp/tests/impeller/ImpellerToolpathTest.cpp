// 5-axis toolpaths of a generated 2 x 9 impeller with the tools its route chooses: no gouge
// deeper than 0.01 mm into the blades or the hub and no holder collision, checked on the
// generated moves and again on the program written as APT and read back; roughing keeps its
// allowance; the program posts for the AC cradle 840D machine under TRAORI.
#include <aeronc/core/Error.h>
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/Blank.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impellerpath/AxialOperations.h>
#include <aeronc/impellerpath/ImpellerToolpaths.h>
#include <aeronc/kb/ImpellerRoute.h>
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/kinematics/MachineModel.h>
#include <aeronc/post/Apt.h>
#include <aeronc/post/Post.h>
#include <aeronc/testparts/ImpellerGenerator.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <BRepAlgoAPI_Splitter.hxx>
#include <BRepBuilderAPI_MakeSolid.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Pln.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRep_Builder.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS_Compound.hxx>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>

#include <filesystem>
#include <functional>
#include <map>

#include "ErrorOf.h"

using namespace aeronc;
using namespace aeronc::impellerpath;

namespace {

constexpr double kGougeLimit = 0.01;  // mm, the bound

CutterShape cutterOf(const impeller::CuttingTool& t, int number, double shankRadius) {
    CutterShape c;
    c.id = t.id;
    c.number = number;
    c.tipRadius = t.diameter / 2;
    c.taperDeg = t.taperDeg;
    c.fluteLength = t.fluteLength;
    c.reach = t.reach;
    c.shankRadius = shankRadius;
    c.rpm = 12000;
    c.feed = 1200;
    return c;
}

testparts::Impeller exported(testparts::Impeller part, const std::function<TopoDS_Shape(const testparts::Impeller&)>& reshape) {
    if (reshape) part.shape = reshape(part);
    return part;
}

// The hub face cut along the half-planes through the axis at these angles (an exporter's
// patches of one hub): the hub split by the planes, the part sewn again from its other faces
// and the pieces.
TopoDS_Shape hubCutAt(const testparts::Impeller& part, const std::vector<double>& anglesDeg) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part.shape, TopAbs_FACE, faces);
    const TopoDS_Face hub = TopoDS::Face(faces(part.truth.hub));
    BRepAlgoAPI_Splitter split;
    TopTools_ListOfShape args, tools;
    args.Append(hub);
    for (double a : anglesDeg) {
        const double t = a * M_PI / 180;
        const gp_Pln half(gp_Ax3(gp_Pnt(0, 0, 0), gp_Dir(-std::sin(t), std::cos(t), 0), gp_Dir(std::cos(t), std::sin(t), 0)));  // v runs down the axis
        tools.Append(BRepBuilderAPI_MakeFace(half, 0, 200, -200, 10).Face());
    }
    split.SetArguments(args);
    split.SetTools(tools);
    split.Build();
    if (!split.IsDone()) throw std::runtime_error("hub not split");
    BRepBuilderAPI_Sewing sew(1e-4);
    for (int i = 1; i <= faces.Extent(); ++i)
        if (i != part.truth.hub) sew.Add(faces(i));
    for (TopExp_Explorer e(split.Shape(), TopAbs_FACE); e.More(); e.Next()) sew.Add(e.Current());
    sew.Perform();
    TopExp_Explorer shell(sew.SewedShape(), TopAbs_SHELL);
    if (!shell.More()) throw std::runtime_error("no shell sewn");
    BRepBuilderAPI_MakeSolid solid(TopoDS::Shell(shell.Current()));
    return solid.Solid();
}

struct Programmed {
    testparts::Impeller part;
    impeller::ImpellerFeatures features;
    impeller::ImpellerDimensions dims;
    CutterShape rougher, finisher, filletBall;
    // reshape: the generated part as an exporter might write it (faces split, say).
    explicit Programmed(const testparts::ImpellerSpec& spec = {},
                        const std::function<TopoDS_Shape(const testparts::Impeller&)>& reshape = nullptr)
        : part(exported(testparts::makeImpeller(spec), reshape)),
          features(impeller::recogniseImpeller(part.shape)),
          dims(impeller::measureImpeller(part.shape, features)) {
        // Per process: two test runs at once (two checkouts) would share and remove one file.
        const auto path = std::filesystem::temp_directory_path() /
                          ("aeronc_impeller_paths_" + std::to_string(::getpid()) + ".sqlite");
        std::filesystem::remove(path);
        const auto kb =
            kb::KnowledgeBase::openWithSqlFolder(path.string(), [] { return std::string(AERONC_RESOURCES) + "/kb"; });
        const auto route = kb::planImpellerRoute(kb, features, dims);
        for (const auto& s : route.steps) {
            // Shank: the tool's own diameter for a ball; the tapered ball's is in its table (8 to 10 mm).
            if (s.operation == "rough_channels") rougher = cutterOf(*s.tool, 1, s.tool->diameter / 2);
            if (s.operation == "finish_blades") finisher = cutterOf(*s.tool, 2, 4.0);
            if (s.operation == "finish_fillets") filletBall = cutterOf(*s.tool, 3, s.tool->diameter / 2);
        }
    }
};

PathOptions quick() {
    PathOptions o;
    o.stations = 6;
    o.channels = 2;  // one channel of each kind: main to splitter, splitter to main
    return o;
}

}  // namespace

// An exported part's blades are not exact copies: here main blade 2 stands 0.3 degrees off its
// pitch (0.28 mm at the outlet). The channels beside it, turned from channel 0, would cut into it;
// placed again against their own blades, no channel gouges or touches with the holder, and the
// toolpaths' own check covers every channel's positions.
TEST(ImpellerToolpaths, EveryChannelPlacedOnItsOwnBlades) {
    testparts::ImpellerSpec spec;
    spec.bladeCount = 5;
    spec.splitters = false;
    spec.offPitchBlade = 2;
    spec.offPitchDeg = 0.3;
    Programmed s(spec);
    ASSERT_EQ(s.features.bladeCount, 5);
    PathOptions o;
    o.stations = 6;
    const auto prog = impellerToolpaths(s.part.shape, s.features, s.dims, s.rougher, s.finisher, o);
    std::vector<std::pair<CutterShape, std::vector<Move>>> ops;
    for (const auto& op : prog.operations) ops.push_back({op.cutter, op.moves});
    const auto again = checkProgram(s.part.shape, s.features, ops);
    EXPECT_EQ(again.positions, prog.check.positions);
    EXPECT_LE(again.maxGouge, kGougeLimit) << again.worstAt[0] << " " << again.worstAt[1] << " " << again.worstAt[2];
    EXPECT_EQ(again.holderCollisions, 0);
    EXPECT_LE(prog.check.maxGouge, kGougeLimit);
    EXPECT_EQ(prog.check.holderCollisions, 0);
    // The channels beside the blade are 0.28 mm narrower or wider at most: stepping back absorbs
    // that, so nothing is left out.
    EXPECT_EQ(prog.check.leftOut, 0);
}

// An exporter's hub in a piece per channel whose seams do not follow the blades: here each
// seam runs along the middle of a channel at its inlet, so every channel runs over two pieces,
// and the blades lean 20 degrees. Every channel finds the pieces under it (each holding about
// half of it), and the program of every channel is clean.
TEST(ImpellerToolpaths, HubInPiecesAcrossTheChannels) {
    testparts::ImpellerSpec spec;
    spec.bladeCount = 6;
    spec.splitters = false;
    spec.leanDeg = 20;
    const auto seams = [](const testparts::Impeller& p) {
        std::vector<double> at;
        for (const auto& b : p.truth.blades) at.push_back(b.angleDeg + 60.0 / 2);
        return hubCutAt(p, at);
    };
    Programmed s(spec, seams);
    ASSERT_EQ(s.features.bladeCount, 6);
    ASSERT_EQ(s.features.hubFaces.size(), 6u);
    PathOptions o;
    o.stations = 6;
    const auto prog = impellerToolpaths(s.part.shape, s.features, s.dims, s.rougher, s.finisher, o);
    std::vector<std::pair<CutterShape, std::vector<Move>>> ops;
    for (const auto& op : prog.operations) ops.push_back({op.cutter, op.moves});
    const auto again = checkProgram(s.part.shape, s.features, ops);
    EXPECT_EQ(again.positions, prog.check.positions);
    EXPECT_LE(again.maxGouge, kGougeLimit) << again.worstAt[0] << " " << again.worstAt[1] << " " << again.worstAt[2];
    EXPECT_EQ(again.holderCollisions, 0);
}

TEST(ImpellerToolpaths, NoGougeNoCollisionPostedUnderTraori) {
    Programmed s;
    ASSERT_EQ(s.rougher.id.rfind("EM-BALL", 0), 0u) << s.rougher.id;
    ASSERT_GT(s.finisher.taperDeg, 0);
    const auto prog = impellerToolpaths(s.part.shape, s.features, s.dims, s.rougher, s.finisher, quick());
    ASSERT_EQ(prog.operations.size(), 3u);
    for (const auto& op : prog.operations) {
        SCOPED_TRACE(op.name);
        int cutting = 0;
        for (const auto& m : op.moves) {
            EXPECT_NEAR(m.axis.norm(), 1, 1e-9);
            EXPECT_GT(m.axis.dot(kinematics::Vec3::UnitZ()), 0.5);  // reachable from above
            cutting += !m.rapid;
        }
        EXPECT_GT(cutting, 10);
    }
    EXPECT_GT(prog.check.positions, 100);
    EXPECT_LE(prog.check.maxGouge, kGougeLimit) << prog.check.worstAt[0] << " " << prog.check.worstAt[1] << " "
                                                 << prog.check.worstAt[2];
    EXPECT_EQ(prog.check.holderCollisions, 0);

    // Written as APT, read back, checked again.
    const std::string apt = post::writeApt(toClProgram(prog, "IMPELLER"));
    const auto reread = movesOf(post::readApt(apt), std::vector<CutterShape>{s.rougher, s.finisher});
    ASSERT_EQ(reread.size(), 3u);
    const auto again = checkProgram(s.part.shape, s.features, reread);
    EXPECT_EQ(again.positions, prog.check.positions);
    EXPECT_LE(again.maxGouge, kGougeLimit);
    EXPECT_EQ(again.holderCollisions, 0);
    // Roughing leaves its allowance: a ball grown by it (less 0.01 mm) touches nothing.
    CutterShape grown = s.rougher;
    grown.tipRadius += quick().roughAllowance - 0.01;
    grown.fluteLength += quick().roughAllowance;
    grown.shankRadius = grown.tipRadius;
    EXPECT_LE(checkProgram(s.part.shape, s.features, {{grown, reread[0].second}}).maxGouge, 0.0);

    // Passes are entered and left along the tool axis at feed until the tool is outside the blank;
    // the rapids between them stay outside it, so they cut neither the part nor any stock left.
    EXPECT_GT(prog.check.links, 20);
    EXPECT_EQ(prog.check.linkCollisions, 0);
    const auto blank = impeller::outerProfile(s.part.shape, s.features, quick().blankAllowance);
    const auto rapids = checkRapids(blank, s.features, reread, quick().rapidClearance - 1e-6);
    EXPECT_GT(rapids.links, 20);
    EXPECT_EQ(rapids.linkCollisions, 0);
    // Retracting at rapid straight from the last cutting position would run through the stock.
    auto direct = reread;
    int passes = 0;
    for (auto& [cutter, moves] : direct)
        for (size_t i = 1; i + 1 < moves.size(); ++i)
            if (!moves[i - 1].rapid && !moves[i].rapid && moves[i + 1].rapid) {
                moves.erase(moves.begin() + static_cast<long>(i));
                ++passes;
            }
    EXPECT_GT(passes, 10);
    EXPECT_GE(checkRapids(blank, s.features, direct).linkCollisions, passes);

    // Posted for the AC cradle machine with the 840D: TRAORI around the simultaneous moves.
    const auto machine = kinematics::loadMachineFile(std::string(AERONC_MACHINES) + "/AC-5AX.json");
    post::NcOptions nc;
    nc.programName = "IMPELLER";
    const auto posted = post::postApt(apt, machine, nc, {});
    EXPECT_NE(posted.text.find("TRAORI"), std::string::npos);
    EXPECT_NE(posted.text.find("TRAFOOF"), std::string::npos);
    EXPECT_NE(posted.text.find("M30"), std::string::npos);
    EXPECT_GE(posted.moves, reread[0].second.size() + reread[1].second.size() + reread[2].second.size());
}

// A cutter whose holder is too fat for the channel is reported, not hidden; a roughing ball
// wider than the channel is refused.
// A holder too fat for the channel: the positions where it still touches after tilting are
// left out of the program (counted), never delivered; the program read back touches nowhere.
TEST(ImpellerToolpaths, CollidingPositionsLeftOutAndTooWideRefused) {
    Programmed s;
    CutterShape fat = s.finisher;
    fat.fluteLength = 6;
    fat.shankRadius = 9;
    PathOptions o = quick();
    o.channels = 1;
    o.stations = 4;
    o.maxTiltDeg = 4;
    const auto prog = impellerToolpaths(s.part.shape, s.features, s.dims, s.rougher, fat, o);
    EXPECT_GT(prog.check.leftOut, 0);
    EXPECT_EQ(prog.check.holderCollisions, 0);
    const std::string apt = post::writeApt(toClProgram(prog, "IMPELLER"));
    const auto again = checkProgram(s.part.shape, s.features, movesOf(post::readApt(apt), {s.rougher, fat, fat}));
    EXPECT_EQ(again.holderCollisions, 0);

    CutterShape wide = s.rougher;
    wide.tipRadius = wide.shankRadius = s.dims.minChannelWidth / 2;
    const std::string msg = test::inputErrorOf([&] { impellerToolpaths(s.part.shape, s.features, s.dims, wide, s.finisher, o); });
    EXPECT_NE(msg.find("wider than the narrowest channel"), std::string::npos) << msg;
}

// Fillet finishing runs along the root fillets touching them, and the inducer ahead of the
// splitters is roughed; no move of the program read back gouges a blade or the hub, and its
// rapids stay outside the blank.
TEST(ImpellerToolpaths, FilletsAndInducer) {
    Programmed s;
    ASSERT_GT(s.filletBall.tipRadius, 0);
    ASSERT_LE(s.filletBall.tipRadius, s.dims.filletRadius + 1e-9);
    const auto prog = impellerToolpaths(s.part.shape, s.features, s.dims, RouteCutters{s.rougher, s.finisher, s.filletBall},
                                        quick());
    ASSERT_EQ(prog.operations.size(), 4u);
    EXPECT_EQ(prog.operations[3].name, "finish_fillets");
    EXPECT_EQ(prog.check.linkCollisions, 0);

    const std::string apt = post::writeApt(toClProgram(prog, "IMPELLER"));
    const auto reread = movesOf(post::readApt(apt), {s.rougher, s.finisher, s.filletBall});
    ASSERT_EQ(reread.size(), 4u);
    const auto again = checkProgram(s.part.shape, s.features, reread);
    EXPECT_LE(again.maxGouge, kGougeLimit);
    EXPECT_EQ(again.holderCollisions, 0);
    const auto blank = impeller::outerProfile(s.part.shape, s.features, quick().blankAllowance);
    EXPECT_EQ(checkRapids(blank, s.features, reread, quick().rapidClearance - 1e-6).linkCollisions, 0);

    // The fillet ball touches the fillet faces: its centre its radius from them.
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(s.part.shape, TopAbs_FACE, faces);
    BRep_Builder b;
    TopoDS_Compound fillets;
    b.MakeCompound(fillets);
    for (const auto& blade : s.features.blades)
        for (int id : blade.fillets) b.Add(fillets, faces(id));
    int touching = 0;
    for (const auto& m : reread[3].second) {
        if (m.rapid) continue;
        BRepExtrema_DistShapeShape dist(BRepBuilderAPI_MakeVertex(gp_Pnt(m.centre.x(), m.centre.y(), m.centre.z())).Vertex(),
                                        fillets);
        ASSERT_TRUE(dist.IsDone());
        touching += std::abs(dist.Value() - s.filletBall.tipRadius) < 0.01;
    }
    // Two walls in each of the two channels, a pass of `stations` positions along each.
    EXPECT_GE(touching, 4 * (quick().stations - 1));

    // The inducer: roughing positions ahead of the splitters' leading edges (radius 38.6 mm).
    const testparts::ImpellerSpec spec;
    const double splitterStart = spec.leadingRadius + spec.splitterStart * (spec.trailingRadius - spec.leadingRadius);
    int inducer = 0;
    for (const auto& m : reread[0].second)
        inducer += !m.rapid && std::hypot(m.centre.x(), m.centre.y()) < splitterStart - s.rougher.tipRadius;
    EXPECT_GT(inducer, 2 * quick().stations);
}

// Turning, facing, drilling and boring with the route's tools on the generated impeller: every
// step the part needs yields moves, none gouges the finished part, the bore is bored to its
// truth radius, and the milled steps post as plain moves.
TEST(ImpellerAxialOperations, EveryRouteStepHasMoves) {
    Programmed s;
    const auto path = std::filesystem::temp_directory_path() / "aeronc_impeller_axial.sqlite";
    std::filesystem::remove(path);
    const auto kb = kb::KnowledgeBase::openWithSqlFolder(path.string(), [] { return std::string(AERONC_RESOURCES) + "/kb"; });
    AxialCutters cutters;
    int number = 3;
    for (const auto& st : kb::planImpellerRoute(kb, s.features, s.dims).steps) {
        if (!st.tool || (st.operation != "face" && st.operation != "drill" && st.operation != "bore")) continue;
        const CutterShape c =
            flatCutter(st.tool->id, ++number, st.tool->diameter, st.tool->fluteLength, st.tool->reach, 2000, 200);
        (st.operation == "face" ? cutters.faceMill : st.operation == "drill" ? cutters.drill : cutters.boringMill) = c;
    }
    ASSERT_TRUE(cutters.faceMill && cutters.drill && cutters.boringMill);
    const auto prog = axialToolpaths(s.part.shape, s.features, s.dims, cutters);
    std::map<std::string, const Operation*> ops;
    for (const auto& op : prog.operations) ops[op.name] = &op;
    for (const char* name : {"turn", "face", "drill", "bore"}) {
        SCOPED_TRACE(name);
        ASSERT_TRUE(ops.count(name));
        int cutting = 0;
        for (const auto& mv : ops[name]->moves) cutting += !mv.rapid;
        EXPECT_GT(cutting, 5);
    }
    EXPECT_LE(prog.check.maxGouge, kGougeLimit) << prog.check.worstAt[0] << " " << prog.check.worstAt[1] << " "
                                                 << prog.check.worstAt[2];
    EXPECT_EQ(prog.check.holderCollisions, 0);
    // Both planes faced: the face mill's tip on the nose plane (z 40) and on the back face (z 0),
    // its axis away from the part; the lathe's insert over both too.
    for (const char* name : {"face", "turn"}) {
        SCOPED_TRACE(name);
        const auto& op = *ops[name];
        int onNose = 0, onBack = 0;
        for (const auto& mv : op.moves) {
            if (mv.rapid) continue;
            const kinematics::Vec3 tip = mv.centre - op.cutter.tipRadius * mv.axis;
            onNose += std::abs(tip.z() - 40) < 1e-6 && mv.axis.z() > 0.999;
            onBack += std::abs(tip.z()) < 1e-6 && mv.axis.z() < -0.999;
        }
        EXPECT_GT(onNose, 3);
        EXPECT_GT(onBack, 3);
    }
    // The boring mill's flutes (32 mm) do not reach through the 40 mm bore: the rest from the back.
    ASSERT_TRUE(ops.count("bore_back"));
    EXPECT_LT(ops["bore_back"]->moves.front().axis.z(), -0.999);

    // Boring: the tool's side at the truth's bore radius all the way down.
    const double boreRadius = s.part.truth.boreDiameter / 2;
    for (const auto& mv : ops["bore"]->moves) {
        if (mv.rapid) continue;
        EXPECT_NEAR(std::hypot(mv.centre.x(), mv.centre.y()) + ops["bore"]->cutter.tipRadius, boreRadius, 1e-9);
    }
    // The drill leaves the allowance.
    EXPECT_LE(ops["drill"]->cutter.tipRadius, boreRadius - AxialOptions{}.drillAllowance + 1e-9);

    // Re-read from APT, checked again against the finished part, and posted as plain moves.
    ImpellerProgram milled;
    for (const char* name : {"drill", "bore"}) milled.operations.push_back(*ops[name]);
    const std::string apt = post::writeApt(toClProgram(milled, "BORE"));
    const auto reread = movesOf(post::readApt(apt), {*cutters.drill, *cutters.boringMill});
    const auto again = checkProgram(s.part.shape, s.features, reread);
    EXPECT_GT(again.positions, 20);
    const auto machine = kinematics::loadMachineFile(std::string(AERONC_MACHINES) + "/AC-5AX.json");
    post::NcOptions nc;
    nc.programName = "BORE";
    const auto posted = post::postApt(apt, machine, nc, {});
    EXPECT_NE(posted.text.find("M30"), std::string::npos);
}

// Blades standing above the nose plane: the face mill would cut them, so it does not face that
// plane and says so; what it does face touches nothing.
TEST(ImpellerAxialOperations, FaceMillKeptOffTheBlades) {
    testparts::ImpellerSpec spec;
    spec.noseHeight = 30;
    const auto part = testparts::makeImpeller(spec);
    const auto f = impeller::recogniseImpeller(part.shape);
    const auto d = impeller::measureImpeller(part.shape, f);
    AxialCutters cutters;
    cutters.faceMill = flatCutter("FM-125", 4, 125, 6, 63, 1000, 500);
    const auto prog = axialToolpaths(part.shape, f, d, cutters);
    bool noted = false;
    for (const auto& n : prog.notes) noted = noted || n.find("cannot face plane") != std::string::npos;
    EXPECT_TRUE(noted);
    for (const auto& op : prog.operations)
        for (const auto& mv : op.moves)
            if (op.name == "face" && !mv.rapid) EXPECT_LT(mv.axis.z(), -0.999);  // the back face only
    EXPECT_LE(prog.check.maxGouge, kGougeLimit);
}
