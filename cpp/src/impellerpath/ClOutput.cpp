// Impeller programs as CL programs and back: tool changes, spindle, feeds, every move's tip
// and axis (see ImpellerToolpaths.h).
#include <aeronc/impellerpath/ImpellerToolpaths.h>

#include <aeronc/core/Error.h>

namespace aeronc::impellerpath {

kinematics::ClProgram toClProgram(const ImpellerProgram& p, const std::string& name) {
    using namespace kinematics;
    ClProgram cl;
    cl.name = name;
    auto add = [&](ClRecord r) {
        r.op = static_cast<int>(cl.operations.size()) - 1;
        cl.records.push_back(r);
    };
    for (const auto& op : p.operations) {
        cl.operations.push_back({op.name});
        ClRecord label;
        label.kind = ClKind::Operation;
        label.text = op.name;
        add(label);
        ClRecord tool;
        tool.kind = ClKind::LoadTool;
        tool.tool = ClTool{op.cutter.number, op.cutter.id, 2 * op.cutter.tipRadius,
                           op.cutter.flat ? 0.0 : op.cutter.tipRadius, 0.0};
        add(tool);
        ClRecord spindle;
        spindle.kind = ClKind::Spindle;
        spindle.rpm = op.cutter.rpm;
        spindle.spindleDir = 1;
        add(spindle);
        ClRecord coolant;
        coolant.kind = ClKind::Coolant;
        coolant.text = "flood";
        add(coolant);
        for (const auto& m : op.moves) {
            ClRecord r;
            r.kind = ClKind::Move;
            r.motion = m.rapid ? Motion::Rapid : Motion::Linear;
            r.axis = m.axis.normalized();
            r.tip = m.centre - op.cutter.tipRadius * r.axis;
            r.feed = m.rapid ? 0.0 : op.cutter.feed;
            add(r);
        }
    }
    return cl;
}

std::vector<std::pair<CutterShape, std::vector<Move>>> movesOf(const kinematics::ClProgram& cl,
                                                               const std::vector<CutterShape>& cutters) {
    using namespace kinematics;
    std::vector<std::pair<CutterShape, std::vector<Move>>> out;
    const CutterShape* current = nullptr;
    int op = -2;
    for (const auto& r : cl.records) {
        if (r.kind == ClKind::LoadTool) {
            current = nullptr;
            for (const auto& c : cutters)
                if (c.number == r.tool.number) current = &c;
            if (!current) throw inputError("impeller program: tool " + std::to_string(r.tool.number) + " is not one of its cutters");
        }
        if (r.kind != ClKind::Move) continue;
        if (!current) throw inputError("impeller program: a move before any tool is loaded (" + cl.where(r) + ")");
        if (r.op != op || out.empty() || out.back().first.number != current->number) {
            out.push_back({*current, {}});
            op = r.op;
        }
        const kinematics::Vec3 axis = r.axis.normalized();
        out.back().second.push_back(Move{r.tip + current->tipRadius * axis, axis, r.motion == Motion::Rapid});
    }
    return out;
}

}  // namespace aeronc::impellerpath
