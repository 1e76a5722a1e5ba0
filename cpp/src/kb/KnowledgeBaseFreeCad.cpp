// The knowledge base's side of the FreeCAD tool bridge (see FreeCadToolLibrary.h).
#include <aeronc/kb/KnowledgeBase.h>

#include "Sqlite.h"
#include "ToolRow.h"

#include <algorithm>
#include <cctype>

namespace aeronc::kb {

using namespace detail;
using toolselect::Tool;

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

struct StoredTool {
    Tool tool;
    std::optional<double> overallLength;
    std::optional<std::string> bitFile, bitDocument;
};

StoredTool storedTool(sqlite3* db, const std::string& path, const std::string& id) {
    Statement s(db, path,
                (std::string("SELECT ") + kToolColumns +
                 ", overall_length, b.file_name, b.document FROM tool "
                 "LEFT JOIN freecad_tool_bit b ON b.tool_id = tool.id WHERE tool.id = ?")
                    .c_str());
    s.bind(1, id);
    if (!s.step("reading a tool")) notFound(db, path, "knowledge base " + quoted(path) + ": unknown tool " + quoted(id));
    StoredTool out;
    out.tool = toolFromRow(s, path);
    out.overallLength = s.optReal(9);
    if (!s.isNull(10)) out.bitFile = s.text(10), out.bitDocument = s.text(11);
    return out;
}

FreeCadBit bitOf(const StoredTool& st, int nr) {
    FreeCadBit b;
    b.nr = nr;
    if (st.bitDocument) {
        b.fileName = *st.bitFile;
        b.document = bitWithTool(*st.bitDocument, st.tool, st.overallLength);
    } else {
        b.fileName = bitFileNameFor(st.tool.id);
        b.document = newBitFor(st.tool, st.overallLength);
    }
    return b;
}

}  // namespace

int KnowledgeBase::importFreeCadLibrary(const FreeCadLibrary& library, const BitDefaults& defaults) {
    sqlite3* db = db_.get();
    const std::string who = "FreeCAD library " + quoted(library.name);
    const auto materials = names(db, path_, "SELECT name FROM tool_material ORDER BY name");
    auto material = [&](const std::string& m, const std::string& bit) {
        for (const auto& known : materials)
            if (lower(known) == lower(m)) return known;
        throw inputError(who + ": bit " + bit + ": unknown tool material " + quoted(m) + " (known: " +
                         joined(materials) + "); nothing was imported");
    };
    // Check everything before touching the file.
    std::vector<BitTool> tools;
    for (const FreeCadBit& b : library.bits) {
        BitTool bt = toolFromBit(b, defaults);
        bt.tool.material = material(bt.tool.material, b.fileName);
        try {
            bt.tool.validate();
        } catch (const Error& e) {
            throw inputError(who + ": bit " + b.fileName + ": " + e.what() + "; nothing was imported");
        }
        tools.push_back(bt);
    }

    Transaction tx(db, path_, "importing " + who);
    {
        Statement s(db, path_, "INSERT INTO freecad_tool_library (name, version, document) VALUES (?, ?, ?)");
        s.bind(1, library.name).bind(2, library.version).bind(3, library.document);
        if (s.tryStep() != SQLITE_DONE)
            throw inputError(who + " is already in the knowledge base " + quoted(path_) +
                             " (remove it first, or import under another file name)");
    }
    Statement addTool(db, path_,
                      "INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, "
                      "reach, overall_length) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)");
    Statement addBit(db, path_, "INSERT INTO freecad_tool_bit (tool_id, file_name, document) VALUES (?, ?, ?)");
    Statement addEntry(db, path_, "INSERT INTO freecad_tool_library_entry (library, nr, tool_id) VALUES (?, ?, ?)");
    for (std::size_t i = 0; i < tools.size(); ++i) {
        const Tool& t = tools[i].tool;
        const FreeCadBit& b = library.bits[i];
        addTool.reset();
        addTool.bind(1, t.id).bind(2, t.type).bind(3, t.material).bind(4, t.diameter).bind(5, t.cornerRadius);
        addTool.bind(6, t.flutes).bind(7, t.fluteLength).bind(8, t.reach).bind(9, tools[i].overallLength);
        const int rc = addTool.tryStep();
        if (rc != SQLITE_DONE) {
            const int ext = sqlite3_extended_errcode(db);
            if (ext == SQLITE_CONSTRAINT_PRIMARYKEY || ext == SQLITE_CONSTRAINT_UNIQUE)
                throw inputError(who + ": bit " + b.fileName + ": a tool with id " + quoted(t.id) +
                                 " already exists; nothing was imported");
            throw inputError(who + ": bit " + b.fileName + ": rejected by the knowledge base (" +
                             sqlite3_errmsg(db) + "); nothing was imported");
        }
        addBit.reset();
        addBit.bind(1, t.id).bind(2, b.fileName).bind(3, b.document);
        addBit.step("storing bit " + b.fileName);
        addEntry.reset();
        addEntry.bind(1, library.name).bind(2, b.nr).bind(3, t.id);
        addEntry.step("storing tool number " + std::to_string(b.nr));
    }
    tx.commit();
    return static_cast<int>(tools.size());
}

std::vector<std::string> KnowledgeBase::freeCadLibraryNames() const {
    return names(db_.get(), path_, "SELECT name FROM freecad_tool_library ORDER BY name");
}

FreeCadLibrary KnowledgeBase::freeCadLibrary(const std::string& name) const {
    sqlite3* db = db_.get();
    Statement lib(db, path_, "SELECT version, document FROM freecad_tool_library WHERE name = ?");
    lib.bind(1, name);
    if (!lib.step("reading a FreeCAD library"))
        notFound(db, path_, "knowledge base " + quoted(path_) + ": no FreeCAD library " + quoted(name) + " (known: " +
                         joined(freeCadLibraryNames()) + ")");
    FreeCadLibrary out;
    out.name = name;
    lib.about("FreeCAD library " + quoted(name));
    out.version = lib.integer(0);
    out.document = lib.text(1);
    Statement e(db, path_, "SELECT nr, tool_id FROM freecad_tool_library_entry WHERE library = ? ORDER BY nr");
    e.bind(1, name);
    std::vector<std::pair<int, std::string>> entries;
    while (e.step("reading a FreeCAD library")) entries.emplace_back(e.integer(0), e.text(1));
    for (const auto& [nr, id] : entries) out.bits.push_back(bitOf(storedTool(db, path_, id), nr));
    return out;
}

FreeCadLibrary KnowledgeBase::freeCadLibraryOf(const std::string& name, const std::vector<std::string>& toolIds) const {
    FreeCadLibrary out;
    out.name = name;
    int nr = 0;
    for (const std::string& id : toolIds) out.bits.push_back(bitOf(storedTool(db_.get(), path_, id), ++nr));
    return out;
}

}  // namespace aeronc::kb
