// The machining knowledge base: built from the shipped SQL, migrated from version 0, and
// every bad input (impossible tool, bad import, corrupt or locked file, unknown material)
// reported clearly with the database left as it was.
#include "ErrorOf.h"

#include <aeronc/core/Error.h>
#include <aeronc/core/TextFile.h>
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/kb/LongReach.h>
#include <aeronc/toolselect/EdgeTools.h>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <set>
#include <tuple>
#include <unistd.h>

namespace fs = std::filesystem;
using aeronc::Error;
using aeronc::kb::KnowledgeBase;
using aeronc::toolselect::Tool;
namespace toolselect = aeronc::toolselect;

using aeronc::test::inputErrorOf;

namespace {

// Rows of the shipped tool table: 29 end mills, face mill and tap drills, 29 jobber drills,
// 2 inch jobber drills, the 30 small, necked and long-reach end mills of the shop crib and the
// 5 extra-long-neck end mills, the long-reach D3 ball of schema version 8, version 9's two
// micro end mills, version 10's eleven long-reach end mills D16-D32 and version 11's D4 x 40.
constexpr std::size_t kShippedTools = 110;
// The crib's tools added by schema versions 6 and 7 (docs/tool-crib.md).
constexpr std::size_t kCribTools = 35;
// The extra-long-neck series schema version 7 added (8 x D).
const std::vector<std::string> kExtraLongNeck = {"EM-F1.5x12", "EM-F2x16", "EM-F3x24", "EM-F4x32", "EM-F6x48"};
// Schema version 9: micro end mills for lettering 0.25-0.4 mm wide.
const std::vector<std::string> kVersion9 = {"EM-F0.2", "EM-F0.3"};
// Schema version 10: long-reach end mills D16-D32 reaching 80-160 mm for deep open regions.
const std::vector<std::string> kVersion10 = {"EM-F16x80",  "EM-F16x100",  "EM-F20x100",   "EM-F20x130",
                                             "EM-F25x125", "EM-F25x160",  "EM-F32x160",   "EM-B16R2x80",
                                             "EM-B20R3x100", "EM-B25R4x125", "EM-B32R4x160"};
// Schema version 11: a flat D4 reaching 40 mm (10 x D) and two large 90 degree chamfer mills.
const std::vector<std::string> kVersion11Tools = {"EM-F4x40"};
const std::vector<std::string> kVersion11EdgeTools = {"CM-90-D25", "CM-90-D32"};

// What schema version 6 added to a new file (docs/tool-crib.md), removed again: the layout and
// rows of a version-5 file, from which a test makes the older ones.
constexpr const char* kWithoutVersion6 = R"sql(
        DELETE FROM tool WHERE neck_diameter IS NOT NULL OR id = 'EM-BALL16';
        DELETE FROM cutting_condition WHERE d_min IN (0, 1);
        DELETE FROM threshold WHERE name LIKE 'long_reach_%' OR name = 'allowance_max_ratio';
        DROP TABLE edge_tool;
        ALTER TABLE tool DROP COLUMN neck_diameter;
)sql";

const std::string& schemaSql() {
    static const std::string s = aeronc::readTextFile(AERONC_RESOURCES "/kb/schema.sql", "schema");
    return s;
}
const std::string& dataSql() {
    static const std::string s = aeronc::readTextFile(AERONC_RESOURCES "/kb/default_data.sql", "default data");
    return s;
}

// Runs SQL on a plain connection, outside KnowledgeBase.
void rawExec(const fs::path& file, const std::string& sql) {
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
    char* err = nullptr;
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err);
    const std::string msg = err ? err : "";
    sqlite3_free(err);
    sqlite3_close(db);
    ASSERT_EQ(rc, SQLITE_OK) << msg;
}

Tool tool(const std::string& id, double d, double r = 0, const std::string& type = "flat") {
    Tool t;
    t.id = id;
    t.type = type;
    t.material = "carbide";
    t.diameter = d;
    t.cornerRadius = r;
    t.flutes = 3;
    t.fluteLength = 2 * d;
    t.reach = 3 * d;
    return t;
}

class KnowledgeBaseTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("aeronc_kb_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path file(const std::string& name = "kb.sqlite") const { return dir_ / name; }
    KnowledgeBase openDefault(const fs::path& p) { return KnowledgeBase::open(p.string(), schemaSql(), dataSql()); }

    fs::path dir_;
};

}  // namespace

TEST_F(KnowledgeBaseTest, CreatesFromShippedSqlWithDefaultRows) {
    const fs::path p = file();
    {
        KnowledgeBase kb = openDefault(p);
        EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
        const auto tools = kb.tools();
        EXPECT_EQ(tools.size(), kShippedTools);
        for (const Tool& t : tools) EXPECT_NO_THROW(t.validate()) << t.id;
        EXPECT_EQ(tools.front().id, "FM-125");  // largest first
        EXPECT_EQ(tools.front().flutes, 4);
        EXPECT_EQ(kb.workpieceMaterials().size(), 4u);
        EXPECT_EQ(kb.machineNames().size(), 4u);

        const auto mill = kb.machine("XA5032");
        EXPECT_DOUBLE_EQ(mill.maxSpindleRpm, 1800);
        EXPECT_DOUBLE_EQ(mill.powerKw, 7.5);
        EXPECT_DOUBLE_EQ(mill.maxFeedMmMin, 980);
        EXPECT_DOUBLE_EQ(mill.maxForceN, 15000);
        EXPECT_DOUBLE_EQ(mill.efficiency, 0.75);
        EXPECT_FALSE(mill.aMin.has_value());
        EXPECT_TRUE(kb.machine("AC-5AX").cMax.has_value());

        const auto cc = kb.cuttingCondition("45 steel", "carbide", "roughing");
        EXPECT_DOUBLE_EQ(cc.cF, 825);
        EXPECT_GT(cc.vc, 0);
        EXPECT_GT(cc.taylorM, 0);
        for (const std::string m : {"7050-T7451", "2024-T351", "Ti-6Al-4V", "45 steel"})
            for (const std::string tm : {"HSS", "carbide"})
                for (const std::string op : {"roughing", "finishing", "drilling"})
                    EXPECT_NO_THROW(kb.cuttingCondition(m, tm, op, 10.0)) << m << " " << tm << " " << op;
    }
    EXPECT_FALSE(fs::exists(p.string() + ".creating"));
    // Opening again keeps the rows (no second insert of the defaults).
    EXPECT_EQ(openDefault(p).tools().size(), kShippedTools);
}

