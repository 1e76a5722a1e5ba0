// The stored domain tree (recognise --json, a Machining Features group's Result): reader, and
// a tree it accepts must write and read back to the same text.
#include "FuzzCommon.h"

#include <aeronc/recognition/DomainTreeJson.h>

using namespace aeronc;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    recognition::DomainTree t;
    if (!fuzz::expectingErrors([&] { t = recognition::fromJson(fuzz::text(data, size)); })) return 0;
    const std::string once = recognition::toJson(t);
    std::string twice;
    if (!fuzz::expectingErrors([&] { twice = recognition::toJson(recognition::fromJson(once)); }))
        fuzz::finding("a tree the reader accepted does not read back once written");
    if (once != twice) fuzz::finding("a tree the reader accepted changes when written and read again");
    return 0;
}
