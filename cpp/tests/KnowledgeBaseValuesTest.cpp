// Every number read from a tool library, a bit file or the knowledge-base file is checked:
// never wrapped (tool number 4294967297 stored as 1), never replaced (a fractional flute count
// read as the default 2, a negative cutting edge as the bit's length), never read as 0.0 or
// inf from a cell that holds text, NULL or an overflow. A damaged file is reported as damaged.
#include "ErrorOf.h"

#include <aeronc/core/Error.h>
#include <aeronc/core/TextFile.h>
#include <aeronc/kb/FreeCadToolLibrary.h>
#include <aeronc/kb/KnowledgeBase.h>

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace aeronc;
using namespace aeronc::kb;
using aeronc::test::inputErrorOf;

namespace {

class KnowledgeBaseValuesTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("aeronc_kbvalues_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path kbFile() const { return dir_ / "kb.sqlite"; }
    KnowledgeBase openKb() {
        const fs::path res(AERONC_RESOURCES);
        return KnowledgeBase::open(kbFile().string(), readTextFile((res / "kb/schema.sql").string(), "schema"),
                                   readTextFile((res / "kb/default_data.sql").string(), "data"));
    }
    // SQL on a plain connection, as another program would edit the file.
    void rawExec(const std::string& sql) {
        sqlite3* db = nullptr;
        ASSERT_EQ(sqlite3_open(kbFile().c_str(), &db), SQLITE_OK);
        char* err = nullptr;
        const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &err);
        const std::string msg = err ? err : "";
        sqlite3_free(err);
        sqlite3_close(db);
        ASSERT_EQ(rc, SQLITE_OK) << msg;
    }
    // A library in FreeCAD's layout: Library/<name>.fctl and Bit/a.fctb.
    fs::path library(const std::string& fctl, const std::string& bit = R"({"shape": "endmill.fcstd",
        "parameter": {"Diameter": "6 mm", "CuttingEdgeHeight": "12 mm", "Length": "50 mm"}})") {
        writeTextFileAtomically((dir_ / "lib" / "Bit" / "a.fctb").string(), bit);
        const fs::path p = dir_ / "lib" / "Library" / "L.fctl";
        writeTextFileAtomically(p.string(), fctl);
        return p;
    }
    static FreeCadBit bit(const std::string& document) { return {1, "a.fctb", document}; }

    fs::path dir_;
};

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_F(KnowledgeBaseValuesTest, LibraryNumbersBeyondTheirRangeAreRefused) {
    std::string e = inputErrorOf([&] { readFreeCadLibrary(library(R"({"version": 1, "tools": [{"nr": 4294967297, "path": "a.fctb"}]})").string()); });
    EXPECT_TRUE(has(e, "nr") && has(e, "4294967297")) << e;
    e = inputErrorOf([&] { readFreeCadLibrary(library(R"({"version": 1, "tools": [{"nr": -1, "path": "a.fctb"}]})").string()); });
    EXPECT_TRUE(has(e, "nr")) << e;
    e = inputErrorOf([&] { readFreeCadLibrary(library(R"({"version": 99999999999, "tools": []})").string()); });
    EXPECT_TRUE(has(e, "version") && has(e, "99999999999")) << e;
    e = inputErrorOf([&] { readFreeCadLibrary(library(R"({"version": "one", "tools": []})").string()); });
    EXPECT_TRUE(has(e, "version")) << e;
    // In range: read as written.
    const FreeCadLibrary lib = readFreeCadLibrary(library(R"({"version": 3, "tools": [{"nr": 2147483647, "path": "a.fctb"}]})").string());
    EXPECT_EQ(lib.version, 3);
    ASSERT_EQ(lib.bits.size(), 1u);
    EXPECT_EQ(lib.bits[0].nr, 2147483647);
}

TEST_F(KnowledgeBaseValuesTest, BitFlutesAndCuttingEdgeAreCheckedNotReplaced) {
    const std::string head = R"({"shape": "endmill.fcstd", "parameter": {"Diameter": "6 mm", "CuttingEdgeHeight": "12 mm", "Length": "50 mm"}, "attribute": {"Flutes": )";
    for (const std::string flutes : {"4294967297", "2.5", "\"2.5\"", "\"abc\"", "0", "-3", "\"\"", "[3]"}) {
        const std::string e = inputErrorOf([&] { toolFromBit(bit(head + flutes + "}}"), {}); });
        EXPECT_TRUE(has(e, "a.fctb") && has(e, "Flutes")) << flutes << ": " << e;
    }
    EXPECT_EQ(toolFromBit(bit(head + "3}}"), {}).tool.flutes, 3);
    EXPECT_EQ(toolFromBit(bit(head + "\"4\"}}"), {}).tool.flutes, 4);  // FreeCAD 0.19 wrote strings

    for (const std::string edge : {"-5 mm", "0 mm"}) {
        const std::string e = inputErrorOf([&] {
            toolFromBit(bit(R"({"shape": "endmill.fcstd", "parameter": {"Diameter": "6 mm", "CuttingEdgeHeight": ")" + edge +
                            R"(", "Length": "50 mm"}})"),
                        {});
        });
        EXPECT_TRUE(has(e, "CuttingEdgeHeight")) << edge << ": " << e;
    }
    for (const std::string length : {"1e400 mm", "nan mm", "-50 mm"}) {
        const std::string e = inputErrorOf([&] {
            toolFromBit(bit(R"({"shape": "drill.fcstd", "parameter": {"Diameter": "6 mm", "Length": ")" + length + "\"}}"), {});
        });
        EXPECT_TRUE(has(e, "Length")) << length << ": " << e;
    }
}