// The SQL folder is needed, and asked for, only when the file has to be built.
TEST_F(KnowledgeBaseTest, SqlFolderAskedOnlyToBuild) {
    const fs::path p = file();
    int asked = 0;
    const auto folder = [&] {
        ++asked;
        return (fs::path(AERONC_RESOURCES) / "kb").string();
    };
    EXPECT_EQ(KnowledgeBase::openWithSqlFolder(p.string(), folder).tools().size(), kShippedTools);
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(KnowledgeBase::openWithSqlFolder(p.string(), folder).tools().size(), kShippedTools);
    EXPECT_EQ(asked, 1);
    const fs::path other = p.parent_path() / "other.sqlite";
    try {
        KnowledgeBase::openWithSqlFolder(other.string(), [] { return std::string("/nonexistent"); });
        FAIL() << "built without SQL";
    } catch (const aeronc::Error& e) {
        EXPECT_NE(std::string(e.what()).find("schema.sql"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(other));
}

TEST_F(KnowledgeBaseTest, Thresholds) {
    KnowledgeBase kb = openDefault(file());
    EXPECT_DOUBLE_EQ(kb.threshold("eta_min"), 0.85);
    EXPECT_DOUBLE_EQ(kb.threshold("mu_merge"), 0.7);
    const std::string e = inputErrorOf([&] { kb.threshold("no_such"); });
    EXPECT_NE(e.find("unknown threshold 'no_such'"), std::string::npos) << e;
    EXPECT_NE(e.find("eta_min"), std::string::npos) << e;
}

TEST_F(KnowledgeBaseTest, AddToolPersists) {
    const fs::path p = file();
    openDefault(p).addTool(tool("USER-7", 7, 0.5, "bull"), 33.0);
    const auto tools = openDefault(p).tools();
    ASSERT_EQ(tools.size(), kShippedTools + 1);
    const auto it = std::find_if(tools.begin(), tools.end(), [](const Tool& t) { return t.id == "USER-7"; });
    ASSERT_NE(it, tools.end());
    EXPECT_DOUBLE_EQ(it->cornerRadius, 0.5);
    EXPECT_EQ(it->type, "bull");
}

TEST_F(KnowledgeBaseTest, ImpossibleToolRejectedAndDatabaseUnchanged) {
    KnowledgeBase kb = openDefault(file());
    Tool bad = tool("BAD-1", 10, 6, "bull");  // corner radius larger than the radius
    std::string e = inputErrorOf([&] { kb.addTool(bad); });
    EXPECT_NE(e.find("BAD-1"), std::string::npos) << e;
    Tool negative = tool("BAD-2", -4);
    e = inputErrorOf([&] { kb.addTool(negative); });
    EXPECT_NE(e.find("BAD-2"), std::string::npos) << e;
    Tool shortReach = tool("BAD-3", 10);
    shortReach.reach = 5;
    e = inputErrorOf([&] { kb.addTool(shortReach); });
    EXPECT_NE(e.find("BAD-3"), std::string::npos) << e;
    EXPECT_EQ(kb.tools().size(), kShippedTools);

    // A duplicate id and an unknown tool material are named too.
    e = inputErrorOf([&] { kb.addTool(tool("EM-F10", 10)); });
    EXPECT_NE(e.find("already exists"), std::string::npos) << e;
    Tool ceramic = tool("CER-1", 10);
    ceramic.material = "ceramic";
    e = inputErrorOf([&] { kb.addTool(ceramic); });
    EXPECT_NE(e.find("unknown tool material 'ceramic'"), std::string::npos) << e;
    EXPECT_EQ(kb.tools().size(), kShippedTools);
}

TEST_F(KnowledgeBaseTest, DatabaseCheckConstraintsRefuseImpossibleTools) {
    // The schema itself refuses what validate() refuses, for hand edits.
    const fs::path p = file();
    openDefault(p);
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(p.c_str(), &db), SQLITE_OK);
    const char* bad[] = {
        "INSERT INTO tool (id,type,tool_material,diameter,corner_radius,flutes,flute_length,reach) "
        "VALUES ('X1','flat','carbide',0,0,2,10,20)",
        "INSERT INTO tool (id,type,tool_material,diameter,corner_radius,flutes,flute_length,reach) "
        "VALUES ('X2','bull','carbide',10,5.5,2,10,20)",
        "INSERT INTO tool (id,type,tool_material,diameter,corner_radius,flutes,flute_length,reach) "
        "VALUES ('X3','flat','carbide',10,0,0,10,20)",
        "INSERT INTO tool (id,type,tool_material,diameter,corner_radius,flutes,flute_length,reach) "
        "VALUES ('X4','flat','carbide',10,0,2,30,20)",
        "INSERT INTO tool (id,type,tool_material,diameter,corner_radius,flutes,flute_length,reach) "
        "VALUES ('X5','flat','carbide',10,-1,2,10,20)",
    };
    for (const char* sql : bad) EXPECT_NE(sqlite3_exec(db, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sql;
    sqlite3_close(db);
    EXPECT_EQ(openDefault(p).tools().size(), kShippedTools);
}

TEST_F(KnowledgeBaseTest, ImportIsAllOrNothing) {
    KnowledgeBase kb = openDefault(file());
    std::vector<Tool> batch = {tool("IMP-1", 5), tool("IMP-2", 7), tool("IMP-3", 9, 10, "bull"), tool("IMP-4", 11)};
    const std::string e = inputErrorOf([&] { kb.importTools(batch); });
    EXPECT_NE(e.find("IMP-3"), std::string::npos) << e;
    EXPECT_EQ(kb.tools().size(), kShippedTools);

    // A batch that fails inside the database (a duplicate in the middle) is rolled back too.
    batch = {tool("IMP-1", 5), tool("EM-F6", 6), tool("IMP-4", 11)};
    const std::string dup = inputErrorOf([&] { kb.importTools(batch); });
    EXPECT_NE(dup.find("EM-F6"), std::string::npos) << dup;
    EXPECT_NE(dup.find("nothing was imported"), std::string::npos) << dup;
    EXPECT_EQ(kb.tools().size(), kShippedTools);

    batch = {tool("IMP-1", 5), tool("IMP-4", 11)};
    kb.importTools(batch);
    EXPECT_EQ(kb.tools().size(), kShippedTools + 2);
}

TEST_F(KnowledgeBaseTest, MigratesVersionZeroKeepingUserRows) {
    const fs::path p = file();
    // Version 0: no schema_version table, no tool.cost column, a user's own tool and threshold.
    rawExec(p, R"sql(
        CREATE TABLE tool_material (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, kind TEXT NOT NULL);
        CREATE TABLE tool (
            id TEXT PRIMARY KEY NOT NULL,
            type TEXT NOT NULL CHECK (type IN ('flat', 'bull', 'ball', 'drill', 'face')),
            tool_material TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
            diameter REAL NOT NULL CHECK (diameter > 0),
            corner_radius REAL NOT NULL DEFAULT 0 CHECK (corner_radius >= 0 AND corner_radius <= diameter / 2.0),
            flutes INTEGER NOT NULL CHECK (flutes > 0),
            flute_length REAL NOT NULL CHECK (flute_length > 0),
            overall_length REAL,
            reach REAL NOT NULL CHECK (reach >= flute_length));
        CREATE TABLE threshold (name TEXT PRIMARY KEY NOT NULL, value REAL NOT NULL, description TEXT);
        INSERT INTO tool_material (name, kind) VALUES ('carbide', 'carbide');
        INSERT INTO tool VALUES ('MY-TOOL-14', 'bull', 'carbide', 14, 1.5, 4, 30, 90, 40);
        INSERT INTO threshold (name, value) VALUES ('eta_min', 0.9);
    )sql");

    {
        KnowledgeBase kb = openDefault(p);
        EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
        const auto tools = kb.tools();
        ASSERT_EQ(tools.size(), 1u);
        EXPECT_EQ(tools[0].id, "MY-TOOL-14");
        EXPECT_DOUBLE_EQ(tools[0].diameter, 14);
        EXPECT_DOUBLE_EQ(tools[0].cornerRadius, 1.5);
        EXPECT_DOUBLE_EQ(tools[0].reach, 40);
        EXPECT_DOUBLE_EQ(kb.threshold("eta_min"), 0.9);  // the user's value, not the default
        EXPECT_DOUBLE_EQ(kb.threshold("mu_merge"), 0.7);  // seeded by the migration
        // The new column works.
        kb.addTool(tool("NEW-6", 6), 25.0);
        EXPECT_EQ(kb.tools().size(), 2u);
    }
    EXPECT_TRUE(fs::exists(p.string() + ".v0.bak"));
    // Reopening a migrated file does nothing more.
    EXPECT_EQ(openDefault(p).tools().size(), 2u);
}

TEST_F(KnowledgeBaseTest, MigratesVersionOneKeepingUserRows) {
    const fs::path p = file();
    // The version-1 layout: tool types without 'other', cutting data without diameter ranges,
    // no FreeCAD tables; with a user's tool, cutting data and changed threshold.
    rawExec(p, R"sql(
        PRAGMA foreign_keys = ON;
        CREATE TABLE schema_version (version INTEGER NOT NULL);
        INSERT INTO schema_version VALUES (1);
        CREATE TABLE workpiece_material (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, family TEXT NOT NULL,
                                         hardness_hb REAL);
        CREATE TABLE tool_material (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, kind TEXT NOT NULL);
        CREATE TABLE machine (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, type TEXT NOT NULL,
            kinematics TEXT NOT NULL, travel_x REAL NOT NULL, travel_y REAL NOT NULL, travel_z REAL NOT NULL,
            a_min REAL, a_max REAL, c_min REAL, c_max REAL, max_spindle_rpm REAL NOT NULL, power_kw REAL NOT NULL,
            max_feed_mm_min REAL NOT NULL, max_force_n REAL NOT NULL, efficiency REAL NOT NULL,
            tool_change_s REAL NOT NULL);
        CREATE TABLE tool (
            id TEXT PRIMARY KEY NOT NULL,
            type TEXT NOT NULL CHECK (type IN ('flat', 'bull', 'ball', 'drill', 'face')),
            tool_material TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
            diameter REAL NOT NULL, corner_radius REAL NOT NULL DEFAULT 0, flutes INTEGER NOT NULL,
            flute_length REAL NOT NULL, overall_length REAL, reach REAL NOT NULL, cost REAL);
        CREATE TABLE cutting_condition (id INTEGER PRIMARY KEY,
            workpiece_material TEXT NOT NULL REFERENCES workpiece_material (name) ON UPDATE CASCADE,
            tool_material TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
            operation TEXT NOT NULL, vc_m_min REAL NOT NULL, fz_mm REAL NOT NULL, ap_mm REAL NOT NULL,
            ae_ratio REAL NOT NULL, c_f REAL NOT NULL, x_f REAL NOT NULL, y_f REAL NOT NULL, u_f REAL NOT NULL,
            q_f REAL NOT NULL, w_f REAL NOT NULL, k_fc REAL NOT NULL DEFAULT 1, taylor_c REAL NOT NULL,
            taylor_m REAL NOT NULL, UNIQUE (workpiece_material, tool_material, operation));
        CREATE TABLE threshold (name TEXT PRIMARY KEY NOT NULL, value REAL NOT NULL, description TEXT);
        CREATE TABLE process_template (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, steps TEXT NOT NULL);
        CREATE TABLE sequencing_rule (id INTEGER PRIMARY KEY, priority INTEGER NOT NULL UNIQUE, rule TEXT NOT NULL);
        INSERT INTO workpiece_material (name, family) VALUES ('7075-T6', 'aluminium');
        INSERT INTO tool_material (name, kind) VALUES ('carbide', 'carbide');
        INSERT INTO tool VALUES ('SHOP-EM-14', 'bull', 'carbide', 14, 1.5, 4, 30, 90, 40, 77);
        INSERT INTO cutting_condition (workpiece_material, tool_material, operation, vc_m_min, fz_mm, ap_mm,
            ae_ratio, c_f, x_f, y_f, u_f, q_f, w_f, k_fc, taylor_c, taylor_m)
            VALUES ('7075-T6', 'carbide', 'roughing', 444, 0.07, 3.5, 0.4, 200, 1, 0.75, 1.1, 1.3, 0.2, 1, 1400, 0.3);
        INSERT INTO threshold (name, value) VALUES ('eta_min', 0.8), ('mu_merge', 0.7);
    )sql");

    {
        KnowledgeBase kb = openDefault(p);
        EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
        const auto tools = kb.tools();
        ASSERT_EQ(tools.size(), 1u);
        EXPECT_EQ(tools[0].id, "SHOP-EM-14");
        EXPECT_DOUBLE_EQ(tools[0].cornerRadius, 1.5);
        EXPECT_DOUBLE_EQ(kb.threshold("eta_min"), 0.8);
        EXPECT_DOUBLE_EQ(kb.threshold("plunge_feed_ratio"), 0.3);  // added by the migration
        // The user's cutting data, for any diameter (the row has no range).
        const auto cc = kb.cuttingCondition("7075-T6", "carbide", "roughing", 14.0);
        EXPECT_DOUBLE_EQ(cc.vc, 444);
        EXPECT_FALSE(cc.dMin.has_value());
        EXPECT_DOUBLE_EQ(kb.cuttingCondition("7075-T6", "carbide", "roughing").fz, 0.07);
        // What version 2 allows: a tool kept for FreeCAD only.
        Tool probe = tool("PROBE-2", 2, 0, "other");
        kb.addTool(probe);
        EXPECT_EQ(kb.tools().size(), 2u);
        // The old constraint still holds in the rebuilt table.
        EXPECT_NE(inputErrorOf([&] { kb.addTool(tool("BAD", 4, 3, "bull")); }), "");
    }
    EXPECT_TRUE(fs::exists(p.string() + ".v1.bak"));
}

TEST_F(KnowledgeBaseTest, CuttingDataByDiameterRange) {
    KnowledgeBase kb = openDefault(file());
    // Shipped rows for 7050-T7451 carbide roughing: [0,6) f_z 0.04, [6,10) 0.06, [10,16) 0.08,
    // [16,25) 0.10 with a_p 5, [25,inf) 0.12.
    EXPECT_DOUBLE_EQ(kb.cuttingCondition("7050-T7451", "carbide", "roughing", 4.0).fz, 0.04);
    EXPECT_DOUBLE_EQ(kb.cuttingCondition("7050-T7451", "carbide", "roughing", 10.0).fz, 0.08);  // lower bound in
    EXPECT_DOUBLE_EQ(kb.cuttingCondition("7050-T7451", "carbide", "roughing", 15.99).fz, 0.08);
    EXPECT_DOUBLE_EQ(kb.cuttingCondition("7050-T7451", "carbide", "roughing", 16.0).ap, 5.0);
    EXPECT_DOUBLE_EQ(*kb.cuttingCondition("7050-T7451", "carbide", "roughing", 40.0).dMin, 25.0);
    // Unranged rows serve any diameter; without a diameter, ranged rows cannot be chosen.
    EXPECT_DOUBLE_EQ(kb.cuttingCondition("7050-T7451", "carbide", "finishing", 6.0).fz, 0.06);
    const std::string e = inputErrorOf([&] { kb.cuttingCondition("7050-T7451", "carbide", "roughing"); });
    EXPECT_NE(e.find("diameter"), std::string::npos) << e;
}

TEST_F(KnowledgeBaseTest, NewerSchemaVersionRefused) {
    const fs::path p = file();
    openDefault(p);
    rawExec(p, "UPDATE schema_version SET version = 99");
    const std::string e = inputErrorOf([&] { openDefault(p); });
    EXPECT_NE(e.find("newer"), std::string::npos) << e;
}

TEST_F(KnowledgeBaseTest, MissingDirectory) {
    const fs::path p = dir_ / "no" / "such" / "kb.sqlite";
    const std::string e = inputErrorOf([&] { openDefault(p); });
    EXPECT_NE(e.find("does not exist"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(dir_ / "no"));
}

TEST_F(KnowledgeBaseTest, CorruptFile) {
    const fs::path p = file();
    {
        std::mt19937 rng(7);
        std::ofstream out(p, std::ios::binary);
        for (int i = 0; i < 8192; ++i) out.put(static_cast<char>(rng() & 0xff));
    }
    const auto sizeBefore = fs::file_size(p);
    const std::string e = inputErrorOf([&] { openDefault(p); });
    EXPECT_NE(e.find("file is not a database"), std::string::npos) << e;
    EXPECT_NE(e.find(p.string()), std::string::npos) << e;
    EXPECT_EQ(fs::file_size(p), sizeBefore);  // not overwritten
}

TEST_F(KnowledgeBaseTest, NotAKnowledgeBase) {
    const fs::path p = file();
    rawExec(p, "CREATE TABLE other (x INTEGER)");
    const std::string e = inputErrorOf([&] { openDefault(p); });
    EXPECT_NE(e.find("not an AeroNC knowledge base"), std::string::npos) << e;
}

TEST_F(KnowledgeBaseTest, LockedDatabase) {
    const fs::path p = file();
    KnowledgeBase kb = openDefault(p);

    sqlite3* other = nullptr;
    ASSERT_EQ(sqlite3_open(p.c_str(), &other), SQLITE_OK);
    ASSERT_EQ(sqlite3_exec(other, "BEGIN EXCLUSIVE", nullptr, nullptr, nullptr), SQLITE_OK);

    std::string e = inputErrorOf([&] { openDefault(p); });
    EXPECT_NE(e.find("locked"), std::string::npos) << e;
    e = inputErrorOf([&] { kb.addTool(tool("LOCK-1", 5)); });
    EXPECT_NE(e.find("locked"), std::string::npos) << e;
    e = inputErrorOf([&] { kb.tools(); });
    EXPECT_NE(e.find("locked"), std::string::npos) << e;

    sqlite3_exec(other, "ROLLBACK", nullptr, nullptr, nullptr);
    sqlite3_close(other);
    kb.addTool(tool("LOCK-1", 5));
    EXPECT_EQ(kb.tools().size(), kShippedTools + 1);
}

TEST_F(KnowledgeBaseTest, UnknownMaterial) {
    KnowledgeBase kb = openDefault(file());
    std::string e = inputErrorOf([&] { kb.cuttingCondition("unobtainium", "carbide", "roughing"); });
    EXPECT_NE(e.find("unknown workpiece material 'unobtainium'"), std::string::npos) << e;
    EXPECT_NE(e.find("Ti-6Al-4V"), std::string::npos) << e;  // lists the known ones
    e = inputErrorOf([&] { kb.cuttingCondition("45 steel", "diamond", "roughing"); });
    EXPECT_NE(e.find("unknown tool material 'diamond'"), std::string::npos) << e;
    e = inputErrorOf([&] { kb.cuttingCondition("45 steel", "carbide", "threading"); });
    EXPECT_NE(e.find("no cutting condition"), std::string::npos) << e;
    e = inputErrorOf([&] { kb.machine("Unknown mill"); });
    EXPECT_NE(e.find("unknown machine"), std::string::npos) << e;
}

TEST_F(KnowledgeBaseTest, EmptyFileIsFilledInPlace) {
    const fs::path p = file();
    std::ofstream(p).close();
    EXPECT_EQ(openDefault(p).tools().size(), kShippedTools);
}

TEST_F(KnowledgeBaseTest, BadShippedSqlLeavesNoFile) {
    const fs::path p = file();
    const std::string e = inputErrorOf([&] { KnowledgeBase::open(p.string(), schemaSql(), "INSERT INTO nowhere VALUES (1);"); });
    EXPECT_NE(e.find("default data"), std::string::npos) << e;
    EXPECT_FALSE(fs::exists(p));
    EXPECT_FALSE(fs::exists(p.string() + ".creating"));
}

TEST_F(KnowledgeBaseTest, TableEditingIsOneTransactionWithNamedErrors) {
    KnowledgeBase kb = openDefault(file());
    const auto tools = kb.table("tool");
    ASSERT_EQ(tools.rows.size(), kShippedTools);
    ASSERT_EQ(tools.columns[0].name, "id");
    auto rowOf = [&](const aeronc::kb::Table& t, const std::string& id) {
        for (std::size_t i = 0; i < t.rows.size(); ++i)
            if (t.rows[i][0] == id) return t.rowIds[i];
        ADD_FAILURE() << "no row " << id;
        return -1LL;
    };
    const long long f10 = rowOf(tools, "EM-F10"), f12 = rowOf(tools, "EM-F12");
    auto diameterOf = [&](const std::string& id) {
        for (const Tool& t : kb.tools())
            if (t.id == id) return t.diameter;
        return -1.0;
    };

    // A good edit and a bad one in one batch: neither is applied; the message names the row.
    std::string e = inputErrorOf([&] { kb.editTable("tool", {{f12, "diameter", "11.5"}, {f10, "diameter", "-1"}}); });
    EXPECT_NE(e.find("row 'EM-F10'"), std::string::npos) << e;
    EXPECT_NE(e.find("nothing was changed"), std::string::npos) << e;
    EXPECT_DOUBLE_EQ(diameterOf("EM-F12"), 12);
    e = inputErrorOf([&] { kb.editTable("tool", {{f10, "diameter", "ten"}}); });
    EXPECT_NE(e.find("'ten' is not a number"), std::string::npos) << e;
    e = inputErrorOf([&] { kb.editTable("tool", {{f10, "flutes", "2.5"}}); });
    EXPECT_NE(e.find("whole number"), std::string::npos) << e;
    e = inputErrorOf([&] { kb.editTable("tool", {{f10, "tool_material", "diamond"}}); });
    EXPECT_NE(e.find("refers to a row that does not exist"), std::string::npos) << e;
    e = inputErrorOf([&] { kb.editTable("sqlite_master", {}); });
    EXPECT_NE(e.find("no editable table"), std::string::npos) << e;

    // Good edits persist; inserts and deletes work.
    kb.editTable("tool", {{f12, "diameter", "11.5"}});
    EXPECT_DOUBLE_EQ(diameterOf("EM-F12"), 11.5);
    const auto th = kb.table("threshold");
    kb.editTable("threshold", {}, {{std::string("my_rule"), std::string("0.5"), std::nullopt}});
    EXPECT_DOUBLE_EQ(kb.threshold("my_rule"), 0.5);
    EXPECT_EQ(kb.table("threshold").rows.size(), th.rows.size() + 1);
    kb.editTable("tool", {}, {}, {f10});
    EXPECT_EQ(kb.tools().size(), kShippedTools - 1);
    // Shown values read back exactly.
    const auto cc = kb.table("cutting_condition");
    EXPECT_EQ(cc.columns[6].name, "vc_m_min");
    EXPECT_EQ(cc.rows[0][6].value_or("?"), "600");
    EXPECT_EQ(cc.rows[0][7].value_or("?"), "0.04");
}

// The shipped drill series has the clearance and tap-drill sizes, each a jobber drill whose
// flutes are shorter than its reach.
TEST_F(KnowledgeBaseTest, ShippedDrillSeries) {
    KnowledgeBase kb = openDefault(file());
    std::vector<Tool> drills;
    for (const Tool& t : kb.tools())
        if (t.type == "drill") drills.push_back(t);
    EXPECT_EQ(drills.size(), 35u);
    auto has = [&](double d) {
        return std::any_of(drills.begin(), drills.end(), [d](const Tool& t) { return std::fabs(t.diameter - d) < 1e-9; });
    };
    for (double d : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0}) EXPECT_TRUE(has(d)) << d;
    for (double d : {6.4, 6.6, 9.0, 11.0, 13.5, 17.5, 20.0, 22.0}) EXPECT_TRUE(has(d)) << "clearance " << d;
    for (double d : {3.3, 4.2, 5.0, 6.8, 8.5, 10.2, 14.0, 17.5}) EXPECT_TRUE(has(d)) << "tap drill " << d;
    for (double in : {0.281, 0.173}) EXPECT_TRUE(has(in * 25.4)) << "inch drill " << in;  // letter K, number 17
    for (const Tool& t : drills) {
        EXPECT_NO_THROW(t.validate()) << t.id;
        EXPECT_GE(t.reach, t.fluteLength) << t.id;
        // HSS jobber flutes are 6 to 12 diameters long; the two carbide drills are stub length.
        EXPECT_GE(t.fluteLength, (t.material == "HSS" ? 6 : 4) * t.diameter) << t.id;
        EXPECT_LE(t.fluteLength, 12 * t.diameter) << t.id;
        EXPECT_NO_THROW(kb.cuttingCondition("7050-T7451", t.material, "drilling", t.diameter)) << t.id;
    }
}

TEST_F(KnowledgeBaseTest, MigratesVersionTwoKeepingUserRows) {
    const fs::path p = file();
    // The version-2 layout's planning tables: a template is a name and its step codes, a rule
    // a line of text; with the shipped rows, a user's template, a user's rule and a user's tool.
    rawExec(p, R"sql(
        PRAGMA foreign_keys = ON;
        CREATE TABLE schema_version (version INTEGER NOT NULL);
        INSERT INTO schema_version VALUES (2);
        CREATE TABLE workpiece_material (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, family TEXT NOT NULL,
                                         hardness_hb REAL);
        CREATE TABLE tool_material (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, kind TEXT NOT NULL);
        CREATE TABLE tool (
            id TEXT PRIMARY KEY NOT NULL,
            type TEXT NOT NULL CHECK (type IN ('flat', 'bull', 'ball', 'drill', 'face', 'other')),
            tool_material TEXT NOT NULL REFERENCES tool_material (name) ON UPDATE CASCADE,
            diameter REAL NOT NULL, corner_radius REAL NOT NULL DEFAULT 0, flutes INTEGER NOT NULL,
            flute_length REAL NOT NULL, overall_length REAL, reach REAL NOT NULL, cost REAL);
        CREATE TABLE threshold (name TEXT PRIMARY KEY NOT NULL, value REAL NOT NULL, description TEXT);
        CREATE TABLE process_template (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, steps TEXT NOT NULL);
        CREATE TABLE sequencing_rule (id INTEGER PRIMARY KEY, priority INTEGER NOT NULL UNIQUE, rule TEXT NOT NULL);
        INSERT INTO tool_material (name, kind) VALUES ('carbide', 'carbide');
        INSERT INTO tool VALUES ('SHOP-EM-14', 'bull', 'carbide', 14, 1.5, 4, 30, 90, 40, 77);
        INSERT INTO threshold (name, value) VALUES ('eta_min', 0.8), ('mu_merge', 0.7), ('breakthrough_mm', 2.5);
        INSERT INTO process_template (name, steps) VALUES
          ('panel: corners before semi-finishing', 'r w c ss sf fs ff'),
          ('my panel', 'r  w fs');
        INSERT INTO sequencing_rule (priority, rule) VALUES
          (1, 'process with a step that must come earlier first; otherwise larger tool first'),
          (2, 'outer contour (m = -1) before inner shape (m = 0)'),
          (6, 'keep the thin walls for last');
    )sql");

    KnowledgeBase kb = openDefault(p);
    EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
    ASSERT_EQ(kb.tools().size(), 1u);
    EXPECT_EQ(kb.tools()[0].id, "SHOP-EM-14");
    EXPECT_DOUBLE_EQ(kb.threshold("eta_min"), 0.8);
    EXPECT_DOUBLE_EQ(kb.threshold("breakthrough_mm"), 2.5);   // the user's value
    EXPECT_DOUBLE_EQ(kb.threshold("rest_min_area_mm2"), 0.5);  // added
    EXPECT_TRUE(fs::exists(p.string() + ".v2.bak"));

    auto rowsOf = [&](const std::string& table, const std::string& key, const std::string& value) {
        const auto t = kb.table(table);
        std::size_t col = 0;
        while (col < t.columns.size() && t.columns[col].name != key) ++col;
        std::vector<std::vector<aeronc::kb::Cell>> out;
        for (const auto& r : t.rows)
            if (r.at(col) == value) out.push_back(r);
        return out;
    };
    // The user's template: its codes in its order, each with the shipped integral-panel step's data.
    const auto mine = rowsOf("template_step", "template", "my panel");
    ASSERT_EQ(mine.size(), 3u);
    EXPECT_EQ(mine[0][3].value_or(""), "r");
    EXPECT_EQ(mine[1][3].value_or(""), "w");
    EXPECT_EQ(mine[2][3].value_or(""), "fs");
    EXPECT_EQ(mine[0][4].value_or(""), "must");
    EXPECT_EQ(mine[0][6].value_or(""), "roughing");
    EXPECT_EQ(mine[0][7].value_or(""), "1");  // radial allowance of the shipped r step
    const auto myTemplate = rowsOf("process_template", "name", "my panel");
    ASSERT_EQ(myTemplate.size(), 1u);
    EXPECT_EQ(myTemplate[0][1].value_or(""), "integral_panel");
    EXPECT_EQ(rowsOf("step_order", "name", "v2: my panel").at(0)[1].value_or(""), "r  w fs");
    // Every template has the five keyed rules; the user's own text is kept, disabled.
    EXPECT_EQ(rowsOf("sequencing_rule", "template", "my panel").size(), 5u);
    const auto notes = rowsOf("sequencing_rule", "rule", "note");
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_EQ(notes[0][5].value_or(""), "0");
    EXPECT_EQ(notes[0][6].value_or(""), "keep the thin walls for last");

    // The shipped templates are there, row for row as a new knowledge base has them.
    KnowledgeBase fresh = openDefault(file("fresh.sqlite"));
    for (const std::string table : {"part_family", "process_template", "template_step"}) {
        for (const std::string name : {"integral_panel", "frame_beam", "rib"}) {
            const std::string key = table == "template_step" ? "template" : "name";
            auto strip = [&](std::vector<std::vector<aeronc::kb::Cell>> rows) {
                if (table == "template_step")
                    for (auto& r : rows) r[0] = std::nullopt;  // the row id differs
                return rows;
            };
            const auto a = strip(rowsOf(table, key, name));
            const auto t = fresh.table(table);
            std::size_t col = 0;
            while (t.columns[col].name != key) ++col;
            std::vector<std::vector<aeronc::kb::Cell>> b;
            for (const auto& r : t.rows)
                if (r[col] == name) b.push_back(r);
            EXPECT_FALSE(b.empty()) << table << " " << name;
            EXPECT_EQ(a, strip(b)) << table << " " << name;
        }
    }
}

// Version 3 had no impeller tables: the migration adds them with the shipped rule library and
// tapered balls, keeping the user's rows (here a tool of the user's and an edited threshold).
TEST_F(KnowledgeBaseTest, MigratesVersionThreeAddingTheImpellerTables) {
    const fs::path p = file();
    { openDefault(p); }
    rawExec(p, kWithoutVersion6);
    rawExec(p, R"sql(
        DROP TABLE impeller_route_step;
        DROP TABLE tapered_ball_tool;
        UPDATE schema_version SET version = 3;
        INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach)
            VALUES ('SHOP-BALL-5', 'ball', 'carbide', 5, 2.5, 2, 10, 30);
        UPDATE threshold SET value = 0.75 WHERE name = 'eta_min';
    )sql");
    KnowledgeBase kb = openDefault(p);
    EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
    EXPECT_TRUE(fs::exists(p.string() + ".v3.bak"));
    EXPECT_EQ(kb.tools().size(), kShippedTools + 1);
    EXPECT_DOUBLE_EQ(kb.threshold("eta_min"), 0.75);
    // The same rows as a new file has.
    const fs::path fresh = dir_ / "fresh.sqlite";
    KnowledgeBase shipped = openDefault(fresh);
    for (const char* table : {"impeller_route_step", "tapered_ball_tool"}) {
        SCOPED_TRACE(table);
        const auto migrated = kb.table(table), made = shipped.table(table);
        EXPECT_FALSE(made.rows.empty());
        EXPECT_EQ(migrated.rows, made.rows);
    }
}

// Version 4 had only the table machines: the migration adds the gantry as a new file has it,
// and keeps the user's machines and their edits (here a larger AC-5AX-L and a machine of theirs).
TEST_F(KnowledgeBaseTest, MigratesVersionFourAddingTheGantry) {
    const fs::path p = file();
    { openDefault(p); }
    rawExec(p, kWithoutVersion6);
    rawExec(p, R"sql(
        DELETE FROM machine WHERE name = 'AC-GANTRY';
        UPDATE schema_version SET version = 4;
        UPDATE machine SET travel_x = 1200 WHERE name = 'AC-5AX-L';
        INSERT INTO machine (name, type, kinematics, travel_x, travel_y, travel_z, max_spindle_rpm, power_kw,
                             max_feed_mm_min, max_force_n, efficiency, tool_change_s)
            VALUES ('SHOP-VMC', 'vertical mill', 'XYZ', 800, 500, 500, 12000, 15, 20000, 5000, 0.8, 5);
    )sql");
    KnowledgeBase kb = openDefault(p);
    EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
    EXPECT_TRUE(fs::exists(p.string() + ".v4.bak"));
    EXPECT_EQ(kb.machineNames(), (std::vector<std::string>{"AC-5AX", "AC-5AX-L", "AC-GANTRY", "SHOP-VMC", "XA5032"}));
    EXPECT_DOUBLE_EQ(kb.machine("AC-5AX-L").travelX, 1200);
    const auto gantry = kb.machine("AC-GANTRY");
    EXPECT_DOUBLE_EQ(gantry.travelX, 4000);
    EXPECT_DOUBLE_EQ(gantry.travelZ, 1500);
    // The same row as a new file has.
    KnowledgeBase shipped = openDefault(dir_ / "fresh.sqlite");
    const auto made = shipped.machine("AC-GANTRY");
    EXPECT_EQ(gantry.kinematics, made.kinematics);
    EXPECT_DOUBLE_EQ(gantry.travelY, made.travelY);
    EXPECT_DOUBLE_EQ(gantry.maxSpindleRpm, made.maxSpindleRpm);
    EXPECT_EQ(gantry.aMin, made.aMin);
    EXPECT_EQ(gantry.cMax, made.cMax);
}

// Version 5 had no necks, no edge tools and no small or long-reach end mills: the migration adds
// the crib as a new file has it to a file that carries the shipped crib, keeping the user's rows
// (a tool and an edited cutting condition of theirs).
TEST_F(KnowledgeBaseTest, MigratesVersionFiveAddingTheShopCrib) {
    const fs::path p = file();
    { openDefault(p); }
    rawExec(p, kWithoutVersion6);
    rawExec(p, R"sql(
        UPDATE schema_version SET version = 5;
        INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach)
            VALUES ('SHOP-F5', 'flat', 'carbide', 5, 0, 3, 12, 30);
        UPDATE cutting_condition SET vc_m_min = 700 WHERE workpiece_material = '7050-T7451'
            AND tool_material = 'carbide' AND operation = 'finishing';
    )sql");
    KnowledgeBase kb = openDefault(p);
    EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
    EXPECT_TRUE(fs::exists(p.string() + ".v5.bak"));
    const auto tools = kb.tools();
    EXPECT_EQ(tools.size(), kShippedTools + 1);
    const auto shop = std::find_if(tools.begin(), tools.end(), [](const Tool& t) { return t.id == "SHOP-F5"; });
    ASSERT_NE(shop, tools.end());
    EXPECT_FALSE(shop->necked());
    EXPECT_DOUBLE_EQ(shop->usableLength(), 12);  // no neck: its flutes limit it
    EXPECT_DOUBLE_EQ(kb.cuttingCondition("7050-T7451", "carbide", "finishing", 10.0).vc, 700);
    KnowledgeBase shipped = openDefault(dir_ / "fresh.sqlite");
    for (const char* table : {"edge_tool", "threshold"}) {
        SCOPED_TRACE(table);
        const auto migrated = kb.table(table), made = shipped.table(table);
        EXPECT_FALSE(made.rows.empty());
        EXPECT_EQ(migrated.rows, made.rows);
    }
    for (const Tool& t : shipped.tools()) {
        const auto m = std::find_if(tools.begin(), tools.end(), [&](const Tool& x) { return x.id == t.id; });
        ASSERT_NE(m, tools.end()) << t.id;
        EXPECT_DOUBLE_EQ(m->neckDiameter, t.neckDiameter) << t.id;
        EXPECT_DOUBLE_EQ(m->reach, t.reach) << t.id;
        EXPECT_DOUBLE_EQ(m->fluteLength, t.fluteLength) << t.id;
    }
    for (const std::string m : {"7050-T7451", "2024-T351", "Ti-6Al-4V", "45 steel"})
        for (const std::string op : {"roughing", "finishing"})
            for (double d : {0.5, 1.5}) {
                const auto a = kb.cuttingCondition(m, "carbide", op, d), b = shipped.cuttingCondition(m, "carbide", op, d);
                EXPECT_DOUBLE_EQ(a.fz, b.fz) << m << " " << op << " " << d;
                EXPECT_DOUBLE_EQ(a.ap, b.ap) << m << " " << op << " " << d;
            }
}

// A user's own crib (a version-5 file holding none of the shipped end mills) stays theirs: the
// migration adds the columns and tables but no tool and no cutting data of the shipped crib.
// Version 6 had no extra-long-neck end mills: the migration adds them to the shipped crib, as a new
// file has them, and keeps a user's tool.
TEST_F(KnowledgeBaseTest, MigratesVersionSixAddingTheExtraLongNeckSeries) {
    const fs::path p = file();
    { openDefault(p); }
    std::string drop = "DELETE FROM tool WHERE id IN (";
    for (std::size_t i = 0; i < kExtraLongNeck.size(); ++i) drop += (i ? ", '" : "'") + kExtraLongNeck[i] + "'";
    rawExec(p, drop + ");" + R"sql(
        UPDATE schema_version SET version = 6;
        INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach)
            VALUES ('SHOP-F5', 'flat', 'carbide', 5, 0, 3, 12, 30);
    )sql");
    KnowledgeBase kb = openDefault(p);
    EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
    EXPECT_TRUE(fs::exists(p.string() + ".v6.bak"));
    std::map<std::string, Tool> migrated, made;
    for (const Tool& t : kb.tools()) migrated[t.id] = t;
    KnowledgeBase shipped = openDefault(dir_ / "fresh.sqlite");
    for (const Tool& t : shipped.tools()) made[t.id] = t;
    EXPECT_EQ(migrated.size(), made.size() + 1);
    EXPECT_TRUE(migrated.count("SHOP-F5"));
    for (const std::string& id : kExtraLongNeck) {
        ASSERT_TRUE(migrated.count(id)) << id;
        const Tool& t = migrated[id];
        EXPECT_DOUBLE_EQ(t.reach, made[id].reach) << id;
        EXPECT_DOUBLE_EQ(t.neckDiameter, made[id].neckDiameter) << id;
        EXPECT_NEAR(t.reach / t.diameter, 8.0, 1e-9) << id;  // the 8 x D series
        EXPECT_DOUBLE_EQ(t.usableLength(), t.reach) << id;     // necked: cuts down to its reach
    }
}

