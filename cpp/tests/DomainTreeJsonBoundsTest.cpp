// A stored domain tree that is valid JSON of no sensible shape: nesting 100,000 deep once
// overflowed the stack while the message quoted the value; a number overflow escaped as a
// JSON library exception without "domain tree" in its message.
#include <aeronc/recognition/DomainTreeJson.h>

#include "ErrorOf.h"

#include <gtest/gtest.h>

#include <string>

using aeronc::recognition::fromJson;
using aeronc::test::inputErrorOf;

TEST(DomainTreeJsonBounds, DeepNestingIsAnErrorNotAStackOverflow) {
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    const std::string e = inputErrorOf([&] {
        fromJson(R"({"faceCount": 0, "setups": [{"id": 0, "direction": )" + deep + R"(, "name": "+Z", "elements": []}],
                    "elements": [], "faceRoles": [], "faceElement": [], "warnings": []})");
    });
    EXPECT_NE(e.find("domain tree: JSON nested deeper than 64 levels"), std::string::npos) << e.substr(0, 300);
}

TEST(DomainTreeJsonBounds, ANumberOverflowIsNotValidJson) {
    const std::string e = inputErrorOf([] { fromJson(R"({"faceCount": 1e400})"); });
    EXPECT_NE(e.find("domain tree: not valid JSON"), std::string::npos) << e;
}
