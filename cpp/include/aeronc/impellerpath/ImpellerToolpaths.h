#pragma once
// 5-axis toolpaths of a recognised impeller (docs/impeller.md): channel roughing in layers
// between adjacent blades, flank finishing of the blade walls with the tool axis along the
// rulings (tilted from them by the taper), and hub finishing with the axis interpolated between
// the two blades. Every move carries its tool axis. Each position is checked against the blades
// and the hub with OCCT distance queries (the tool as the union of spheres along its axis: ball
// and taper, then the holder), and tilted towards the channel's middle when the holder would
// touch.
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/kinematics/ClProgram.h>

#include <TopoDS_Shape.hxx>
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
    // Radius of the cutting part at distance h from the ball's centre along the axis.
    double radiusAt(double h) const;
};

struct Move {
    kinematics::Vec3 centre;  // ball centre, workpiece frame
    kinematics::Vec3 axis;    // unit, from the tip towards the spindle
    bool rapid = false;
};

struct Operation {
    std::string name;         // rough_channels, finish_blades, finish_hub
    CutterShape cutter;
    std::vector<Move> moves;
};

struct PathOptions {
    double roughAllowance = 0.5;   // stock roughing leaves on the blades and the hub (mm)
    double stepDown = 2.0;         // roughing layer depth (mm)
    double stepOver = 0.6;         // fraction of the ball diameter between roughing lanes
    double finishStep = 1.0;       // mm between finishing passes (along the hub, across it)
    int stations = 24;             // positions along each pass (from inlet to outlet)
    double safeDistance = 5.0;     // retract height above the shroud along the axis (mm)
    double maxTiltDeg = 20;        // largest tilt towards the channel's middle to clear the holder
    int channels = 0;              // channels to machine (0: all); 1 or 2 for a quick look
};

struct CheckResult {
    double maxGouge = 0;       // deepest penetration of the cutter into the blades and hub (mm)
    int holderCollisions = 0;  // positions where the shank or holder touches the part
    int tilted = 0;            // positions tilted to clear the holder
    int positions = 0;         // cutting positions checked
    double worstAt[3] = {0, 0, 0};
};

struct ImpellerProgram {
    std::vector<Operation> operations;
    CheckResult check;         // over every cutting position, after tilting
};

// Toolpaths for every channel (adjacent pair of blades) of the part: the two kinds of channel
// (main to splitter, splitter to main) are computed and checked once, the others are copies
// turned about the axis by the blade pitch. Throws inputError when a cutter does not fit (a
// ball wider than the channel) or when the part has no channel with both walls along it.
ImpellerProgram impellerToolpaths(const TopoDS_Shape& part, const impeller::ImpellerFeatures& features,
                                  const impeller::ImpellerDimensions& dimensions, const CutterShape& rougher,
                                  const CutterShape& finisher, const PathOptions& options = {});

// Checks cutting positions (not rapids) of `program` against the part's blades and hub: the
// same measure as the generator's check, for a program read back from its posted text.
CheckResult checkProgram(const TopoDS_Shape& part, const impeller::ImpellerFeatures& features,
                         const std::vector<std::pair<CutterShape, std::vector<Move>>>& operations);

// The CL program: one operation per toolpath, tool changes, spindle, feeds, every move with its
// tip (centre − tip radius · axis) and axis, retracts between passes as rapids.
kinematics::ClProgram toClProgram(const ImpellerProgram& program, const std::string& name);

// Moves of each operation of a CL program (an APT file read back): centre = tip + radius · axis.
std::vector<std::pair<CutterShape, std::vector<Move>>> movesOf(const kinematics::ClProgram& cl,
                                                               const std::vector<CutterShape>& cutters);

}  // namespace aeronc::impellerpath