// A user's own version-6 crib gets none of the extra-long-neck series.
TEST_F(KnowledgeBaseTest, MigratingAUsersOwnVersionSixCribAddsNoShippedTools) {
    const fs::path p = file();
    { openDefault(p); }
    rawExec(p, R"sql(
        DELETE FROM tool;
        UPDATE schema_version SET version = 6;
        INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach)
            VALUES ('MY-F10', 'flat', 'carbide', 10, 0, 3, 25, 40);
    )sql");
    KnowledgeBase kb = openDefault(p);
    EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
    const auto tools = kb.tools();
    ASSERT_EQ(tools.size(), 1u);
    EXPECT_EQ(tools[0].id, "MY-F10");
}

TEST_F(KnowledgeBaseTest, MigratingAUsersOwnCribAddsNoShippedTools) {
    const fs::path p = file();
    { openDefault(p); }
    rawExec(p, kWithoutVersion6);
    rawExec(p, R"sql(
        DELETE FROM tool;
        UPDATE schema_version SET version = 5;
        INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach)
            VALUES ('MY-F10', 'flat', 'carbide', 10, 0, 3, 25, 40), ('MY-F4', 'flat', 'carbide', 4, 0, 3, 10, 20);
    )sql");
    KnowledgeBase kb = openDefault(p);
    EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
    const auto tools = kb.tools();
    ASSERT_EQ(tools.size(), 2u);
    EXPECT_EQ(tools[0].id, "MY-F10");
    EXPECT_EQ(tools[1].id, "MY-F4");
    EXPECT_TRUE(kb.table("edge_tool").rows.empty());
    // Its cutting data are its own: no small-tool row was added beside them.
    EXPECT_DOUBLE_EQ(kb.cuttingCondition("7050-T7451", "carbide", "roughing", 0.5).fz, 0.04);
    EXPECT_TRUE(kb.findThreshold("long_reach_ratio").has_value());
}

