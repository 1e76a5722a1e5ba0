// Generic table access for the knowledge-base editor.
#include <aeronc/kb/KnowledgeBase.h>

#include "Sqlite.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace aeronc::kb {

using namespace detail;

namespace {

bool numeric(const std::string& type) {
    std::string t = type;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::toupper(c); });
    return t.find("INT") != std::string::npos || t.find("REAL") != std::string::npos;
}

std::vector<TableColumn> columnsOf(sqlite3* db, const std::string& path, const std::string& table) {
    Statement s(db, path, ("PRAGMA table_info(" + quoted(table) + ")").c_str());
    std::vector<TableColumn> out;
    while (s.step("reading the layout of " + table)) out.push_back({s.text(1), s.text(2), s.integer(3) != 0, s.integer(5) != 0});
    return out;
}

void checkTable(const std::string& name) {
    const auto& t = KnowledgeBase::editableTables();
    if (std::find(t.begin(), t.end(), name) == t.end())
        throw inputError("knowledge base: no editable table " + quoted(name) + " (tables: " + joined(t) + ")");
}

// Binds a cell: numbers for numeric columns (text there would slip past CHECKs), else text.
void bindCell(Statement& s, int i, const Cell& v, const TableColumn& c, const std::string& where) {
    if (!v || v->empty()) {
        s.bindNull(i);
        return;
    }
    if (!numeric(c.type)) {
        s.bind(i, *v);
        return;
    }
    const char* b = v->c_str();
    char* e = nullptr;
    const double x = std::strtod(b, &e);
    while (e && std::isspace(static_cast<unsigned char>(*e))) ++e;
    if (e == b || *e != '\0' || !std::isfinite(x))
        throw inputError(where + ", column " + c.name + ": '" + *v + "' is not a number");
    std::string t = c.type;
    std::transform(t.begin(), t.end(), t.begin(), [](unsigned char ch) { return std::toupper(ch); });
    if (t.find("INT") == std::string::npos) {
        s.bind(i, x);
        return;
    }
    if (x != std::floor(x) || std::fabs(x) > 9e15)
        throw inputError(where + ", column " + c.name + ": '" + *v + "' is not a whole number");
    s.bindInt64(i, static_cast<long long>(x));
}

}  // namespace

const std::vector<std::string>& KnowledgeBase::editableTables() {
    static const std::vector<std::string> t = {"tool", "cutting_condition", "machine", "workpiece_material",
                                               "tool_material", "threshold", "part_family", "step_order",
                                               "process_template", "template_step", "sequencing_rule",
                                               "tapered_ball_tool", "impeller_route_step", "edge_tool"};
    return t;
}

Table KnowledgeBase::table(const std::string& name) const {
    checkTable(name);
    Table t;
    t.name = name;
    t.columns = columnsOf(db_.get(), path_, name);
    Statement s(db_.get(), path_, ("SELECT rowid, * FROM " + name + " ORDER BY rowid").c_str());
    while (s.step("reading table " + name)) {
        t.rowIds.push_back(sqlite3_column_int64(s.raw(), 0));
        std::vector<Cell> row;
        for (std::size_t c = 0; c < t.columns.size(); ++c) {
            const int col = static_cast<int>(c) + 1;
            if (s.isNull(col)) row.emplace_back(std::nullopt);
            else if (sqlite3_column_type(s.raw(), col) == SQLITE_FLOAT) {
                // Shortest text that reads back to the same double.
                const double x = sqlite3_column_double(s.raw(), col);  // inf too: the editor shows it
                char buf[32];
                for (int prec = 6; prec <= 17; ++prec) {
                    std::snprintf(buf, sizeof buf, "%.*g", prec, x);
                    if (std::strtod(buf, nullptr) == x) break;
                }
                row.emplace_back(buf);
            } else row.emplace_back(s.text(col));
        }
        t.rows.push_back(std::move(row));
    }
    return t;
}

void KnowledgeBase::editTable(const std::string& name, const std::vector<CellEdit>& edits,
                              const std::vector<std::vector<Cell>>& inserts, const std::vector<long long>& deletes) {
    checkTable(name);
    sqlite3* db = db_.get();
    const auto columns = columnsOf(db, path_, name);
    auto column = [&](const std::string& c) -> const TableColumn& {
        for (const auto& k : columns)
            if (k.name == c) return k;
        throw inputError("knowledge base: table " + name + " has no column " + quoted(c));
    };
    // A row's first column (its id or name) says which row a message is about.
    auto rowName = [&](long long rowId) {
        Statement s(db, path_, ("SELECT " + columns.front().name + " FROM " + name + " WHERE rowid = ?").c_str());
        s.bindInt64(1, rowId);
        if (!s.step()) throw inputError("knowledge base: table " + name + " has no row " + std::to_string(rowId));
        return "table " + name + ", row " + quoted(s.text(0));
    };
    auto failed = [&](const std::string& where) {
        const int ext = sqlite3_extended_errcode(db);
        std::string why = sqlite3_errmsg(db);
        if (ext == SQLITE_CONSTRAINT_CHECK) why = "the value breaks the rule " + why;
        else if (ext == SQLITE_CONSTRAINT_FOREIGNKEY) why = "it refers to a row that does not exist, or other rows refer to it";
        else if (ext == SQLITE_CONSTRAINT_UNIQUE || ext == SQLITE_CONSTRAINT_PRIMARYKEY) why = "the value is already used";
        else if (ext == SQLITE_CONSTRAINT_NOTNULL) why = "a required value is empty";
        throw inputError("knowledge base: " + where + ": " + why + "; nothing was changed");
    };

    Transaction tx(db, path_, "editing table " + name);
    for (const CellEdit& e : edits) {
        const TableColumn& c = column(e.column);
        const std::string where = rowName(e.rowId) + ", column " + c.name;
        Statement s(db, path_, ("UPDATE " + name + " SET \"" + c.name + "\" = ? WHERE rowid = ?").c_str());
        bindCell(s, 1, e.value, c, rowName(e.rowId));
        s.bindInt64(2, e.rowId);
        if (s.tryStep() != SQLITE_DONE) failed(where);
    }
    for (const auto& row : inserts) {
        if (row.size() != columns.size())
            throw inputError("knowledge base: a new row of " + name + " needs " + std::to_string(columns.size()) +
                             " values, got " + std::to_string(row.size()));
        std::string cols, marks;
        for (const auto& c : columns) cols += (cols.empty() ? "\"" : ", \"") + c.name + "\"", marks += marks.empty() ? "?" : ", ?";
        Statement s(db, path_, ("INSERT INTO " + name + " (" + cols + ") VALUES (" + marks + ")").c_str());
        const std::string where = "table " + name + ", new row " + quoted(row.front().value_or(""));
        for (std::size_t i = 0; i < columns.size(); ++i) {
            // An empty INTEGER PRIMARY KEY is numbered by SQLite.
            bindCell(s, static_cast<int>(i) + 1, row[i], columns[i], where);
        }
        if (s.tryStep() != SQLITE_DONE) failed(where);
    }
    for (long long id : deletes) {
        const std::string where = rowName(id);
        Statement s(db, path_, ("DELETE FROM " + name + " WHERE rowid = ?").c_str());
        s.bindInt64(1, id);
        if (s.tryStep() != SQLITE_DONE) failed(where + " (delete)");
    }
    tx.commit();
}

}  // namespace aeronc::kb
