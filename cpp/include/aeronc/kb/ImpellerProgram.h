#pragma once
// One impeller program from its process route (docs/impeller.md §5-§6): the route's cutters with
// their tool numbers, the toolpaths of every step with their checks, and the cutting data of
// each tool. The command line (aeronc impeller-program), the Python module (_core.impeller_program)
// and FreeCAD's Program impeller all make their program here, so they agree on every number.
//
// Cutting data: the 5-axis tools (channel roughing, blade, hub and fillet finishing) take the
// cutting-parameter optimiser's answer for the engagement of their own toolpaths, as Optimise
// cutting does for a Job; facing, drilling and boring, single plain passes, take the knowledge
// base's cutting condition (n = 1000·v_c/(π·D), f_z·Z·n), capped at the machine's limits.
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/impeller/ProcessRoute.h>
#include <aeronc/impellerpath/AxialOperations.h>
#include <aeronc/impellerpath/ImpellerToolpaths.h>
#include <aeronc/kb/KnowledgeBase.h>

#include <TopoDS_Shape.hxx>

#include <map>
#include <string>
#include <vector>

namespace aeronc::kb {

struct ImpellerProgramOptions {
    std::string material = "7050-T7451";
    std::string machine = "AC-5AX";     // its spindle speed and feed limits
    // Stations, channels, steps and clearances of the toolpaths; the roughing allowance is the
    // route's channel roughing step's.
    impellerpath::PathOptions paths;
};

// The cutting data of one tool for every step it cuts (one ToolController, one tool change).
struct ToolCutting {
    std::string tool;
    std::string operation;                // the knowledge base's: roughing, finishing, drilling
    double rpm = 0, feed = 0, plungeFeed = 0;  // r/min, mm/min
    double fz = 0;                        // mm per tooth
    double ap = 0, ae = 0;                // the engagement the speeds were chosen for (mm)
    double length = 0;                    // cut length of its steps (mm)
    std::vector<std::string> active;      // the limits active at the optimum ("knowledge base": none sought)
    double kbFz = 0, kbVc = 0;            // the knowledge base's cutting condition
    std::vector<int> steps;               // route positions
};

struct ImpellerProgramming {
    std::map<int, int> toolNumbers;               // route position -> tool number
    impellerpath::ImpellerProgram fiveAxis;       // its cutters carry their tool's cutting data
    impellerpath::CheckResult rapids;             // the 5-axis rapids against the blank
    impellerpath::AxialProgram axial;             // turning, facing, drilling, boring (front and back)
    std::vector<ToolCutting> cutting;             // per tool: the axial tools, then the 5-axis ones
    double toolpathSeconds = 0, cuttingSeconds = 0;  // wall time of the toolpaths (with their checks), of the cutting data
};

// Tool numbers in route order, one per distinct tool: route position -> number.
std::map<int, int> impellerToolNumbers(const std::vector<impeller::RouteStep>& steps);

// What programImpeller refuses before it reads any geometry: throws inputError for an unknown
// material or machine, stations outside 2 to 200, a route without channel roughing or blade
// finishing, a tool of the wrong kind for its step, a negative allowance.
void checkImpellerProgram(const std::vector<impeller::RouteStep>& steps, const KnowledgeBase& kb,
                          const ImpellerProgramOptions& options);

// The program of `steps` (the route as planned, or as the user edited it: tools and allowances).
// Throws inputError for a route without channel roughing or blade finishing, a tool of the wrong
// kind for its step (a ball or tapered ball for the channels and fillets, a flat-bottomed tool
// for facing, drilling and boring), an unknown material or machine, and what the toolpaths and
// the optimiser refuse.
ImpellerProgramming programImpeller(const TopoDS_Shape& part, const impeller::ImpellerFeatures& features,
                                    const impeller::ImpellerDimensions& dimensions,
                                    const std::vector<impeller::RouteStep>& steps, const KnowledgeBase& kb,
                                    const ImpellerProgramOptions& options = {});

}  // namespace aeronc::kb