// Version 7 to 8: the long-reach D3 ball joins a file that carries the shipped crib, not a
// user's own; the user's rows stay.
TEST_F(KnowledgeBaseTest, MigratesVersionSevenAddingTheLongReachSmallBall) {
    for (bool ownCrib : {false, true}) {
        SCOPED_TRACE(ownCrib ? "a user's own crib" : "the shipped crib");
        const fs::path p = dir_ / (ownCrib ? "own7.sqlite" : "shipped7.sqlite");
        { openDefault(p); }
        std::string dropLater = "DELETE FROM tool WHERE id IN ('EM-BALL3x30'";
        for (const std::string& id : kVersion9) dropLater += ", '" + id + "'";
        rawExec(p, dropLater + "); UPDATE schema_version SET version = 7;" +
                       (ownCrib ? "DELETE FROM tool;" : "") +
                       "INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach) "
                       "VALUES ('MY-BALL5', 'ball', 'carbide', 5, 2.5, 2, 10, 25);");
        KnowledgeBase kb = openDefault(p);
        EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
        std::map<std::string, Tool> byId;
        for (const Tool& t : kb.tools()) byId[t.id] = t;
        EXPECT_TRUE(byId.count("MY-BALL5"));
        EXPECT_EQ(byId.size(), ownCrib ? 1u : kShippedTools + 1);
        if (ownCrib) continue;
        for (const std::string& id : kVersion9) EXPECT_TRUE(byId.count(id)) << id;
        ASSERT_TRUE(byId.count("EM-BALL3x30"));
        const Tool& b = byId["EM-BALL3x30"];
        EXPECT_EQ(b.type, "ball");
        EXPECT_DOUBLE_EQ(b.diameter, 3);
        EXPECT_DOUBLE_EQ(b.reach, 30);
        EXPECT_DOUBLE_EQ(b.neckDiameter, 2.85);
        EXPECT_DOUBLE_EQ(b.usableLength(), 30);  // necked: it cuts down to its reach
        // Cutting data for it: the carbide rows for tools below 6 mm.
        EXPECT_GT(kb.cuttingCondition("7050-T7451", "carbide", "roughing", 3.0).fz, 0);
    }
}

