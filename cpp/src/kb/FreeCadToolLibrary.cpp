#include <aeronc/core/Error.h>
#include <aeronc/core/JsonNesting.h>
#include <aeronc/core/TextFile.h>
#include <aeronc/kb/FreeCadToolLibrary.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;  // FreeCAD writes bits in insertion order; keep it

namespace aeronc::kb {

using toolselect::Tool;

namespace {

// A change smaller than this is no change: quantity strings carry 4 decimals.
constexpr double kSame = 5e-5;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
    return s;
}

ojson parse(const std::string& text, const std::string& what) {
    checkJsonNesting(text, what);
    try {
        return ojson::parse(text);
    } catch (const std::exception& e) {
        throw inputError(what + " is not valid JSON (" + e.what() + ")");
    }
}

std::string shapeStem(const ojson& bit) {
    const auto it = bit.find("shape");
    if (it == bit.end() || !it->is_string()) return "";
    return lower(fs::path(it->get<std::string>()).stem().string());
}

std::string typeOfShape(const std::string& stem) {
    if (stem == "endmill") return "flat";
    if (stem == "bullnose") return "bull";
    if (stem == "ballend") return "ball";
    if (stem == "drill") return "drill";
    return "other";
}

std::string shapeOfType(const std::string& type) {
    if (type == "bull") return "bullnose.fcstd";
    if (type == "ball") return "ballend.fcstd";
    if (type == "drill") return "drill.fcstd";
    return "endmill.fcstd";
}

std::string mm(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f mm", v);
    return buf;
}

// The bit's parameter `key` in mm, if present.
std::optional<double> param(const ojson& bit, const std::string& key, const std::string& who) {
    const auto p = bit.find("parameter");
    if (p == bit.end() || !p->is_object()) return std::nullopt;
    const auto v = p->find(key);
    if (v == p->end()) return std::nullopt;
    if (v->is_number()) return v->get<double>();
    if (!v->is_string()) throw inputError(who + ": parameter " + key + " is neither a number nor a quantity");
    return lengthOf(v->get<std::string>(), who + ": parameter " + key);
}

// Sets parameter `key` to v mm when it differs from what is there (or is absent and `add`).
bool setParam(ojson& bit, const std::string& key, double v, bool add) {
    ojson& p = bit["parameter"];
    const auto it = p.find(key);
    if (it == p.end()) {
        if (!add) return false;
        p[key] = mm(v);
        return true;
    }
    double old = NAN;
    try {
        old = it->is_number() ? it->get<double>() : lengthOf(it->get<std::string>(), key);
    } catch (const Error&) {
    }
    if (std::isfinite(old) && std::fabs(old - v) < kSame) return false;
    *it = mm(v);
    return true;
}

// A whole number in [lo, 2^31) from a JSON number or, as FreeCAD 0.19 wrote some, a string
// of digits; anything else (a fraction, an overflow, text) is an error naming `what`.
int wholeNumber(const ojson& v, long long lo, const std::string& what) {
    long long n = 0;
    bool ok = false;
    if (v.is_number_integer()) {
        ok = !(v.is_number_unsigned() && v.get<unsigned long long>() > 2147483647ULL);
        if (ok) n = v.get<long long>();
    } else if (v.is_string()) {
        const std::string& t = v.get_ref<const std::string&>();
        ok = !t.empty() && t.size() <= 10 && t.find_first_not_of("0123456789") == std::string::npos;
        if (ok) n = std::stoll(t);
    }
    if (!ok || n < lo || n > 2147483647LL) {
        std::string shown = v.is_primitive() ? v.dump() : std::string(v.is_array() ? "an array" : "an object");
        if (shown.size() > 40) shown = shown.substr(0, 40) + "...";
        throw inputError(what + " must be a whole number from " + std::to_string(lo) + " to 2147483647, not " + shown);
    }
    return static_cast<int>(n);
}

}  // namespace

