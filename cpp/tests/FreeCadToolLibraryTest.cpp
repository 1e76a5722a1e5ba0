// The FreeCAD tool bridge: a tool library imported into the knowledge base and exported again
// is the same bytes; edits in the knowledge base reach the bit documents; bad libraries are
// refused with the database left as it was.
#include "ErrorOf.h"

#include <aeronc/core/Error.h>
#include <aeronc/core/TextFile.h>
#include <aeronc/kb/FreeCadToolLibrary.h>
#include <aeronc/kb/KnowledgeBase.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sqlite3.h>

#include <filesystem>
#include <functional>
#include <map>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace aeronc;
using namespace aeronc::kb;

using aeronc::test::errorOf;

namespace {

// FreeCAD's own library, installed with the freecad package the set-up script installs.
const fs::path kFreeCadTools = "/usr/share/freecad/Mod/Path/Tools";

class FreeCadToolLibraryTest : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("aeronc_fctl_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    KnowledgeBase openKb(const std::string& name = "kb.sqlite") {
        const fs::path res(AERONC_RESOURCES);
        return KnowledgeBase::open((dir_ / name).string(), readTextFile((res / "kb/schema.sql").string(), "schema"),
                                   readTextFile((res / "kb/default_data.sql").string(), "data"));
    }

    // A small library in FreeCAD's folder layout, with features FreeCAD's sample lacks:
    // inch units, a material and flute attribute, a bull nose's flat radius.
    fs::path writeLibrary(const std::string& name, const std::map<std::string, std::string>& bits,
                          const std::string& fctl) {
        for (const auto& [file, text] : bits) writeTextFileAtomically((dir_ / "lib" / "Bit" / file).string(), text);
        const fs::path p = dir_ / "lib" / "Library" / (name + ".fctl");
        writeTextFileAtomically(p.string(), fctl);
        return p;
    }
    fs::path shopLibrary() {
        return writeLibrary(
            "Shop",
            {{"em10.fctb", R"({
  "version": 2,
  "name": "10 mm end mill",
  "shape": "endmill.fcstd",
  "parameter": {
    "Diameter": "10.0000 mm",
    "CuttingEdgeHeight": "22.0000 mm",
    "Length": "72.0000 mm",
    "ShankDiameter": "10.0000 mm"
  },
  "attribute": {
    "Flutes": 3,
    "Material": "Carbide"
  }
})"},
             {"bull_half_inch.fctb", R"({
  "version": 2,
  "name": "1/2 in bull nose",
  "shape": "bullnose.fcstd",
  "parameter": {
    "Diameter": "0.5000 in",
    "FlatRadius": "0.1875 in",
    "CuttingEdgeHeight": "1.0000 in",
    "Length": "3.0000 in"
  },
  "attribute": {}
})"}},
            R"({
  "tools": [
    {
      "nr": 4,
      "path": "em10.fctb"
    },
    {
      "nr": 7,
      "path": "bull_half_inch.fctb"
    }
  ],
  "version": 1
})");
    }

    static int count(KnowledgeBase& kb) { return static_cast<int>(kb.tools().size()); }

    fs::path dir_;
};

const toolselect::Tool* find(const std::vector<toolselect::Tool>& tools, const std::string& id) {
    for (const auto& t : tools)
        if (t.id == id) return &t;
    return nullptr;
}

}  // namespace

TEST_F(FreeCadToolLibraryTest, FreeCadDefaultLibraryRoundTripsUnchanged) {
    const fs::path fctl = kFreeCadTools / "Library" / "Default.fctl";
    if (!fs::exists(fctl)) GTEST_SKIP() << "FreeCAD's tool library is not installed (" << fctl << ")";
    KnowledgeBase kb = openKb();
    const int before = count(kb);
    const FreeCadLibrary lib = readFreeCadLibrary(fctl.string());
    ASSERT_EQ(lib.bits.size(), 9u);
    EXPECT_EQ(kb.importFreeCadLibrary(lib), 9);
    EXPECT_EQ(count(kb), before + 9);

    // The selector sees them with their FreeCAD dimensions.
    const auto tools = kb.tools();
    const auto* em = find(tools, "5mm_Endmill");
    ASSERT_TRUE(em);
    EXPECT_EQ(em->type, "flat");
    EXPECT_DOUBLE_EQ(em->diameter, 5);
    EXPECT_DOUBLE_EQ(em->fluteLength, 30);
    EXPECT_DOUBLE_EQ(em->reach, 50);
    const auto* bull = find(tools, "6mm_Bullnose");
    ASSERT_TRUE(bull);
    EXPECT_EQ(bull->type, "bull");
    EXPECT_DOUBLE_EQ(bull->cornerRadius, 3 - 1.5);  // radius minus FlatRadius
    EXPECT_EQ(find(tools, "6mm_Ball_End")->type, "ball");
    EXPECT_DOUBLE_EQ(find(tools, "6mm_Ball_End")->cornerRadius, 3);
    EXPECT_EQ(find(tools, "5mm_Drill")->type, "drill");
    EXPECT_EQ(find(tools, "probe")->type, "other");
    EXPECT_EQ(find(tools, "60degree_Vbit")->type, "other");

    // Exported again: every file the same bytes as FreeCAD's.
    const auto written = writeFreeCadLibrary(kb.freeCadLibrary("Default"), (dir_ / "out").string());
    ASSERT_EQ(written.size(), 10u);
    EXPECT_EQ(readTextFile(written[0], "fctl"), readTextFile(fctl.string(), "fctl"));
    for (const auto& bit : lib.bits)
        EXPECT_EQ(readTextFile((dir_ / "out" / "Bit" / bit.fileName).string(), "bit"),
                  readTextFile((kFreeCadTools / "Bit" / bit.fileName).string(), "bit"))
            << bit.fileName;
}

