#pragma once
// A small part known by construction, with a tool plan written by hand, for the chain tests:
//   setup +Z: element 0, a 100 x 60 pocket (floor z = 5, top 20, corner radius 6);
//             element 1, a 40 x 20 pocket in its floor (floor z = 0, corner radius 6);
//             element 2, a 6.6 mm through hole in element 0's floor at (80, 30);
//   setup -Z: element 3, a 50 x 30 pocket from z = 0 to z = 4 (corner radius 6).
// Tools: R20 (flat 20, roughing), F10 (flat 10), F8, F4, DR-6.6; cutting data for each.
#include <aeronc/chain/Fusing.h>
#include <aeronc/kb/KnowledgeBase.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace aeronc::test {

inline toolselect::Tool makeTool(const std::string& id, const std::string& type, double d, double flute, double reach) {
    toolselect::Tool t;
    t.id = id;
    t.type = type;
    t.material = "carbide";
    t.diameter = d;
    t.flutes = type == "drill" ? 2 : 3;
    t.fluteLength = flute;
    t.reach = reach;
    return t;
}

inline recognition::Polyline rectangle(double x0, double y0, double x1, double y1, double z) {
    return {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
}

inline recognition::DomainElement pocket(int id, int setup, int parent, double level, double top,
                                         const recognition::Polyline& contour, double minWidth) {
    recognition::DomainElement e;
    e.id = id;
    e.setup = setup;
    e.parent = parent;
    e.type = recognition::ElementType::ClosedPocket;
    e.level = level;
    e.top = top;
    e.depth = top - level;
    e.minWidth = minWidth;
    e.minCornerRadius = 6;
    e.floorFilletRadius = 0;
    e.contour = contour;
    e.floorFaces = {100 + id};
    return e;
}

inline recognition::DomainTree smallTree() {
    recognition::DomainTree t;
    t.setups = {{0, {0, 0, 1}, "+Z", {0}}, {1, {0, 0, -1}, "-Z", {3}}};
    t.elements.push_back(pocket(0, 0, -1, 5, 20, rectangle(0, 0, 100, 60, 5), 60));
    t.elements.push_back(pocket(1, 0, 0, 0, 20, rectangle(10, 20, 50, 40, 0), 20));
    recognition::DomainElement h;
    h.id = 2;
    h.setup = 0;
    h.parent = 0;
    h.type = recognition::ElementType::Hole;
    h.level = 0;
    h.top = 5;
    h.depth = 5;
    h.minWidth = 6.6;
    h.minCornerRadius = 3.3;
    recognition::HoleInfo hi;
    hi.diameter = 6.6;
    hi.depth = 5;
    hi.through = true;
    hi.location = {80, 30, 5};
    h.hole = hi;
    for (int k = 0; k < 16; ++k) {
        const double a = 2 * 3.14159265358979323846 * k / 16;
        h.contour.push_back({80 + 3.3 * std::cos(a), 30 + 3.3 * std::sin(a), 0});
    }
    t.elements.push_back(h);
    t.elements.push_back(pocket(3, 1, -1, -4, 0, rectangle(20, 10, 70, 40, 4), 30));
    t.elements[0].children = {1, 2};
    return t;
}

inline toolselect::ToolPlan smallPlan() {
    toolselect::ToolPlan p;
    p.tools = {makeTool("R20", "flat", 20, 40, 60), makeTool("F10", "flat", 10, 30, 50), makeTool("F8", "flat", 8, 25, 40),
               makeTool("F4", "flat", 4, 12, 20), makeTool("DR-6.6", "drill", 6.6, 63, 73)};
    auto choice = [](int e, int finish, int rough) {
        toolselect::ElementChoice c;
        c.element = e;
        c.finishingTool = finish;
        c.roughingTool = rough;
        c.ratio.eta = 0.95;
        return c;
    };
    p.elements = {choice(0, 1, 0), choice(1, 1, 1), choice(3, 1, 0)};
    toolselect::HoleChoice h;
    h.element = 2;
    h.diameter = 6.6;
    h.depth = 5;
    h.drill = 4;
    p.holes = {h};
    p.groupsAfter = {{0, {0, 3}}, {1, {1}}};
    auto setting = [](int tool, const char* op, double d, double ap) {
        toolselect::ToolSetting s;
        s.tool = tool;
        s.operation = op;
        s.spindleRpm = 1000 * 300 / (3.14159265358979323846 * d);
        s.feedMmMin = 0.05 * 3 * s.spindleRpm;
        s.plungeFeedMmMin = 0.3 * s.feedMmMin;
        s.ap = ap;
        s.ae = std::string(op) == "finishing" ? 0.1 * d : 0.5 * d;
        return s;
    };
    p.settings = {setting(0, "roughing", 20, 5), setting(1, "roughing", 10, 3), setting(1, "finishing", 10, 1),
                  setting(2, "finishing", 8, 1),  setting(3, "roughing", 4, 1),  setting(3, "finishing", 4, 0.5),
                  setting(4, "drilling", 6.6, 5)};
    return p;
}

// The shipped integral-panel template, written out as the knowledge base holds it.
inline chain::TemplateRows panelRows() {
    chain::TemplateRows r;
    r.name = "integral_panel";
    r.family = "integral_panel";
    r.requiredSteps = "r w fs";
    r.stepOrderName = "standard";
    r.stepOrder = "r w c ss sf fs ff d h t";
    r.steps = {
        {1, "r", "must", "closed_pocket open_pocket flange opening", "roughing", 1.0, 0.5, ""},
        {2, "w", "must", "closed_pocket open_pocket flange", "finishing", 0.5, 0.0, ""},
        {3, "c", "may", "closed_pocket open_pocket flange opening", "corner", 0.5, 0.0, ""},
        {4, "ss", "may", "closed_pocket open_pocket opening", "finishing", 0.2, 0.0, ""},
        {5, "sf", "may", "flange", "finishing", 0.2, 0.0, ""},
        {6, "fs", "must", "closed_pocket open_pocket opening", "finishing", 0.0, 0.0, ""},
        {7, "ff", "may", "flange", "finishing", 0.0, 0.0, ""},
        {8, "d", "may", "hole", "drilling", 0.0, 0.0, ""},
        {9, "h", "may", "hole", "finishing", 0.0, 0.0, ""},
    };
    r.rules = {{1, "process_order", "order=larger_tool_first", true},
               {2, "outer_before_inner", "outer=open_pocket,flange", true},
               {3, "higher_z_first", "", true},
               {4, "feature_type_order", "order=open_pocket,closed_pocket,flange,opening,hole", true},
               {5, "centre_out", "", true}};
    return r;
}

inline chain::ChainOptions smallOptions() {
    chain::ChainOptions o;
    o.material = "7050-T7451";
    o.machine = "AC-5AX";
    return o;
}

inline chain::MachiningChain smallChain() {
    return chain::buildChain(smallTree(), smallPlan(), chain::parseTemplate(panelRows()), smallOptions());
}

// A knowledge base built from the shipped SQL in a folder of its own.
class KbDir {
public:
    explicit KbDir(const std::string& name)
        : dir_(std::filesystem::temp_directory_path() / ("aeronc_chain_" + std::to_string(::getpid()) + "_" + name)) {
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    ~KbDir() { std::filesystem::remove_all(dir_); }
    kb::KnowledgeBase open() const {
        return kb::KnowledgeBase::openWithSqlFolder((dir_ / "kb.sqlite").string(), [] {
            return (std::filesystem::path(AERONC_RESOURCES) / "kb").string();
        });
    }

private:
    std::filesystem::path dir_;
};

}  // namespace aeronc::test
