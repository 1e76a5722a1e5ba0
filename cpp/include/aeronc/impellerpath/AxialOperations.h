#pragma once
// The route's steps about and along the impeller's axis (docs/impeller.md §5): turning on the
// lathe, facing the planes, drilling and boring the bore, as plain moves with a fixed tool axis.
// They run before the 5-axis steps, on the blank; every position is checked against the finished
// part (every face of it) with the same distance queries as the 5-axis toolpaths.
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impellerpath/ImpellerToolpaths.h>

#include <TopoDS_Shape.hxx>
#include <optional>
#include <string>
#include <vector>

namespace aeronc::impellerpath {

// The route's tools for these steps. A face mill, drill or flat end mill is a CutterShape with
// tipRadius its radius and flat set (its moves' centre is then tipRadius above the tip, as for a
// ball, so the CL program's tips are right); the turning insert is a ball of its nose radius
// whose shank points away from the part.
struct AxialCutters {
    std::optional<CutterShape> faceMill, drill, boringMill;
    CutterShape turningInsert{"LATHE-R0.8", 9, 0.8, 0, 1.6, 0.8, 30, 2000, 200};
};

// A flat-bottomed tool as a CutterShape: radius, flat; a face mill's body (wider than its
// flutes are long) counts as cutting part up to its radius above the tip.
CutterShape flatCutter(const std::string& id, int number, double diameter, double fluteLength, double reach,
                       double rpm, double feed);

struct AxialOptions {
    double drillAllowance = 0.5;  // radial stock the drill leaves in the bore for boring (mm)
    double helixPitch = 2.0;      // boring: axial advance per turn (mm)
    double turnStep = 0.5;        // spacing of turning and facing positions (mm)
    double safeDistance = 5.0;    // approach and retract above the face being machined (mm)
};

struct AxialProgram {
    // turn, face, drill, bore (those the part has and the tools allow); drill_back, bore_back:
    // what the flutes could not reach from the front, from the back face in a second setup (the
    // part turned over: these moves' axis points against the impeller's)
    std::vector<Operation> operations;
    CheckResult check;                   // over every non-rapid move
    std::vector<std::string> notes;      // what a step could not reach, and why
};

// Toolpaths of the steps: turn (the outer cylinders and the planes, contoured in one meridian
// plane by the insert), face (straight passes of the face mill over each plane it can reach
// without touching the part; a plane it cannot reach is noted, the lathe faces it), drill (down
// the axis through the bore, the drill no wider than the bore less the allowance), bore (a helix
// of the flat end mill at the bore's radius less its own, then a full circle at the bottom);
// drilling and boring go as deep as the flutes reach (the shank, as wide as the cut, would rub
// the finished wall), the rest from the back.
// Throws inputError when a tool does not fit the bore.
AxialProgram axialToolpaths(const TopoDS_Shape& part, const impeller::ImpellerFeatures& features,
                            const impeller::ImpellerDimensions& dimensions, const AxialCutters& cutters,
                            const AxialOptions& options = {});

}  // namespace aeronc::impellerpath
