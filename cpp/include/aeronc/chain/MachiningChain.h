#pragma once
// The NC machining chain (the patent's 数控加工链): the process plan's seven levels
// part -> machine -> setup -> process -> step -> program -> tool, with the machining units
// under the tool nodes as the eighth. Geometry is 2-D in each setup's frame (u, v), heights
// along its tool axis w, all in mm; docs/machining-chain.md describes every field.
#include <aeronc/chain/ProcessTemplate.h>
#include <aeronc/core/Vec3.h>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace aeronc::chain {

using Point2 = std::array<double, 2>;  // (u, v)
using Loop = std::vector<Point2>;      // closed, the first point not repeated

struct Cutter {
    double diameter = 0;
    double cornerRadius = 0;
    std::string type;  // flat, bull, ball, drill, chamfer
    double tipDiameter = 0;    // chamfer mill
    double includedAngle = 0;  // chamfer mill, degrees
};

// Spindle speed and feeds of the unit's tool in its operation.
struct Setting {
    double spindleRpm = 0;
    double feedMmMin = 0;
    double plungeFeedMmMin = 0;
};

struct HoleTarget {
    double u = 0, v = 0;
    double diameter = 0;
    double top = 0, bottom = 0;  // heights along w; bottom includes the breakthrough of a through hole
    bool through = false;
    // A blind hole's fillet between wall and floor: the cutter keeps out of it near the floor.
    double floorFilletRadius = 0;
};

// One machining unit: a region of one element, one operation, one tool.
struct MachiningUnit {
    int id = -1;
    int setup = -1;
    int element = -1;
    StepCode step = StepCode::Rough;
    Operation operation = Operation::Pocket;
    std::string featureType;
    std::string tool;
    int toolNumber = 0;
    Cutter cutter;
    std::optional<Cutter> previousCutter;  // rest: the cutter that went before
    std::optional<double> previousAllowance;  // rest: the radial allowance that cutter left
    Setting setting;
    double top = 0, bottom = 0;  // heights along w
    std::optional<double> stockTop;  // the material may stand this high over the unit (StockTops.h)
    Loop contour;                // drive loop at the floor (counter-clockwise)
    std::vector<Loop> islands;   // island loops (clockwise)
    // Per island (empty: none): the height of its top where it stops short of the element's
    // cavity, NaN where it stands through the unit. Above it the island is material to clear.
    std::vector<double> islandTops;
    bool faceIslandTops = false;  // a floor unit: the lower island tops are floors of it too
    std::vector<std::array<Point2, 2>> openEdges;  // stretches of the contour open to the blank
    std::vector<HoleTarget> holes;
    // A chamfer unit (Operation::Chamfer): the mill's axis runs this far from the drive loop (the
    // chamfer's lower line), on the pocket's side, its tip at `bottom` (toolselect/EdgeTools.h).
    double edgeOffset = 0;
    double radialAllowance = 0, axialAllowance = 0;
    double floorFilletRadius = 0;  // the element's: the toolpath keeps the cutter out of it
    double stepDown = 0;  // the knowledge base's a_p for the tool
    double stepOver = 0;  // a_e
    Point2 at{0, 0};      // where rapid travel to and from the unit is measured
    std::optional<double> eta;  // machinable ratio of the tool in the element (pocket, rest)
    std::string note;           // why this operation, when it is not the obvious one
    // A roughing that stops short of the element's floor (deeper than every end mill reaches):
    // nothing below relies on it, and left out it takes nothing with it.
    bool shortOfFloor = false;
    bool enabled = true;
    int order = -1;  // position in MachiningChain::order
};

struct ChainProgram {
    std::string tool;
    std::vector<int> units;
};
struct ChainStep {
    StepCode code = StepCode::Rough;
    std::vector<ChainProgram> programs;
};
// The steps done on one machine with one tool in one clamping, back to back.
struct ChainProcess {
    int id = -1;
    std::string machine;
    std::string tool;
    std::vector<ChainStep> steps;
};
struct ChainSetup {
    int id = -1;
    std::string name;
    Vec3 direction{0, 0, 1};
    Vec3 u{1, 0, 0}, v{0, 1, 0}, w{0, 0, 1};  // the frame the units' geometry is in
    std::optional<double> blankTop;  // the blank's highest corner along w, when recognition gave it
    std::vector<ChainProcess> processes;
};