// Version 8 to 9: the micro end mills join a file that carries the shipped crib, as
// a new file has them, and not a user's own; the user's rows stay.
TEST_F(KnowledgeBaseTest, MigratesVersionEightAddingTheMicroEndMills) {
    KnowledgeBase shipped = openDefault(dir_ / "fresh9.sqlite");
    std::map<std::string, Tool> made;
    for (const Tool& t : shipped.tools()) made[t.id] = t;
    for (bool ownCrib : {false, true}) {
        SCOPED_TRACE(ownCrib ? "a user's own crib" : "the shipped crib");
        const fs::path p = dir_ / (ownCrib ? "own8.sqlite" : "shipped8.sqlite");
        { openDefault(p); }
        std::string drop = "DELETE FROM tool WHERE id IN (";
        for (std::size_t i = 0; i < kVersion9.size(); ++i) drop += (i ? ", '" : "'") + kVersion9[i] + "'";
        rawExec(p, drop + "); UPDATE schema_version SET version = 8;" + (ownCrib ? "DELETE FROM tool;" : "") +
                       "INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach) "
                       "VALUES ('MY-F30', 'flat', 'carbide', 30, 0, 4, 45, 90);");
        KnowledgeBase kb = openDefault(p);
        EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
        EXPECT_TRUE(fs::exists(p.string() + ".v8.bak"));
        std::map<std::string, Tool> byId;
        for (const Tool& t : kb.tools()) byId[t.id] = t;
        EXPECT_TRUE(byId.count("MY-F30"));
        EXPECT_EQ(byId.size(), ownCrib ? 1u : kShippedTools + 1);
        if (ownCrib) continue;
        for (const std::string& id : kVersion9) {
            ASSERT_TRUE(byId.count(id)) << id;
            const Tool& t = byId[id];
            EXPECT_NO_THROW(t.validate()) << id;
            EXPECT_TRUE(t.necked()) << id;
            EXPECT_DOUBLE_EQ(t.usableLength(), t.reach) << id;  // necked: it cuts down to its reach
            EXPECT_DOUBLE_EQ(t.reach, made.at(id).reach) << id;
            EXPECT_DOUBLE_EQ(t.neckDiameter, made.at(id).neckDiameter) << id;
            EXPECT_GT(kb.cuttingCondition("7050-T7451", "carbide", "roughing", t.diameter).fz, 0) << id;
        }
        EXPECT_DOUBLE_EQ(byId["EM-F0.2"].diameter, 0.2);
        EXPECT_DOUBLE_EQ(byId["EM-F0.3"].diameter, 0.3);
        for (const std::string& id : kVersion9)  // one layer cuts lettering 0.5 mm deep
            EXPECT_GE(byId[id].passHeight(), 0.52) << id;
    }
}

