#pragma once
// 5-axis toolpaths of a recognised impeller (docs/impeller.md): channel roughing in layers
// between adjacent blades, flank finishing of the blade walls with the tool axis along the
// rulings (tilted from them by the taper), and hub finishing with the axis interpolated between
// the two blades. Every move carries its tool axis. Each position is checked against the blades
// and the hub with OCCT distance queries (the tool as the union of spheres along its axis: ball
// and taper, then the holder), and tilted towards the channel's middle when the holder would
// touch.
#include <aeronc/impeller/Blank.h>
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/kinematics/ClProgram.h>

#include <TopoDS_Shape.hxx>
#include <optional>
#include <string>
#include <vector>

namespace aeronc::impellerpath {

// A ball or tapered ball end mill in its holder.
struct CutterShape {
    std::string id;
    int number = 1;
    double tipRadius = 0;     // ball radius
    double taperDeg = 0;      // half angle of the cone above the ball (0: a plain ball end mill)
    double fluteLength = 0;   // cutting length from the tip
    double shankRadius = 0;   // the shank and holder above the flutes, as a cylinder ...
    double reach = 0;         // ... up to this length from the tip
    double rpm = 0, feed = 0; // r/min, mm/min
    bool flat = false;        // a flat-bottomed tool (face mill, flat end mill, drill) of radius tipRadius
    // Radius of the cutting part at distance h from the ball's centre along the axis.
    double radiusAt(double h) const;
};

struct Move {
    kinematics::Vec3 centre;  // ball centre, workpiece frame
    kinematics::Vec3 axis;    // unit, from the tip towards the spindle
    bool rapid = false;
};

struct Operation {
    std::string name;         // rough_channels, finish_blades, finish_hub, finish_fillets
    CutterShape cutter;
    std::vector<Move> moves;
};

struct PathOptions {
    double roughAllowance = 0.5;   // stock roughing leaves on the blades and the hub (mm)
    double stepDown = 2.0;         // roughing layer depth (mm)
    double stepOver = 0.6;         // fraction of the ball diameter between roughing lanes
    double finishStep = 1.0;       // mm between finishing passes (along the hub, across it)
    int stations = 24;             // positions along each pass (from inlet to outlet)
    double safeDistance = 5.0;     // clearance plane: the ball this far above the blank's top (mm)
    double blankAllowance = 2.0;   // the blank: the part's outer profile grown by this (mm)
    double rapidClearance = 1.0;   // rapids keep the whole tool this far outside the blank (mm)
    double maxTiltDeg = 20;        // largest tilt towards the channel's middle to clear the holder
    int channels = 0;              // channels to machine (0: all); 1 or 2 for a quick look
};

struct CheckResult {
    double maxGouge = 0;       // deepest penetration of the cutter into the blades and hub (mm)
    int holderCollisions = 0;  // positions where the shank or holder touches the part
    int tilted = 0;            // positions tilted to clear the holder
    int positions = 0;         // cutting positions checked
    double worstAt[3] = {0, 0, 0};
    // Links: the approach and retract of each pass along the tool axis at feed, checked against
    // the part every millimetre, and the rapids, checked against the blank (docs/impeller.md §5).
    int links = 0;             // links checked
    int linkCollisions = 0;    // feed links that touch the part, rapids that enter the blank
    // The least gap between the shank or holder and the part over the positions (mm; negative:
    // a collision); gaps of 1 mm or more are not measured further (1 stands for them).
    double minHolderGap = 1.0;
    // Positions left out of their pass (the pass split there): the holder still touched after
    // tilting, or the cutter still cut into the part after stepping back.
    int leftOut = 0;
};

struct ImpellerProgram {
    std::vector<Operation> operations;
    CheckResult check;         // over every cutting position, after tilting
};

// The route's cutters for the 5-axis operations: the fillet finishing ball is optional.
struct RouteCutters {
    CutterShape rougher, finisher;
    std::optional<CutterShape> filletBall;  // finish_fillets: along each root fillet
};

// Toolpaths for every channel (adjacent pair of blades) of the part: the two kinds of channel
// (main to splitter, splitter to main) are computed once; the others are those turned about the
// axis by the blade pitch and placed again against their own blades and hub (stepped back,
// tilted or left out there: an exported part's blades are not exact copies), so the check covers
// every channel's moves. With splitters, the inducer (from one main blade to
// the next, ahead of the splitter's leading edge) is roughed and its hub finished as a third
// kind, repeated once per main blade. Throws inputError when a cutter does not fit (a
// ball wider than the channel) or when the part has no channel with both walls along it.
ImpellerProgram impellerToolpaths(const TopoDS_Shape& part, const impeller::ImpellerFeatures& features,
                                  const impeller::ImpellerDimensions& dimensions, const CutterShape& rougher,
                                  const CutterShape& finisher, const PathOptions& options = {});

// The same with the fillet finishing (operation finish_fillets, after finish_hub): along the root
// fillet of each blade's pressure and suction walls, the ball touching the fillet halfway between
// the wall and the hub (or, a ball larger than the fillet, touching both), its axis the wall's
// ruling tilted 10° away from the wall.
ImpellerProgram impellerToolpaths(const TopoDS_Shape& part, const impeller::ImpellerFeatures& features,
                                  const impeller::ImpellerDimensions& dimensions, const RouteCutters& cutters,
                                  const PathOptions& options = {});

// Checks cutting positions (not rapids) of `program` against the part's blades and hub: the
// same measure as the generator's check, for a program read back from its posted text.
CheckResult checkProgram(const TopoDS_Shape& part, const impeller::ImpellerFeatures& features,
                         const std::vector<std::pair<CutterShape, std::vector<Move>>>& operations);

// Rapid moves of `operations` (a program read back) against the blank: every rapid from the
// move before it, its tool (flutes and shank up to the reach) sampled every half millimetre,
// must stay `clearance` outside the blank. Fills links and linkCollisions.
CheckResult checkRapids(const impeller::BlankProfile& blank, const impeller::ImpellerFeatures& features,
                        const std::vector<std::pair<CutterShape, std::vector<Move>>>& operations,
                        double clearance = 0);

// The CL program: one operation per toolpath, tool changes, spindle, feeds, every move with its
// tip (centre − tip radius · axis) and axis, retracts between passes as rapids.
kinematics::ClProgram toClProgram(const ImpellerProgram& program, const std::string& name);

// Moves of each operation of a CL program (an APT file read back): centre = tip + radius · axis.
std::vector<std::pair<CutterShape, std::vector<Move>>> movesOf(const kinematics::ClProgram& cl,
                                                               const std::vector<CutterShape>& cutters);

}  // namespace aeronc::impellerpath