TEST_F(FreeCadToolLibraryTest, UnitsAttributesAndNumbersKept) {
    KnowledgeBase kb = openKb();
    const FreeCadLibrary lib = readFreeCadLibrary(shopLibrary().string());
    kb.importFreeCadLibrary(lib, BitDefaults{"HSS", 2});
    const auto tools = kb.tools();
    const auto* em = find(tools, "em10");
    ASSERT_TRUE(em);
    EXPECT_EQ(em->material, "carbide");  // "Carbide" matched ignoring case, not the HSS default
    EXPECT_EQ(em->flutes, 3);
    EXPECT_DOUBLE_EQ(em->reach, 72);
    const auto* bull = find(tools, "bull_half_inch");
    ASSERT_TRUE(bull);
    EXPECT_EQ(bull->material, "HSS");
    EXPECT_EQ(bull->flutes, 2);
    EXPECT_NEAR(bull->diameter, 12.7, 1e-12);
    EXPECT_NEAR(bull->cornerRadius, 12.7 / 2 - 0.1875 * 25.4, 1e-12);
    EXPECT_NEAR(bull->fluteLength, 25.4, 1e-12);

    const FreeCadLibrary back = kb.freeCadLibrary("Shop");
    ASSERT_EQ(back.bits.size(), 2u);
    EXPECT_EQ(back.bits[0].nr, 4);
    EXPECT_EQ(back.bits[1].nr, 7);
    EXPECT_EQ(back.bits[1].document, lib.bits[1].document);  // inch text untouched
    EXPECT_EQ(back.document, lib.document);
}

TEST_F(FreeCadToolLibraryTest, EditedDimensionReachesTheBitOnly) {
    KnowledgeBase kb = openKb();
    const FreeCadLibrary lib = readFreeCadLibrary(shopLibrary().string());
    kb.importFreeCadLibrary(lib);
    {
        // A user's edit through the database (the editor panel does the same in a transaction).
        sqlite3* db = nullptr;
        ASSERT_EQ(sqlite3_open((dir_ / "kb.sqlite").c_str(), &db), SQLITE_OK);
        ASSERT_EQ(sqlite3_exec(db, "UPDATE tool SET diameter = 9.5 WHERE id = 'em10'", nullptr, nullptr, nullptr),
                  SQLITE_OK);
        sqlite3_close(db);
    }
    const FreeCadLibrary back = kb.freeCadLibrary("Shop");
    const auto edited = nlohmann::ordered_json::parse(back.bits[0].document);
    const auto original = nlohmann::ordered_json::parse(lib.bits[0].document);
    EXPECT_EQ(edited["parameter"]["Diameter"], "9.5000 mm");
    auto same = edited;
    same["parameter"]["Diameter"] = original["parameter"]["Diameter"];
    EXPECT_EQ(same, original);  // nothing else changed, key order included
    EXPECT_EQ(back.bits[1].document, lib.bits[1].document);

    // And it comes back in: a fresh knowledge base reads 9.5 mm from the exported files.
    writeFreeCadLibrary(back, (dir_ / "out").string());
    KnowledgeBase other = openKb("other.sqlite");
    other.importFreeCadLibrary(readFreeCadLibrary((dir_ / "out" / "Library" / "Shop.fctl").string()));
    EXPECT_DOUBLE_EQ(find(other.tools(), "em10")->diameter, 9.5);
}