// Version 9 to 10: the long-reach end mills D16-D32 join a file that carries the shipped crib,
// as a new file has them, and not a user's own; the user's rows stay. They reach 80-160 mm
// (5-6.5 x D) on a neck below the cutter, cut layers no higher than their flutes, and take the
// long-reach reductions of the cutting data for every material.
TEST_F(KnowledgeBaseTest, MigratesVersionNineAddingTheLongReachEndMills) {
    KnowledgeBase shipped = openDefault(dir_ / "fresh10.sqlite");
    std::map<std::string, Tool> made;
    for (const Tool& t : shipped.tools()) made[t.id] = t;
    for (bool ownCrib : {false, true}) {
        SCOPED_TRACE(ownCrib ? "a user's own crib" : "the shipped crib");
        const fs::path p = dir_ / (ownCrib ? "own9.sqlite" : "shipped9.sqlite");
        { openDefault(p); }
        std::string drop = "DELETE FROM tool WHERE id IN (";
        for (std::size_t i = 0; i < kVersion10.size(); ++i) drop += (i ? ", '" : "'") + kVersion10[i] + "'";
        rawExec(p, drop + "); UPDATE schema_version SET version = 9;" + (ownCrib ? "DELETE FROM tool;" : "") +
                       "INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach) "
                       "VALUES ('MY-F40', 'flat', 'carbide', 40, 0, 4, 60, 120);");
        KnowledgeBase kb = openDefault(p);
        EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
        EXPECT_TRUE(fs::exists(p.string() + ".v9.bak"));
        std::map<std::string, Tool> byId;
        for (const Tool& t : kb.tools()) byId[t.id] = t;
        EXPECT_TRUE(byId.count("MY-F40"));
        EXPECT_EQ(byId.size(), ownCrib ? 1u : kShippedTools + 1);
        if (ownCrib) continue;
        double longest = 0;
        const aeronc::kb::LongReach reduction = aeronc::kb::LongReach::of(kb);
        for (const std::string& id : kVersion10) {
            ASSERT_TRUE(byId.count(id)) << id;
            const Tool& t = byId[id];
            EXPECT_NO_THROW(t.validate()) << id;
            EXPECT_TRUE(t.isEndMill()) << id;
            EXPECT_TRUE(t.necked()) << id;
            EXPECT_LT(t.neckDiameter, t.diameter) << id;
            EXPECT_DOUBLE_EQ(t.reach, made.at(id).reach) << id;
            EXPECT_DOUBLE_EQ(t.fluteLength, made.at(id).fluteLength) << id;
            EXPECT_GE(t.diameter, 16) << id;
            EXPECT_LE(t.diameter, 32) << id;
            EXPECT_GE(t.usableLength(), 80) << id;
            EXPECT_LE(t.usableLength(), 160) << id;
            EXPECT_LT(t.passHeight(), t.usableLength()) << id;
            longest = std::max(longest, t.usableLength());
            for (const std::string m : {"7050-T7451", "2024-T351", "Ti-6Al-4V", "45 steel"})
                for (const std::string op : {"roughing", "finishing"}) {
                    const auto c = kb.cuttingCondition(m, t.material, op, t.diameter);
                    EXPECT_GT(c.fz, 0) << id << " " << m << " " << op;
                    // Reduced axial depth and chip for the long overhang.
                    ASSERT_TRUE(reduction.applies(t)) << id;
                    const auto r = reduction.applied(t, c);
                    EXPECT_LT(r.ap, c.ap) << id << " " << m << " " << op;
                    EXPECT_LT(r.fz, c.fz) << id << " " << m << " " << op;
                }
        }
        EXPECT_DOUBLE_EQ(longest, 160);
        // Before version 10 no end mill reached past 60 mm.
        for (const auto& [id, t] : byId)
            if (t.isEndMill() && id != "MY-F40" &&
                std::find(kVersion10.begin(), kVersion10.end(), id) == kVersion10.end())
                EXPECT_LE(t.usableLength(), 60) << id;
    }
}

