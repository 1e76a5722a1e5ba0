#include <aeronc/chain/StepCode.h>
#include <aeronc/core/Error.h>

#include <algorithm>
#include <sstream>

namespace aeronc::chain {

namespace {

struct CodeInfo {
    StepCode code;
    const char* text;
    const char* description;
};

const CodeInfo kCodes[] = {
    {StepCode::Rough, "r", "rough the inner and outer shape"},
    {StepCode::Web, "w", "finish the webs (floors)"},
    {StepCode::Corner, "c", "machine the corners"},
    {StepCode::SemiWall, "ss", "semi-finish the walls"},
    {StepCode::SemiFlange, "sf", "semi-finish the flanges"},
    {StepCode::FinishWall, "fs", "finish the walls"},
    {StepCode::FinishFlange, "ff", "finish the flanges"},
    {StepCode::CutOff, "t", "cut the part off"},
    {StepCode::Drill, "d", "drill the holes"},
    {StepCode::HoleMill, "h", "mill the holes (helical interpolation)"},
    {StepCode::Edge, "e", "chamfer the edges and countersink the holes"},
};

const CodeInfo& info(StepCode c) {
    for (const CodeInfo& i : kCodes)
        if (i.code == c) return i;
    return kCodes[0];
}

std::string knownCodes() {
    std::string s;
    for (const CodeInfo& i : kCodes) s += (s.empty() ? "" : ", ") + std::string(i.text);
    return s;
}

}  // namespace

const char* toString(StepCode c) { return info(c).text; }
const char* describe(StepCode c) { return info(c).description; }

std::optional<StepCode> stepCodeFrom(const std::string& text) {
    for (const CodeInfo& i : kCodes)
        if (text == i.text) return i.code;
    return std::nullopt;
}

const std::vector<StepCode>& allStepCodes() {
    static const std::vector<StepCode> all = [] {
        std::vector<StepCode> v;
        for (const CodeInfo& i : kCodes) v.push_back(i.code);
        return v;
    }();
    return all;
}

StepCode parseStepCode(const std::string& text, const std::string& where) {
    if (const auto c = stepCodeFrom(text)) return *c;
    throw inputError(where + ": unknown step code '" + text + "' (known: " + knownCodes() + ")");
}

std::vector<StepCode> parseStepCodes(const std::string& text, const std::string& where) {
    std::istringstream in(text);
    std::string word;
    std::vector<StepCode> out;
    while (in >> word) {
        const StepCode c = parseStepCode(word, where);
        if (std::find(out.begin(), out.end(), c) != out.end())
            throw inputError(where + ": step code '" + word + "' is listed twice");
        out.push_back(c);
    }
    return out;
}

std::string joinCodes(const std::vector<StepCode>& codes) {
    std::string s;
    for (StepCode c : codes) s += (s.empty() ? "" : " ") + std::string(toString(c));
    return s;
}

const char* toString(Existence e) {
    switch (e) {
        case Existence::Must: return "must";
        case Existence::May: return "may";
        case Existence::MustNot: return "must_not";
    }
    return "?";
}

Existence parseExistence(const std::string& text, const std::string& where) {
    if (text == "must") return Existence::Must;
    if (text == "may") return Existence::May;
    if (text == "must_not") return Existence::MustNot;
    throw inputError(where + ": existence '" + text + "' is none of must, may, must_not");
}

const char* toString(ToolRole r) {
    switch (r) {
        case ToolRole::None: return "";
        case ToolRole::Roughing: return "roughing";
        case ToolRole::Finishing: return "finishing";
        case ToolRole::Corner: return "corner";
        case ToolRole::Drilling: return "drilling";
    }
    return "?";
}

ToolRole parseToolRole(const std::string& text, const std::string& where) {
    if (text.empty()) return ToolRole::None;
    if (text == "roughing") return ToolRole::Roughing;
    if (text == "finishing") return ToolRole::Finishing;
    if (text == "corner") return ToolRole::Corner;
    if (text == "drilling") return ToolRole::Drilling;
    throw inputError(where + ": tool role '" + text + "' is none of roughing, finishing, corner, drilling");
}

const char* toString(Operation o) {
    switch (o) {
        case Operation::Pocket: return "pocket";
        case Operation::Profile: return "profile";
        case Operation::Drill: return "drill";
        case Operation::Helix: return "helix";
        case Operation::Rest: return "rest";
        case Operation::Chamfer: return "chamfer";
    }
    return "?";
}

Operation parseOperation(const std::string& text, const std::string& where) {
    for (Operation o : {Operation::Pocket, Operation::Profile, Operation::Drill, Operation::Helix, Operation::Rest, Operation::Chamfer})
        if (text == toString(o)) return o;
    throw inputError(where + ": operation '" + text + "' is none of pocket, profile, drill, helix, rest, chamfer");
}

const std::vector<std::string>& featureTypes() {
    static const std::vector<std::string> t = {"closed_pocket", "open_pocket", "opening", "hole", "flange"};
    return t;
}

bool isFeatureType(const std::string& name) {
    const auto& t = featureTypes();
    return std::find(t.begin(), t.end(), name) != t.end();
}

}  // namespace aeronc::chain
