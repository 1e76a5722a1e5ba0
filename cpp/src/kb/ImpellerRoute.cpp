#include <aeronc/kb/ImpellerRoute.h>

#include <aeronc/core/Error.h>

#include <cstdlib>

namespace aeronc::kb {

namespace {

// Cells of a table read through the editor's interface, by column name.
struct Columns {
    const Table& t;
    const Cell& at(std::size_t row, const std::string& column) const {
        for (std::size_t c = 0; c < t.columns.size(); ++c)
            if (t.columns[c].name == column) return t.rows[row][c];
        throw inputError("knowledge base: table " + t.name + " has no column '" + column + "'");
    }
    std::string text(std::size_t row, const std::string& column) const { return at(row, column).value_or(""); }
    double number(std::size_t row, const std::string& column) const {
        const std::string v = text(row, column);
        return v.empty() ? 0.0 : std::strtod(v.c_str(), nullptr);
    }
};

}  // namespace

std::vector<impeller::RouteRule> impellerRouteRules(const KnowledgeBase& kb, const std::string& route) {
    const Table t = kb.table("impeller_route_step");
    const Columns c{t};
    std::vector<impeller::RouteRule> out;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        if (c.text(r, "route") != route) continue;
        impeller::RouteRule rule;
        rule.position = static_cast<int>(c.number(r, "position"));
        rule.operation = c.text(r, "operation");
        rule.toolRule = c.text(r, "tool_rule");
        rule.strategy = c.text(r, "strategy");
        rule.description = c.text(r, "description");
        rule.allowance = c.number(r, "allowance");
        rule.clearance = c.number(r, "clearance");
        out.push_back(rule);
    }
    if (out.empty())
        throw inputError("knowledge base: no impeller route '" + route + "' in table impeller_route_step");
    return out;
}

std::vector<impeller::CuttingTool> impellerTools(const KnowledgeBase& kb) {
    std::vector<impeller::CuttingTool> out;
    for (const auto& t : kb.tools()) {
        if (t.type == "other") continue;
        impeller::CuttingTool c;
        c.id = t.id, c.type = t.type, c.material = t.material, c.diameter = t.diameter;
        c.reach = t.reach, c.fluteLength = t.fluteLength, c.flutes = t.flutes, c.shankDiameter = t.diameter;
        out.push_back(c);
    }
    const Table t = kb.table("tapered_ball_tool");
    const Columns col{t};
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
        impeller::CuttingTool c;
        c.id = col.text(r, "id");
        c.type = "tapered_ball";
        c.material = col.text(r, "tool_material");
        c.diameter = col.number(r, "tip_diameter");
        c.taperDeg = col.number(r, "taper_deg");
        c.reach = col.number(r, "reach");
        c.fluteLength = col.number(r, "flute_length");
        c.flutes = static_cast<int>(col.number(r, "flutes"));
        c.shankDiameter = col.number(r, "shank_diameter");
        out.push_back(c);
    }
    return out;
}

impeller::ProcessRoute planImpellerRoute(const KnowledgeBase& kb, const impeller::ImpellerFeatures& features,
                                         const impeller::ImpellerDimensions& dimensions, const std::string& route) {
    return impeller::planRoute(features, dimensions, impellerRouteRules(kb, route), impellerTools(kb));
}

}  // namespace aeronc::kb