// Version 10 to 11: the D4 x 40 end mill and the 90 degree chamfer mills D25 and D32 join a file
// that carries the shipped crib, as a new file has them, and not a user's own; the user's rows
// stay. The end mill reaches 40 mm on its neck (10 x D) with the long-reach data; the chamfer
// mills cover chamfers up to 10.8 and 13.8 mm wide and take finishing data in every material.
TEST_F(KnowledgeBaseTest, MigratesVersionTenAddingTheD4x40AndTheLargeChamferMills) {
    KnowledgeBase shipped = openDefault(dir_ / "fresh11.sqlite");
    std::map<std::string, Tool> made;
    for (const Tool& t : shipped.tools()) made[t.id] = t;
    std::map<std::string, toolselect::EdgeTool> madeEdge;
    for (const toolselect::EdgeTool& t : shipped.edgeTools()) madeEdge[t.id] = t;
    for (bool ownCrib : {false, true}) {
        SCOPED_TRACE(ownCrib ? "a user's own crib" : "the shipped crib");
        const fs::path p = dir_ / (ownCrib ? "own10.sqlite" : "shipped10.sqlite");
        { openDefault(p); }
        rawExec(p, std::string("DELETE FROM tool WHERE id = 'EM-F4x40'; "
                               "DELETE FROM edge_tool WHERE id IN ('CM-90-D25', 'CM-90-D32'); "
                               "UPDATE schema_version SET version = 10;") +
                       (ownCrib ? "DELETE FROM tool; DELETE FROM edge_tool;" : "") +
                       "INSERT INTO tool (id, type, tool_material, diameter, corner_radius, flutes, flute_length, reach) "
                       "VALUES ('MY-F40', 'flat', 'carbide', 40, 0, 4, 60, 120);"
                       "INSERT INTO edge_tool (id, kind, tool_material, diameter, tip_diameter, included_angle, "
                       "flutes, reach) VALUES ('MY-CM-D40', 'chamfer', 'carbide', 40, 5, 90, 4, 40);");
        KnowledgeBase kb = openDefault(p);
        EXPECT_EQ(kb.schemaVersion(), KnowledgeBase::kSchemaVersion);
        EXPECT_TRUE(fs::exists(p.string() + ".v10.bak"));
        std::map<std::string, Tool> byId;
        for (const Tool& t : kb.tools()) byId[t.id] = t;
        std::map<std::string, toolselect::EdgeTool> edgeById;
        for (const toolselect::EdgeTool& t : kb.edgeTools()) edgeById[t.id] = t;
        EXPECT_TRUE(byId.count("MY-F40"));
        EXPECT_TRUE(edgeById.count("MY-CM-D40"));
        EXPECT_EQ(byId.size(), ownCrib ? 1u : kShippedTools + 1);
        EXPECT_EQ(edgeById.size(), ownCrib ? 1u : madeEdge.size() + 1);
        if (ownCrib) continue;
        const aeronc::kb::LongReach reduction = aeronc::kb::LongReach::of(kb);
        for (const std::string& id : kVersion11Tools) {
            ASSERT_TRUE(byId.count(id)) << id;
            const Tool& t = byId[id];
            EXPECT_NO_THROW(t.validate()) << id;
            EXPECT_EQ(t.type, "flat") << id;
            EXPECT_TRUE(t.necked()) << id;
            EXPECT_DOUBLE_EQ(t.diameter, 4) << id;
            EXPECT_DOUBLE_EQ(t.neckDiameter, made.at(id).neckDiameter) << id;
            EXPECT_DOUBLE_EQ(t.usableLength(), 40) << id;
            EXPECT_DOUBLE_EQ(t.fluteLength, made.at(id).fluteLength) << id;
            ASSERT_TRUE(reduction.applies(t)) << id;
            for (const std::string m : {"7050-T7451", "2024-T351", "Ti-6Al-4V", "45 steel"})
                for (const std::string op : {"roughing", "finishing"})
                    EXPECT_GT(kb.cuttingCondition(m, t.material, op, t.diameter).fz, 0) << id << " " << m << " " << op;
        }
        for (const std::string& id : kVersion11EdgeTools) {
            ASSERT_TRUE(edgeById.count(id)) << id;
            const toolselect::EdgeTool& t = edgeById[id];
            const toolselect::EdgeTool& n = madeEdge.at(id);
            EXPECT_EQ(t.kind, "chamfer") << id;
            EXPECT_DOUBLE_EQ(t.includedAngle, 90) << id;
            EXPECT_DOUBLE_EQ(t.diameter, n.diameter) << id;
            EXPECT_DOUBLE_EQ(t.tipDiameter, n.tipDiameter) << id;
            EXPECT_DOUBLE_EQ(t.reach, n.reach) << id;
            for (const std::string m : {"7050-T7451", "2024-T351", "Ti-6Al-4V", "45 steel"})
                EXPECT_GT(kb.cuttingCondition(m, t.material, "finishing", t.diameter).fz, 0) << id << " " << m;
        }
        // The widths they cover: CTC-05's 9.525 mm countersink and CTC-03's 12.7 mm chamfers, both at 45 degrees.
        std::vector<toolselect::EdgeTool> crib;
        for (const auto& [id, t] : edgeById)
            if (id != "MY-CM-D40") crib.push_back(t);
        for (const auto& [width, hole, id] : std::vector<std::tuple<double, double, std::string>>{
                 {9.525, 254, "CM-90-D25"}, {12.7, 0, "CM-90-D32"}}) {
            const auto c = toolselect::chamferTool(crib, {90, width, width, hole});
            ASSERT_TRUE(c.tool) << c.why;
            EXPECT_EQ(c.tool->id, id);
        }
    }
}

