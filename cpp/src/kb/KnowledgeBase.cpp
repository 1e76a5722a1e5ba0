#include <aeronc/core/Error.h>
#include <aeronc/kb/KnowledgeBase.h>

#include "Sqlite.h"
#include "ToolRow.h"

// kMigrations: one step per old schema version, the SQL of resources/kb/migrations/v<N>_to_v<N+1>.sql
// that turns a version-N database into a version-(N+1) one, embedded at build time
// (cpp/cmake/EmbedSql.cmake). All steps from the file's version up run in one transaction, then
// schema_version is set to KnowledgeBase::kSchemaVersion. Steps must keep user rows.
#include "KbMigrations.h"

#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <utility>

namespace fs = std::filesystem;

namespace aeronc::kb {

using toolselect::Tool;
using namespace detail;

namespace {

// Wait this long for another connection's lock before reporting "locked".
constexpr int kBusyTimeoutMs = 250;

std::unique_ptr<sqlite3, KnowledgeBase::Closer> openConnection(const std::string& path, int flags) {
    sqlite3* raw = nullptr;
    const int rc = sqlite3_open_v2(path.c_str(), &raw, flags | SQLITE_OPEN_NOMUTEX, nullptr);
    std::unique_ptr<sqlite3, KnowledgeBase::Closer> db(raw);
    if (rc != SQLITE_OK) fail(raw, rc, path, "opening");
    sqlite3_extended_result_codes(raw, 1);
    sqlite3_busy_timeout(raw, kBusyTimeoutMs);
    exec(raw, path, "PRAGMA foreign_keys = ON", "enabling foreign keys");
    return db;
}

bool hasTable(sqlite3* db, const std::string& path, const char* name) {
    Statement s(db, path, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?");
    s.bind(1, std::string(name));
    return s.step("reading the schema");
}

// -1: an empty database (no tables at all).
int detectVersion(sqlite3* db, const std::string& path) {
    // The first read: a corrupt, foreign or locked file fails here.
    Statement count(db, path, "SELECT count(*) FROM sqlite_master");
    count.step("reading the schema");
    if (count.integer(0) == 0) return -1;
    if (hasTable(db, path, "schema_version")) {
        Statement s(db, path, "SELECT max(version) FROM schema_version");
        if (!s.step("reading the schema version") || s.optReal(0) == std::nullopt)
            throw inputError("knowledge base " + quoted(path) + ": the schema_version table is empty");
        return s.integer(0);
    }
    if (hasTable(db, path, "tool")) return 0;
    throw inputError("knowledge base " + quoted(path) +
                     ": the file is an SQLite database but not an AeroNC knowledge base (no tool table)");
}

void populate(sqlite3* db, const std::string& path, const std::string& schemaSql, const std::string& dataSql) {
    Transaction t(db, path, "creating the knowledge base");
    exec(db, path, schemaSql, "running the schema SQL");
    exec(db, path, dataSql, "running the default data SQL");
    t.commit();
}

void migrate(sqlite3* db, const std::string& path, int from) {
    Transaction t(db, path, "migrating from schema version " + std::to_string(from));
    for (int v = from; v < KnowledgeBase::kSchemaVersion; ++v) {
        const auto step = kMigrations.find(v);
        if (step == kMigrations.end())
            throw inputError("knowledge base " + quoted(path) + ": no migration from schema version " +
                             std::to_string(v));
        exec(db, path, step->second,
             "migrating from schema version " + std::to_string(v) + " to " + std::to_string(v + 1));
    }
    exec(db, path, "UPDATE schema_version SET version = " + std::to_string(KnowledgeBase::kSchemaVersion),
         "recording the schema version");
    // A migration must leave the references intact.
    Statement fk(db, path, "PRAGMA foreign_key_check");
    if (fk.step("checking foreign keys"))
        throw inputError("knowledge base " + quoted(path) + ": migration left a broken reference in table '" +
                         fk.text(0) + "'");
    t.commit();
}

}  // namespace

void KnowledgeBase::Closer::operator()(sqlite3* db) const { sqlite3_close_v2(db); }

KnowledgeBase::KnowledgeBase(std::unique_ptr<sqlite3, Closer> db, std::string path)
    : db_(std::move(db)), path_(std::move(path)) {}
KnowledgeBase::KnowledgeBase(KnowledgeBase&&) noexcept = default;
KnowledgeBase& KnowledgeBase::operator=(KnowledgeBase&&) noexcept = default;
KnowledgeBase::~KnowledgeBase() = default;

KnowledgeBase KnowledgeBase::openWithSqlFolder(const std::string& path,
                                               const std::function<std::string()>& sqlFolder) {
    std::error_code ec;
    const bool build = !fs::exists(path, ec) || (fs::is_regular_file(path, ec) && fs::file_size(path, ec) == 0);
    if (!build) return open(path, "", "");
    const fs::path folder = sqlFolder();
    auto read = [&](const char* name) {
        const fs::path p = folder / name;
        std::ifstream in(p, std::ios::binary);
        if (!in) throw inputError("knowledge-base SQL " + p.string() + " cannot be read");
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    };
    const std::string schema = read("schema.sql");
    return open(path, schema, read("default_data.sql"));
}

KnowledgeBase KnowledgeBase::open(const std::string& path, const std::string& schemaSql,
                                  const std::string& defaultDataSql) {
    const fs::path file(path);
    const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        throw inputError("knowledge base " + quoted(path) + ": the directory " + quoted(dir.string()) +
                         " does not exist");
    if (fs::is_directory(file, ec))
        throw inputError("knowledge base " + quoted(path) + ": is a directory, not a database file");

    if (!fs::exists(file, ec)) {
        // Build under a temporary name and rename, so `path` is either complete or absent.
        const std::string tmp = path + ".creating";
        fs::remove(tmp, ec);
        fs::remove(tmp + "-journal", ec);
        try {
            auto db = openConnection(tmp, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
            populate(db.get(), tmp, schemaSql, defaultDataSql);
        } catch (...) {
            fs::remove(tmp, ec);
            fs::remove(tmp + "-journal", ec);
            throw;
        }
        fs::rename(tmp, file, ec);
        if (ec) {
            fs::remove(tmp, ec);
            throw inputError("knowledge base " + quoted(path) + ": cannot create the file (" + ec.message() + ")");
        }
    }

    auto db = openConnection(path, SQLITE_OPEN_READWRITE);
    const int version = detectVersion(db.get(), path);
    if (version == -1) {
        // An empty file (zero bytes, or a database without tables): fill it in place.
        populate(db.get(), path, schemaSql, defaultDataSql);
    } else if (version > kSchemaVersion) {
        throw inputError("knowledge base " + quoted(path) + ": schema version " + std::to_string(version) +
                         " is newer than this AeroNC understands (" + std::to_string(kSchemaVersion) +
                         "); update AeroNC");
    } else if (version < kSchemaVersion) {
        // Keep the old file: a migration is the one write a user cannot redo by hand.
        const std::string backup = path + ".v" + std::to_string(version) + ".bak";
        fs::copy_file(file, backup, fs::copy_options::overwrite_existing, ec);
        migrate(db.get(), path, version);
    }
    return KnowledgeBase(std::move(db), path);
}

int KnowledgeBase::schemaVersion() const {
    Statement s(db_.get(), path_, "SELECT max(version) FROM schema_version");
    s.step("reading the schema version");
    return s.integer(0);
}

std::vector<Tool> KnowledgeBase::tools() const {
    Statement s(db_.get(), path_,
                (std::string("SELECT ") + kToolColumns + " FROM tool ORDER BY diameter DESC, id").c_str());
    std::vector<Tool> out;
    while (s.step("reading the tools")) out.push_back(toolFromRow(s, path_));
    return out;
}

std::vector<toolselect::EdgeTool> KnowledgeBase::edgeTools() const {
    std::vector<toolselect::EdgeTool> out;
    if (!hasTable(db_.get(), path_, "edge_tool")) return out;
    Statement s(db_.get(), path_,
                "SELECT id, kind, tool_material, diameter, tip_diameter, included_angle, profile_radius, flutes, reach "
                "FROM edge_tool ORDER BY diameter, id");
    while (s.step("reading the edge tools")) {
        toolselect::EdgeTool t;
        t.id = s.text(0);
        s.about("edge tool " + detail::quoted(t.id));
        t.kind = s.text(1);
        t.material = s.text(2);
        t.diameter = s.real(3);
        t.tipDiameter = s.real(4);
        t.includedAngle = s.optReal(5).value_or(0.0);
        t.profileRadius = s.optReal(6).value_or(0.0);
        t.flutes = s.integer(7);
        t.reach = s.real(8);
        out.push_back(t);
    }
    return out;
}

void KnowledgeBase::addTool(const Tool& tool, std::optional<double> cost) {
    insertTools({tool}, {cost});
}

void KnowledgeBase::importTools(const std::vector<Tool>& tools) {
    insertTools(tools, std::vector<std::optional<double>>(tools.size()));
}

void KnowledgeBase::insertTools(const std::vector<Tool>& tools, const std::vector<std::optional<double>>& costs) {
    // Check everything before touching the file.
    for (const Tool& t : tools) t.validate();
    for (const auto& c : costs)
        if (c && !(*c >= 0)) throw inputError("tool cost must not be negative");

    sqlite3* db = db_.get();
    Transaction tx(db, path_, tools.size() == 1 ? "adding tool " + quoted(tools[0].id) : "importing tools");
    Statement s(db, path_,
                "INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach, cost, "
                "neck_diameter) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    for (std::size_t i = 0; i < tools.size(); ++i) {
        const Tool& t = tools[i];
        s.reset();
        s.bind(1, t.id).bind(2, t.type).bind(3, t.material).bind(4, t.diameter).bind(5, t.cornerRadius);
        s.bind(6, t.flutes).bind(7, t.fluteLength).bind(8, t.reach).bind(9, costs[i]);
        s.bind(10, t.necked() ? std::optional<double>(t.neckDiameter) : std::nullopt);
        const int rc = s.tryStep();
        if (rc == SQLITE_DONE) continue;
        const int ext = sqlite3_extended_errcode(db);
        const std::string who = "tool " + quoted(t.id) + ": ";
        const std::string detail = sqlite3_errmsg(db);
        const std::string batch = tools.size() > 1 ? " (nothing was imported)" : "";
        switch (ext) {
        case SQLITE_CONSTRAINT_CHECK:
            throw inputError(who + "impossible dimensions rejected by the knowledge base (" + detail + ")" + batch);
        case SQLITE_CONSTRAINT_PRIMARYKEY:
        case SQLITE_CONSTRAINT_UNIQUE:
            throw inputError(who + "a tool with this id already exists" + batch);
        case SQLITE_CONSTRAINT_FOREIGNKEY:
            throw inputError(who + "unknown tool material " + quoted(t.material) + " (known: " +
                             joined(names(db, path_, "SELECT name FROM tool_material ORDER BY name")) + ")" +
                             batch);
        default:
            fail(db, ext, path_, "adding tool " + quoted(t.id));
        }
    }
    tx.commit();
}

std::optional<double> KnowledgeBase::findThreshold(const std::string& name) const {
    Statement s(db_.get(), path_, "SELECT value FROM threshold WHERE name = ?");
    s.bind(1, name);
    if (!s.step("reading a threshold")) {
        checkIntact(db_.get(), path_);
        return std::nullopt;
    }
    s.about("threshold " + quoted(name));
    return s.real(0);
}

double KnowledgeBase::threshold(const std::string& name) const {
    if (const auto v = findThreshold(name)) return *v;
    throw inputError("knowledge base " + quoted(path_) + ": unknown threshold " + quoted(name) + " (known: " +
                     joined(names(db_.get(), path_, "SELECT name FROM threshold ORDER BY name")) + ")");
}

CuttingCondition KnowledgeBase::cuttingCondition(const std::string& workpieceMaterial,
                                                 const std::string& toolMaterial, const std::string& operation,
                                                 std::optional<double> toolDiameter) const {
    if (auto c = findCuttingCondition(workpieceMaterial, toolMaterial, operation, toolDiameter)) return *c;
    sqlite3* db = db_.get();
    Statement ranged(db, path_,
                     "SELECT count(*) FROM cutting_condition WHERE workpiece_material = ? AND tool_material = ? "
                     "AND operation = ?");
    ranged.bind(1, workpieceMaterial).bind(2, toolMaterial).bind(3, operation);
    ranged.step();
    if (ranged.integer(0) > 0) {
        std::ostringstream d;
        if (toolDiameter) d << "a " << *toolDiameter << " mm tool";
        else d << "a tool of unknown diameter (the rows are by diameter range)";
        throw inputError("no cutting condition for " + quoted(workpieceMaterial) + " with " + quoted(toolMaterial) +
                         " tools and operation " + quoted(operation) + " covers " + d.str());
    }
    Statement ops(db, path_,
                  "SELECT operation FROM cutting_condition WHERE workpiece_material = ? AND tool_material = ? "
                  "ORDER BY operation");
    ops.bind(1, workpieceMaterial).bind(2, toolMaterial);
    std::vector<std::string> known;
    while (ops.step()) known.push_back(ops.text(0));
    throw inputError("no cutting condition for " + quoted(workpieceMaterial) + " with " + quoted(toolMaterial) +
                     " tools and operation " + quoted(operation) + " (operations known for this pair: " +
                     (known.empty() ? std::string("none") : joined(known)) + ")");
}

std::optional<CuttingCondition> KnowledgeBase::findCuttingCondition(const std::string& workpieceMaterial,
                                                                    const std::string& toolMaterial,
                                                                    const std::string& operation,
                                                                    std::optional<double> toolDiameter) const {
    sqlite3* db = db_.get();
    {
        Statement s(db, path_, "SELECT 1 FROM workpiece_material WHERE name = ?");
        s.bind(1, workpieceMaterial);
        if (!s.step())
            notFound(db, path_,
                     "unknown workpiece material " + quoted(workpieceMaterial) + " (known: " +
                         joined(workpieceMaterials()) + ")");
    }
    {
        Statement s(db, path_, "SELECT 1 FROM tool_material WHERE name = ?");
        s.bind(1, toolMaterial);
        if (!s.step())
            notFound(db, path_,
                     "unknown tool material " + quoted(toolMaterial) + " (known: " +
                         joined(names(db, path_, "SELECT name FROM tool_material ORDER BY name")) + ")");
    }
    // ?4 NULL (no diameter) matches only rows without a range; ranged rows sort first.
    Statement s(db, path_,
                "SELECT vc_m_min, fz_mm, ap_mm, ae_ratio, c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m, "
                "d_min, d_max FROM cutting_condition WHERE workpiece_material = ? AND tool_material = ? "
                "AND operation = ? AND ((d_min IS NULL AND d_max IS NULL) OR (?4 IS NOT NULL "
                "AND (d_min IS NULL OR d_min <= ?4) AND (d_max IS NULL OR ?4 < d_max))) "
                "ORDER BY (d_min IS NULL AND d_max IS NULL), d_min DESC LIMIT 1");
    s.bind(1, workpieceMaterial).bind(2, toolMaterial).bind(3, operation).bind(4, toolDiameter);
    if (!s.step("reading cutting conditions")) {
        checkIntact(db, path_);
        return std::nullopt;
    }
    s.about("cutting condition " + quoted(workpieceMaterial) + "/" + quoted(toolMaterial) + "/" + quoted(operation));
    CuttingCondition c;
    c.workpieceMaterial = workpieceMaterial;
    c.toolMaterial = toolMaterial;
    c.operation = operation;
    c.vc = s.real(0);
    c.fz = s.real(1);
    c.ap = s.real(2);
    c.aeRatio = s.real(3);
    c.cF = s.real(4);
    c.xF = s.real(5);
    c.yF = s.real(6);
    c.uF = s.real(7);
    c.qF = s.real(8);
    c.wF = s.real(9);
    c.kFc = s.real(10);
    c.taylorC = s.real(11);
    c.taylorM = s.real(12);
    c.dMin = s.optReal(13);
    c.dMax = s.optReal(14);
    const std::string who = "knowledge base " + quoted(path_) + ": cutting condition " + quoted(workpieceMaterial) + "/" +
                            quoted(toolMaterial) + "/" + quoted(operation) + ": ";
    const std::pair<double, const char*> positive[] = {{c.vc, "vc_m_min"}, {c.fz, "fz_mm"},       {c.ap, "ap_mm"},
                                                       {c.cF, "c_f"},      {c.kFc, "k_fc"},       {c.taylorC, "taylor_c"},
                                                       {c.taylorM, "taylor_m"}, {c.aeRatio, "ae_ratio"}};
    for (const auto& [v, name] : positive)
        if (!(v > 0)) throw inputError(who + name + " must be positive, not " + std::to_string(v));
    if (c.aeRatio > 1) throw inputError(who + "ae_ratio must be at most 1, not " + std::to_string(c.aeRatio));
    return c;
}

Machine KnowledgeBase::machine(const std::string& name) const {
    Statement s(db_.get(), path_,
                "SELECT name, type, kinematics, travel_x, travel_y, travel_z, a_min, a_max, c_min, c_max, "
                "max_spindle_rpm, power_kw, max_feed_mm_min, max_force_n, efficiency, tool_change_s "
                "FROM machine WHERE name = ?");
    s.bind(1, name);
    if (!s.step("reading a machine"))
        notFound(db_.get(), path_, "unknown machine " + quoted(name) + " (known: " + joined(machineNames()) + ")");
    s.about("machine " + quoted(name));
    Machine m;
    m.name = s.text(0);
    m.type = s.text(1);
    m.kinematics = s.text(2);
    m.travelX = s.real(3);
    m.travelY = s.real(4);
    m.travelZ = s.real(5);
    m.aMin = s.optReal(6);
    m.aMax = s.optReal(7);
    m.cMin = s.optReal(8);
    m.cMax = s.optReal(9);
    m.maxSpindleRpm = s.real(10);
    m.powerKw = s.real(11);
    m.maxFeedMmMin = s.real(12);
    m.maxForceN = s.real(13);
    m.efficiency = s.real(14);
    m.toolChangeS = s.real(15);
    const std::string who = "knowledge base " + quoted(path_) + ": machine " + quoted(name) + ": ";
    const std::pair<double, const char*> positive[] = {{m.travelX, "travel_x"}, {m.travelY, "travel_y"},
                                                       {m.travelZ, "travel_z"}, {m.maxSpindleRpm, "max_spindle_rpm"},
                                                       {m.powerKw, "power_kw"}, {m.maxFeedMmMin, "max_feed_mm_min"},
                                                       {m.maxForceN, "max_force_n"}, {m.efficiency, "efficiency"}};
    for (const auto& [v, column] : positive)
        if (!(v > 0)) throw inputError(who + column + " must be positive, not " + std::to_string(v));
    if (m.efficiency > 1) throw inputError(who + "efficiency must be at most 1, not " + std::to_string(m.efficiency));
    if (m.toolChangeS < 0) throw inputError(who + "tool_change_s must not be negative");
    return m;
}

std::vector<std::string> KnowledgeBase::workpieceMaterials() const {
    return names(db_.get(), path_, "SELECT name FROM workpiece_material ORDER BY name");
}

std::vector<std::string> KnowledgeBase::machineNames() const {
    return names(db_.get(), path_, "SELECT name FROM machine ORDER BY name");
}

}  // namespace aeronc::kb
