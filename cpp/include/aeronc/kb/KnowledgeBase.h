#pragma once
// The machining knowledge base: resource facts (machines, materials, tools, cutting data)
// and rule knowledge (thresholds, process templates, sequencing rules) in one SQLite file.
//
// The layout is the reviewable SQL text in resources/kb/schema.sql, the shipped rows are
// resources/kb/default_data.sql. Every write is one transaction; every failure a caller can
// cause or fix (missing folder, corrupt or locked file, unknown material, impossible tool)
// is an aeronc::inputError with a message that says which.
#include <aeronc/kb/FreeCadToolLibrary.h>
#include <aeronc/toolselect/EdgeTools.h>
#include <aeronc/toolselect/Tool.h>

#include <memory>
#include <optional>
#include <functional>
#include <string>
#include <vector>

struct sqlite3;

namespace aeronc::kb {

// Cutting data for one workpiece material x tool material x operation, with the
// coefficients of F_c = 9.81*C_F*a_p^x_F*f_z^y_F*a_e^u_F*Z/(d_0^q_F*n^w_F)*K_Fc and of the
// Taylor tool life v_c*T^m = C.
struct CuttingCondition {
    std::string workpieceMaterial;
    std::string toolMaterial;
    std::string operation;
    std::optional<double> dMin, dMax;  // the tool diameter range of the row; empty: open
    double vc = 0;       // m/min
    double fz = 0;       // mm per tooth
    double ap = 0;       // mm
    double aeRatio = 0;  // a_e / tool diameter
    double cF = 0, xF = 0, yF = 0, uF = 0, qF = 0, wF = 0, kFc = 1;
    double taylorC = 0, taylorM = 0;
};

// A table as the knowledge-base editor shows it: values as text (NULL: empty), with the
// rowid that identifies each row across edits.
struct TableColumn {
    std::string name;
    std::string type;  // declared type: TEXT, REAL, INTEGER
    bool notNull = false;
    bool primaryKey = false;
};
using Cell = std::optional<std::string>;
struct Table {
    std::string name;
    std::vector<TableColumn> columns;
    std::vector<long long> rowIds;
    std::vector<std::vector<Cell>> rows;
};
struct CellEdit {
    long long rowId = 0;
    std::string column;
    Cell value;
};

struct Machine {
    std::string name;
    std::string type;
    std::string kinematics;
    double travelX = 0, travelY = 0, travelZ = 0;  // mm
    std::optional<double> aMin, aMax, cMin, cMax;  // degrees; empty: no such axis
    double maxSpindleRpm = 0;
    double powerKw = 0;
    double maxFeedMmMin = 0;
    double maxForceN = 0;
    double efficiency = 1;
    double toolChangeS = 0;
};

class KnowledgeBase {
public:
    // The schema version this build writes and reads; older files are migrated on open.
    static constexpr int kSchemaVersion = 11;

    // Opens the knowledge base at `path`. A missing file is built from the two SQL texts
    // (under a temporary name, then renamed, so a half-built file is never left at `path`).
    // An existing file from an older schema version is migrated in one transaction, keeping
    // the user's rows; a copy of the old file is kept next to it as `<path>.v<N>.bak`.
    static KnowledgeBase open(const std::string& path, const std::string& schemaSql,
                              const std::string& defaultDataSql);

    // The same, reading schema.sql and default_data.sql from the folder sqlFolder() names,
    // asked only when the file has to be built (missing or empty).
    static KnowledgeBase openWithSqlFolder(const std::string& path, const std::function<std::string()>& sqlFolder);

    KnowledgeBase(KnowledgeBase&&) noexcept;
    KnowledgeBase& operator=(KnowledgeBase&&) noexcept;
    ~KnowledgeBase();

    const std::string& path() const { return path_; }
    int schemaVersion() const;

    // All tools, largest diameter first (ties by id).
    std::vector<toolselect::Tool> tools() const;
    // The chamfer and corner-rounding mills (table edge_tool), smallest diameter first (ties by
    // id), without cutting data. Empty for a file without the table.
    std::vector<toolselect::EdgeTool> edgeTools() const;
    // Validates and inserts one tool; `cost` is optional. Throws inputError naming the tool for
    // impossible dimensions, a duplicate id or an unknown tool material; the database is unchanged.
    void addTool(const toolselect::Tool& tool, std::optional<double> cost = std::nullopt);
    // Inserts all tools or none: one bad tool leaves the database as it was.
    void importTools(const std::vector<toolselect::Tool>& tools);

    // A rule threshold such as "eta_min" or "mu_merge"; throws inputError if unknown.
    double threshold(const std::string& name) const;
    // The same; empty when the knowledge base has no such threshold. A value that is not a
    // finite number, or a damaged file, is still an error.
    std::optional<double> findThreshold(const std::string& name) const;
    // The cutting data for a tool of `toolDiameter` (mm): a row whose diameter range holds it
    // wins over a row without a range. Without a diameter only rows without a range count.
    // Throws inputError for an unknown workpiece or tool material, or a missing combination.
    CuttingCondition cuttingCondition(const std::string& workpieceMaterial, const std::string& toolMaterial,
                                      const std::string& operation,
                                      std::optional<double> toolDiameter = std::nullopt) const;
    // The same; empty when no row covers the combination. Unknown materials, values out of
    // range and a damaged file are still errors.
    std::optional<CuttingCondition> findCuttingCondition(const std::string& workpieceMaterial,
                                                         const std::string& toolMaterial, const std::string& operation,
                                                         std::optional<double> toolDiameter = std::nullopt) const;
    Machine machine(const std::string& name) const;
    std::vector<std::string> workpieceMaterials() const;
    std::vector<std::string> machineNames() const;

    // FreeCAD tool bridge. Imports every bit of `library` as a tool (id: the bit's file name
    // without extension) and the library itself, all or nothing; bit materials are matched to
    // the tool materials ignoring case. Throws inputError naming the bit for a tool id that
    // is already used, impossible dimensions or an unknown material, and for a library name
    // that is already imported. Returns the number of tools added.
    int importFreeCadLibrary(const FreeCadLibrary& library, const BitDefaults& defaults = {});
    std::vector<std::string> freeCadLibraryNames() const;
    // An imported library, its bit documents carrying the tools' current dimensions.
    FreeCadLibrary freeCadLibrary(const std::string& name) const;
    // A library of the given tools numbered 1, 2, ... in that order; tools imported from FreeCAD
    // keep their bit documents, the others get new ones. Throws inputError for an unknown id.
    FreeCadLibrary freeCadLibraryOf(const std::string& name, const std::vector<std::string>& toolIds) const;

    // The tables a user may browse and edit, in the order the editor shows them.
    static const std::vector<std::string>& editableTables();
    Table table(const std::string& name) const;
    // Applies cell edits, then inserts (values in column order), then deletes, in one
    // transaction. Values of REAL and INTEGER columns must be numbers. Throws inputError naming
    // the table, the row and the column, or the rule the database enforces; the database is
    // then unchanged.
    void editTable(const std::string& name, const std::vector<CellEdit>& edits,
                   const std::vector<std::vector<Cell>>& inserts = {}, const std::vector<long long>& deletes = {});

    struct Closer {
        void operator()(sqlite3* db) const;
    };

private:
    KnowledgeBase(std::unique_ptr<sqlite3, Closer> db, std::string path);
    void insertTools(const std::vector<toolselect::Tool>& tools, const std::vector<std::optional<double>>& costs);

    std::unique_ptr<sqlite3, Closer> db_;
    std::string path_;
};

}  // namespace aeronc::kb