// What the rules need to know of a domain element.
struct ChainElement {
    int id = -1;
    int setup = -1;
    int parent = -1;
    std::string featureType;
    double level = 0, top = 0, depth = 0;
    double minWidth = 0;
    double minCornerRadius = -1;  // < 0: no concave corner
    double floorFilletRadius = 0;
    int narrowPassages = 0;  // passages narrower than the roughing tool (toolselect::MachinableRatio)
    std::optional<double> holeDiameter;
};

struct ToolData {
    double spindleRpm = 0, feedMmMin = 0, plungeFeedMmMin = 0;
    double ap = 0, ae = 0;
};

struct ChainTool {
    std::string id, type, material;
    double diameter = 0, cornerRadius = 0, fluteLength = 0, reach = 0;
    double neckDiameter = 0;  // 0: no neck (toolselect::Tool)
    double tipDiameter = 0, includedAngle = 0;  // a chamfer mill (type "chamfer")
    int flutes = 0;
    int number = 0;  // T number in the chain's order of first use; 0: not used
    std::map<std::string, ToolData> settings;  // by operation: roughing, finishing, drilling
    // As toolselect::Tool::usableLength: a necked tool reaches its reach, another its flutes.
    double usableLength() const { return neckDiameter > 0 || fluteLength >= reach ? reach : fluteLength; }
};

struct RuleCheck {
    std::string rule;  // priority, existence, validity, removal, fit
    std::string node;  // the node at fault ("chain" for a rule that holds everywhere)
    bool ok = true;
    std::string message;
};

struct Unmachined {
    int element = -1;
    std::optional<StepCode> step;  // the step that could not machine it; none: nothing could
    std::string reason;
    std::vector<int> faces;  // the faces left when it is not the whole element (FaceN)
};

// What a machined element keeps after its units because no tool of the crib reaches it: a sharp
// or small vertical corner (every wall tool leaves its own radius there) or a floor fillet smaller
// than the corner radius of every end mill reaching the floor. The element is machined; this is
// the part of it left, with the tool it would need. The fit rule accepts the element's wall
// (floor) units whose radius (corner radius) is no larger than `toolRadius`.
struct Remainder {
    int element = -1;
    StepCode step = StepCode::FinishWall;  // the step whose tool leaves it
    std::string kind;                      // "corners", "floor_fillet" or "depth"
    std::string tool;                      // the tool that leaves it
    double toolRadius = 0;  // corners, depth: that tool's radius; floor_fillet: its corner radius, mm
    // The area left, mm² (corners: in plan; floor fillet: the band along the floor's edge; depth:
    // the element's region in plan, under the roughed depth)
    double area = 0;
    double depth = 0;       // how deep it goes (corners: the wall's height; floor fillet: the band's height; depth: below the roughing), mm
    std::string needs;      // the tool it would need
};

struct Travel {
    double rulesOnly = 0;  // rapid travel of the order the sequencing rules alone give, mm
    double optimised = 0;  // of the chain's order
    double savedPercent = 0;
};

struct MachiningChain {
    std::string family, material, machine;
    ProcessTemplate processTemplate;
    std::vector<ChainSetup> setups;
    std::vector<ChainElement> elements;
    std::vector<ChainTool> tools;
    std::vector<MachiningUnit> units;  // units[i].id == i
    std::vector<int> order;            // every unit id once, setup by setup
    Travel travel;
    std::vector<RuleCheck> checks;
    std::vector<Unmachined> unmachined;
    std::vector<Remainder> remainders;

    const ChainTool* tool(const std::string& id) const;
    const ChainElement* element(int id) const;
    const ChainSetup* setup(int id) const;
};

// The operation whose cutting data a unit uses: roughing for r, c, h and t, drilling for d,
// finishing otherwise.
const char* settingOperation(StepCode step);

}  // namespace aeronc::chain