TEST_F(KnowledgeBaseValuesTest, ToolCellsThatAreNoNumberAreNamed) {
    { openKb(); }
    struct Case {
        const char* sql;
        const char* expect;
    };
    // CHECK (diameter > 0) lets text through: SQLite sorts any text above any number.
    const Case cases[] = {
        {"UPDATE tool SET diameter = 'abc' WHERE id = 'EM-F2'", "diameter"},
        {"UPDATE tool SET diameter = 1e999 WHERE id = 'EM-F2'", "diameter"},
        {"UPDATE tool SET flutes = 4294967295 WHERE id = 'EM-F2'", "flutes"},
        {"UPDATE tool SET flutes = 2.5 WHERE id = 'EM-F2'", "flutes"},
        {"UPDATE tool SET diameter = x'00ff' WHERE id = 'EM-F2'", "binary data"},
    };
    for (const Case& c : cases) {
        fs::remove(kbFile());
        { openKb(); }
        rawExec(c.sql);
        KnowledgeBase kb = openKb();
        const std::string e = inputErrorOf([&] { kb.tools(); });
        EXPECT_TRUE(has(e, "EM-F2") && has(e, c.expect)) << c.sql << ": " << e;
    }
    // NULL where the schema says NOT NULL: a table rebuilt by another program without it.
    fs::remove(kbFile());
    { openKb(); }
    rawExec("PRAGMA foreign_keys = OFF; CREATE TABLE t AS SELECT * FROM tool; DROP TABLE tool; "
            "ALTER TABLE t RENAME TO tool; UPDATE tool SET diameter = NULL WHERE id = 'EM-F2';");
    KnowledgeBase kb = openKb();
    const std::string e = inputErrorOf([&] { kb.tools(); });
    EXPECT_TRUE(has(e, "EM-F2") && has(e, "diameter")) << e;
}

TEST_F(KnowledgeBaseValuesTest, CuttingDataThresholdsAndMachinesAreChecked) {
    { openKb(); }
    rawExec("UPDATE cutting_condition SET vc_m_min = 1e999; UPDATE threshold SET value = 'abc' WHERE name = 'eta_min';"
            "UPDATE machine SET max_spindle_rpm = 'fast' WHERE name = 'AC-5AX'");
    KnowledgeBase kb = openKb();
    std::string e = inputErrorOf([&] { kb.cuttingCondition("7050-T7451", "carbide", "roughing", 10.0); });
    EXPECT_TRUE(has(e, "vc_m_min")) << e;
    e = inputErrorOf([&] { kb.threshold("eta_min"); });
    EXPECT_TRUE(has(e, "eta_min") && has(e, "value")) << e;
    e = inputErrorOf([&] { kb.machine("AC-5AX"); });
    EXPECT_TRUE(has(e, "AC-5AX") && has(e, "max_spindle_rpm")) << e;
    // The lookups that may find nothing say so only when nothing is there.
    e = inputErrorOf([&] { kb.findCuttingCondition("7050-T7451", "carbide", "roughing", 10.0); });
    EXPECT_TRUE(has(e, "vc_m_min")) << e;
    EXPECT_FALSE(kb.findCuttingCondition("7050-T7451", "carbide", "engraving", 10.0).has_value());
    e = inputErrorOf([&] { kb.findThreshold("eta_min"); });
    EXPECT_TRUE(has(e, "eta_min")) << e;
    EXPECT_FALSE(kb.findThreshold("no_such_threshold").has_value());
    // The others still read.
    EXPECT_DOUBLE_EQ(kb.threshold("mu_merge"), 0.7);
}

TEST_F(KnowledgeBaseValuesTest, ADamagedThresholdPageIsReportedAsDamaged) {
    // The threshold table's page, or its primary-key index's page, made an empty leaf: its
    // entries vanish, as a torn write can do. The lookup then finds nothing.
    for (const char* object : {"threshold", "sqlite_autoindex_threshold_1"}) {
        fs::remove(kbFile());
        { openKb(); }
        int page = 0, pageSize = 0;
        {
            sqlite3* db = nullptr;
            ASSERT_EQ(sqlite3_open(kbFile().c_str(), &db), SQLITE_OK);
            sqlite3_stmt* s = nullptr;
            sqlite3_prepare_v2(db, "SELECT rootpage FROM sqlite_master WHERE name = ?", -1, &s, nullptr);
            sqlite3_bind_text(s, 1, object, -1, SQLITE_STATIC);
            ASSERT_EQ(sqlite3_step(s), SQLITE_ROW) << object;
            page = sqlite3_column_int(s, 0);
            sqlite3_finalize(s);
            sqlite3_prepare_v2(db, "PRAGMA page_size", -1, &s, nullptr);
            ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
            pageSize = sqlite3_column_int(s, 0);
            sqlite3_finalize(s);
            sqlite3_close(db);
        }
        ASSERT_GT(page, 1);
        {
            std::fstream f(kbFile(), std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(static_cast<std::streamoff>(page - 1) * pageSize + 3);  // the cell count
            f.put(0).put(0);
        }
        KnowledgeBase kb = openKb();
        const std::string e = inputErrorOf([&] { kb.threshold("eta_min"); });
        EXPECT_TRUE(has(e, "corrupt")) << object << ": " << e;
        EXPECT_FALSE(has(e, "unknown threshold")) << object << ": " << e;
    }
}
