// A knowledge-base file as another program may have left it: the input is the SQLite file.
// It is opened (migrated when old), every reader runs over it, and a FreeCAD library is
// imported into it.
#include "FuzzCommon.h"

#include <aeronc/core/TextFile.h>
#include <aeronc/kb/KnowledgeBase.h>

#include <filesystem>
#include <unistd.h>

using namespace aeronc;
using namespace aeronc::kb;

namespace {
std::string resource(const char* name) {
    static const std::string dir = AERONC_RESOURCES "/kb/";
    return readTextFile(dir + name, name);
}

const std::string kBit = R"({"version": 2, "name": "6 mm end mill", "shape": "endmill.fcstd",
  "parameter": {"Diameter": "6.0000 mm", "CuttingEdgeHeight": "14.0000 mm", "Length": "57.0000 mm"},
  "attribute": {"Flutes": 3, "Material": "Carbide"}})";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string schema = resource("schema.sql"), defaults = resource("default_data.sql");
    static const std::string path =
        (std::filesystem::temp_directory_path() / ("aeronc_fuzz_kb_" + std::to_string(::getpid()) + ".sqlite")).string();
    std::error_code ec;
    for (const char* extra : {"", "-journal", ".creating"}) std::filesystem::remove(path + extra, ec);
    for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path(), ec))
        if (e.path().string().rfind(path + ".v", 0) == 0) std::filesystem::remove(e.path(), ec);  // migration backups
    writeTextFileAtomically(path, fuzz::text(data, size));
    fuzz::expectingErrors([&] {
        KnowledgeBase kb = KnowledgeBase::open(path, schema, defaults);
        fuzz::expectingErrors([&] { kb.tools(); });
        for (const char* t : {"eta_min", "mu_merge", "plunge_feed_ratio"}) fuzz::expectingErrors([&] { kb.threshold(t); });
        fuzz::expectingErrors([&] {
            for (const auto& m : kb.machineNames()) fuzz::expectingErrors([&] { kb.machine(m); });
        });
        fuzz::expectingErrors([&] {
            for (const auto& w : kb.workpieceMaterials())
                for (const char* op : {"roughing", "finishing", "drilling"})
                    fuzz::expectingErrors([&] { kb.cuttingCondition(w, "carbide", op, 10.0); });
        });
        for (const auto& t : KnowledgeBase::editableTables()) fuzz::expectingErrors([&] { kb.table(t); });
        fuzz::expectingErrors([&] {
            for (const auto& l : kb.freeCadLibraryNames()) fuzz::expectingErrors([&] { kb.freeCadLibrary(l); });
        });
        FreeCadLibrary lib;
        lib.name = "Fuzz";
        lib.bits.push_back({1, "fuzz_6mm.fctb", kBit});
        fuzz::expectingErrors([&] { kb.importFreeCadLibrary(lib); });
    });
    return 0;
}
