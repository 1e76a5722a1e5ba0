#pragma once
// A tool read from the knowledge base: the one place the tool table's columns become a Tool.
// Internal to cpp/src/kb.
#include <aeronc/toolselect/Tool.h>

#include "Sqlite.h"

namespace aeronc::kb::detail {

// The columns a query selects first, in this order, for toolFromRow.
constexpr const char* kToolColumns = "id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach, neck_diameter";

// Every cell is checked (Statement::real, integer) and the tool validated: a file another
// program wrote may hold anything.
inline toolselect::Tool toolFromRow(Statement& s, const std::string& path) {
    toolselect::Tool t;
    t.id = s.text(0);
    s.about("tool " + quoted(t.id));
    t.type = s.text(1);
    t.material = s.text(2);
    t.diameter = s.real(3);
    t.cornerRadius = s.real(4);
    t.flutes = s.integer(5);
    t.fluteLength = s.real(6);
    t.reach = s.real(7);
    t.neckDiameter = s.optReal(8).value_or(0.0);
    try {
        t.validate();
    } catch (const Error& e) {
        throw inputError("knowledge base " + quoted(path) + ": " + e.what());
    }
    return t;
}

}  // namespace aeronc::kb::detail