TEST_F(FreeCadToolLibraryTest, KnowledgeBaseToolsBecomeBits) {
    KnowledgeBase kb = openKb();
    const FreeCadLibrary lib = kb.freeCadLibraryOf("Chosen", {"EM-B16R2", "EM-F10", "DR-8.5", "EM-BALL6"});
    ASSERT_EQ(lib.bits.size(), 4u);
    const auto written = writeFreeCadLibrary(lib, (dir_ / "out").string());
    const FreeCadLibrary read = readFreeCadLibrary(written[0]);
    ASSERT_EQ(read.bits.size(), 4u);
    const auto tools = kb.tools();
    for (std::size_t i = 0; i < read.bits.size(); ++i) {
        EXPECT_EQ(read.bits[i].nr, static_cast<int>(i + 1));
        const BitTool bt = toolFromBit(read.bits[i], BitDefaults{"HSS", 1});
        const auto* t = find(tools, lib.bits[i].fileName.substr(0, lib.bits[i].fileName.size() - 5));
        ASSERT_TRUE(t) << lib.bits[i].fileName;
        EXPECT_EQ(bt.tool.type, t->type) << t->id;
        EXPECT_EQ(bt.tool.material, t->material) << t->id;
        EXPECT_EQ(bt.tool.flutes, t->flutes) << t->id;
        EXPECT_NEAR(bt.tool.diameter, t->diameter, 1e-4) << t->id;
        EXPECT_NEAR(bt.tool.cornerRadius, t->cornerRadius, 1e-4) << t->id;
        if (t->type != "drill") EXPECT_NEAR(bt.tool.fluteLength, t->fluteLength, 1e-4) << t->id;
    }
    EXPECT_NE(errorOf([&] { kb.freeCadLibraryOf("X", {"NO-SUCH-TOOL"}); }).find("unknown tool 'NO-SUCH-TOOL'"),
              std::string::npos);
}

TEST_F(FreeCadToolLibraryTest, BadLibrariesLeaveTheDatabaseAsItWas) {
    KnowledgeBase kb = openKb();
    const int before = count(kb);
    const FreeCadLibrary lib = readFreeCadLibrary(shopLibrary().string());
    kb.importFreeCadLibrary(lib);
    const int after = count(kb);
    EXPECT_EQ(after, before + 2);

    // The same library twice.
    std::string e = errorOf([&] { kb.importFreeCadLibrary(lib); });
    EXPECT_NE(e.find("already in the knowledge base"), std::string::npos) << e;
    // Another library whose second bit reuses an id: nothing of it stays.
    FreeCadLibrary clash = lib;
    clash.name = "Clash";
    clash.bits[0].fileName = "brand_new.fctb";
    e = errorOf([&] { kb.importFreeCadLibrary(clash); });
    EXPECT_NE(e.find("bull_half_inch"), std::string::npos) << e;
    EXPECT_NE(e.find("nothing was imported"), std::string::npos) << e;
    EXPECT_EQ(count(kb), after);
    EXPECT_EQ(kb.freeCadLibraryNames(), std::vector<std::string>{"Shop"});

    // Impossible dimensions, an unknown material, a missing diameter, a unit that is no length.
    auto bad = [&](const std::string& name, const std::string& bit) {
        FreeCadLibrary l;
        l.name = name;
        l.bits.push_back({1, name + ".fctb", bit});
        return errorOf([&] { kb.importFreeCadLibrary(l); });
    };
    e = bad("neg", R"({"shape": "endmill.fcstd", "parameter": {"Diameter": "-3 mm", "CuttingEdgeHeight": "5 mm"}})");
    EXPECT_NE(e.find("diameter -3 mm must be positive"), std::string::npos) << e;
    e = bad("mat", R"({"shape": "endmill.fcstd", "parameter": {"Diameter": "3 mm"}, "attribute": {"Material": "Unobtainium"}})");
    EXPECT_NE(e.find("unknown tool material 'Unobtainium'"), std::string::npos) << e;
    e = bad("nodia", R"({"shape": "endmill.fcstd", "parameter": {"Length": "30 mm"}})");
    EXPECT_NE(e.find("no Diameter"), std::string::npos) << e;
    e = bad("kg", R"({"shape": "endmill.fcstd", "parameter": {"Diameter": "3 kg"}})");
    EXPECT_NE(e.find("not a length"), std::string::npos) << e;
    e = bad("json", "{ not json");
    EXPECT_NE(e.find("not valid JSON"), std::string::npos) << e;
    EXPECT_EQ(count(kb), after);
    EXPECT_EQ(kb.freeCadLibraryNames().size(), 1u);
}

TEST_F(FreeCadToolLibraryTest, UnreadableLibraryFiles) {
    std::string e = errorOf([&] { readFreeCadLibrary((dir_ / "none.fctl").string()); });
    EXPECT_NE(e.find("cannot be read"), std::string::npos) << e;
    e = errorOf([&] { readFreeCadLibrary((dir_ / "lib.txt").string()); });
    EXPECT_NE(e.find(".fctl"), std::string::npos) << e;
    const fs::path p = writeLibrary("Missing", {}, R"({"version": 1, "tools": [{"nr": 1, "path": "gone.fctb"}]})");
    e = errorOf([&] { readFreeCadLibrary(p.string()); });
    EXPECT_NE(e.find("gone.fctb not found"), std::string::npos) << e;
    const fs::path twice = writeLibrary("Twice", {{"a.fctb", R"({"parameter": {"Diameter": "3 mm"}})"}},
                                        R"({"tools": [{"nr": 1, "path": "a.fctb"}, {"nr": 1, "path": "a.fctb"}]})");
    e = errorOf([&] { readFreeCadLibrary(twice.string()); });
    EXPECT_NE(e.find("appears twice"), std::string::npos) << e;
}