// The shop crib as shipped: the catalogue sizes, necks below the cutter, reach beyond the flutes
// on the necked tools, edge tools, and small-tool cutting data below the standard rows.
TEST_F(KnowledgeBaseTest, ShippedShopCrib) {
    KnowledgeBase kb = openDefault(file());
    std::map<std::string, Tool> byId;
    for (const Tool& t : kb.tools()) byId[t.id] = t;
    std::size_t necked = 0;
    for (const auto& [id, t] : byId)
        if (t.necked()) {
            ++necked;
            EXPECT_LT(t.neckDiameter, t.diameter) << id;
            EXPECT_GT(t.reach, t.fluteLength) << id;
            EXPECT_DOUBLE_EQ(t.usableLength(), t.reach) << id;
            EXPECT_DOUBLE_EQ(t.passHeight(), t.fluteLength) << id;
        }
    // All but EM-BALL16; EM-BALL3x30; version 9's, 10's and 11's.
    EXPECT_EQ(necked, kCribTools - 1 + 1 + kVersion9.size() + kVersion10.size() + kVersion11Tools.size());
    for (const char* id : {"EM-F0.5", "EM-F1", "EM-F1.5", "EM-F2.5", "EM-BALL0.5", "EM-BALL1"})
        EXPECT_TRUE(byId.count(id)) << id;
    // The long-reach series: D6 x 30, D8 x 40, D10 x 50, D12 x 60, flat and bull-nose.
    for (const auto& [flat, bull, d, reach] : std::vector<std::tuple<const char*, const char*, double, double>>{
             {"EM-F6x30", "EM-B6R1x30", 6, 30}, {"EM-F8x40", "EM-B8R1x40", 8, 40},
             {"EM-F10x50", "EM-B10R1x50", 10, 50}, {"EM-F12x60", "EM-B12R2x60", 12, 60}}) {
        for (const char* id : {flat, bull}) {
            ASSERT_TRUE(byId.count(id)) << id;
            EXPECT_DOUBLE_EQ(byId[id].diameter, d) << id;
            EXPECT_DOUBLE_EQ(byId[id].usableLength(), reach) << id;
        }
        EXPECT_EQ(byId[flat].type, "flat");
        EXPECT_EQ(byId[bull].type, "bull");
    }
    const auto edge = kb.table("edge_tool");
    std::set<double> angles, radii;
    for (const auto& row : edge.rows) {
        if (*row[1] == "chamfer") angles.insert(std::stod(*row[5]));
        else radii.insert(std::stod(*row[6]));
    }
    EXPECT_EQ(angles, (std::set<double>{45, 90}));
    EXPECT_EQ(radii, (std::set<double>{1, 2, 3, 4, 5}));
    // Every material has small-tool data, thinner chips and layers than at 6 mm.
    for (const std::string m : {"7050-T7451", "2024-T351", "Ti-6Al-4V", "45 steel"})
        for (const std::string op : {"roughing", "finishing"}) {
            const auto small = kb.cuttingCondition(m, "carbide", op, 0.5);
            const auto one = kb.cuttingCondition(m, "carbide", op, 1.0);
            const auto six = kb.cuttingCondition(m, "carbide", op, 6.0);
            EXPECT_LT(small.fz, one.fz) << m << " " << op;
            EXPECT_LT(one.fz, six.fz) << m << " " << op;
            EXPECT_LT(one.ap, six.ap) << m << " " << op;
        }
}