double lengthOf(const std::string& quantity, const std::string& what) {
    const char* s = quantity.c_str();
    char* end = nullptr;
    const double v = std::strtod(s, &end);
    if (end == s || !std::isfinite(v)) throw inputError(what + ": '" + quantity + "' is not a length");
    std::string unit(end);
    unit.erase(0, unit.find_first_not_of(" \t"));
    unit.erase(unit.find_last_not_of(" \t") + 1);
    if (unit.empty() || unit == "mm") return v;
    if (unit == "in" || unit == "\"") return v * 25.4;
    if (unit == "cm") return v * 10;
    if (unit == "m") return v * 1000;
    if (unit == "um" || unit == "\xC2\xB5m") return v * 1e-3;
    throw inputError(what + ": '" + quantity + "' has a unit that is not a length ('" + unit + "')");
}

std::string bitFileNameFor(const std::string& toolId) {
    std::string s = toolId;
    for (char& c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) c = '_';
    return s + ".fctb";
}

FreeCadLibrary readFreeCadLibrary(const std::string& fctlPath) {
    const fs::path path(fctlPath);
    if (lower(path.extension().string()) != ".fctl")
        throw inputError("FreeCAD tool library " + fctlPath + ": expected an .fctl file");
    FreeCadLibrary lib;
    lib.name = path.stem().string();
    lib.document = readTextFile(fctlPath, "FreeCAD tool library");
    const std::string who = "FreeCAD tool library " + fctlPath;
    const ojson j = parse(lib.document, who);
    if (!j.is_object() || !j.contains("tools") || !j["tools"].is_array())
        throw inputError(who + ": no \"tools\" list");
    lib.version = j.contains("version") ? wholeNumber(j["version"], 1, who + ": \"version\"") : 1;
    std::set<int> numbers;
    for (const ojson& entry : j["tools"]) {
        if (!entry.is_object() || !entry.contains("nr") || !entry.contains("path") || !entry["nr"].is_number_integer() ||
            !entry["path"].is_string())
            throw inputError(who + ": a tool entry needs an integer \"nr\" and a \"path\"");
        FreeCadBit bit;
        bit.nr = wholeNumber(entry["nr"], 0, who + ": tool \"nr\"");
        if (!numbers.insert(bit.nr).second)
            throw inputError(who + ": tool number " + std::to_string(bit.nr) + " appears twice");
        const fs::path rel(entry["path"].get<std::string>());
        std::vector<fs::path> candidates;
        if (rel.is_absolute()) candidates = {rel};
        else candidates = {path.parent_path() / rel, path.parent_path() / ".." / "Bit" / rel};
        std::error_code ec;
        const auto found = std::find_if(candidates.begin(), candidates.end(),
                                        [&](const fs::path& c) { return fs::is_regular_file(c, ec); });
        if (found == candidates.end())
            throw inputError(who + ": tool " + std::to_string(bit.nr) + ": bit file " + rel.string() +
                             " not found beside the library or in ../Bit");
        bit.fileName = rel.filename().string();
        bit.document = readTextFile(found->string(), "FreeCAD tool bit");
        parse(bit.document, "FreeCAD tool bit " + found->string());
        lib.bits.push_back(std::move(bit));
    }
    return lib;
}

std::vector<std::string> writeFreeCadLibrary(const FreeCadLibrary& library, const std::string& folder) {
    const fs::path root(folder);
    std::string libraryText = library.document;
    if (libraryText.empty()) {
        // FreeCAD's own layout: sorted keys, two-space indent.
        nlohmann::json j;
        j["version"] = library.version;
        j["tools"] = nlohmann::json::array();
        for (const FreeCadBit& b : library.bits) j["tools"].push_back({{"nr", b.nr}, {"path", b.fileName}});
        libraryText = j.dump(2);
    }
    std::vector<std::string> written;
    const std::string libPath = (root / "Library" / (library.name + ".fctl")).string();
    for (const FreeCadBit& b : library.bits) {
        const std::string p = (root / "Bit" / b.fileName).string();
        writeTextFileAtomically(p, b.document);
        written.push_back(p);
    }
    // The library last, so it never names a bit that was not written.
    writeTextFileAtomically(libPath, libraryText);
    written.insert(written.begin(), libPath);
    return written;
}

