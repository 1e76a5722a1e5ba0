// FreeCAD tool libraries and bits. Input "<.fctl text>\n---\n<.fctb text>" gives both files
// (Library/L.fctl naming Bit/a.fctb); input without the separator is a bit document alone.
// Then the bit's tool, the bit rewritten with that tool, and a new bit for it.
#include "FuzzCommon.h"

#include <aeronc/core/TextFile.h>
#include <aeronc/kb/FreeCadToolLibrary.h>

#include <filesystem>
#include <unistd.h>

using namespace aeronc;
using namespace aeronc::kb;

namespace {
const std::filesystem::path& folder() {
    static const std::filesystem::path f = [] {
        const auto p = std::filesystem::temp_directory_path() / ("aeronc_fuzz_tools_" + std::to_string(::getpid()));
        std::filesystem::create_directories(p / "Library");
        std::filesystem::create_directories(p / "Bit");
        return p;
    }();
    return f;
}

void bitChecks(const FreeCadBit& bit) {
    BitTool t;
    if (!fuzz::expectingErrors([&] { t = toolFromBit(bit, {}); })) return;
    fuzz::expectingErrors([&] { bitWithTool(bit.document, t.tool, t.overallLength); });
    std::string fresh;
    if (!fuzz::expectingErrors([&] { fresh = newBitFor(t.tool, t.overallLength); })) return;
    fuzz::expectingErrors([&] { toolFromBit({bit.nr, bit.fileName, fresh}, {}); });
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string input = fuzz::text(data, size);
    const size_t cut = input.find("\n---\n");
    if (cut == std::string::npos) {
        bitChecks({1, "a.fctb", input});
        return 0;
    }
    const std::filesystem::path lib = folder() / "Library" / "L.fctl";
    writeTextFileAtomically(lib.string(), input.substr(0, cut));
    writeTextFileAtomically((folder() / "Bit" / "a.fctb").string(), input.substr(cut + 5));
    FreeCadLibrary l;
    if (!fuzz::expectingErrors([&] { l = readFreeCadLibrary(lib.string()); })) return 0;
    for (const auto& b : l.bits) bitChecks(b);
    return 0;
}