BitTool toolFromBit(const FreeCadBit& bit, const BitDefaults& defaults) {
    const std::string who = "FreeCAD tool bit " + bit.fileName;
    const ojson j = parse(bit.document, who);
    BitTool out;
    Tool& t = out.tool;
    t.id = fs::path(bit.fileName).stem().string();
    t.type = typeOfShape(shapeStem(j));
    const auto d = param(j, "Diameter", who);
    if (!d) throw inputError(who + ": no Diameter parameter");
    t.diameter = *d;
    out.overallLength = param(j, "Length", who);
    if (out.overallLength && !(*out.overallLength > 0))
        throw inputError(who + ": parameter Length " + std::to_string(*out.overallLength) + " mm must be positive");
    double cutting = 0;
    for (const char* key : {"CuttingEdgeHeight", "BladeThickness"})
        if (const auto v = param(j, key, who)) {
            if (!(*v > 0)) throw inputError(who + ": parameter " + key + " " + std::to_string(*v) + " mm must be positive");
            cutting = *v;
            break;
        }
    if (cutting == 0) cutting = out.overallLength.value_or(t.diameter);  // a drill cuts along its length
    t.fluteLength = cutting;
    t.reach = std::max(cutting, out.overallLength.value_or(cutting));
    if (t.type == "ball") {
        t.cornerRadius = t.radius();
    } else if (t.type == "bull") {
        if (const auto flat = param(j, "FlatRadius", who)) t.cornerRadius = t.radius() - *flat;
        else if (const auto r = param(j, "CornerRadius", who)) t.cornerRadius = *r;
    }
    t.material = defaults.toolMaterial;
    t.flutes = defaults.flutes;
    if (const auto a = j.find("attribute"); a != j.end() && a->is_object()) {
        if (const auto f = a->find("Flutes"); f != a->end()) t.flutes = wholeNumber(*f, 1, who + ": attribute Flutes");
        if (const auto m = a->find("Material"); m != a->end() && m->is_string() && !m->get<std::string>().empty())
            t.material = m->get<std::string>();
    }
    return out;
}

std::string bitWithTool(const std::string& document, const Tool& tool, std::optional<double> overallLength) {
    ojson j = parse(document, "FreeCAD tool bit of " + tool.id);
    bool changed = setParam(j, "Diameter", tool.diameter, true);
    const std::string type = typeOfShape(shapeStem(j));
    if (type == "flat" || type == "bull" || type == "ball")
        changed |= setParam(j, "CuttingEdgeHeight", tool.fluteLength, false);
    if (type == "bull") changed |= setParam(j, "FlatRadius", tool.radius() - tool.cornerRadius, false);
    if (overallLength) changed |= setParam(j, "Length", *overallLength, false);
    if (auto a = j.find("attribute"); a != j.end() && a->is_object()) {
        if (auto f = a->find("Flutes"); f != a->end() && f->is_number_integer() && f->get<int>() != tool.flutes) {
            *f = tool.flutes;
            changed = true;
        }
    }
    return changed ? j.dump(2, ' ', true) : document;
}

std::string newBitFor(const Tool& tool, std::optional<double> overallLength) {
    ojson j;
    j["version"] = 2;
    j["name"] = tool.id;
    j["shape"] = shapeOfType(tool.type);
    ojson p = ojson::object();
    p["Diameter"] = mm(tool.diameter);
    if (tool.type == "drill") {
        p["Length"] = mm(overallLength.value_or(tool.reach));
        p["TipAngle"] = "118.0000 \xC2\xB0";
    } else {
        p["CuttingEdgeHeight"] = mm(tool.fluteLength);
        if (tool.type == "bull") p["FlatRadius"] = mm(tool.radius() - tool.cornerRadius);
        p["Length"] = mm(overallLength.value_or(tool.reach));
        p["ShankDiameter"] = mm(tool.diameter);
    }
    j["parameter"] = p;
    j["attribute"] = {{"Flutes", tool.flutes}, {"Material", tool.material}};
    return j.dump(2, ' ', true);
}

}  // namespace aeronc::kb
