#include <aeronc/core/Error.h>
#include <aeronc/core/JsonNesting.h>
#include <aeronc/recognition/DomainTreeJson.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace aeronc::recognition {
using nlohmann::json;

namespace {
json num(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }
json vec(const Vec3& v) { return json::array({v[0], v[1], v[2]}); }
json poly(const Polyline& p) {
    json a = json::array();
    for (const Vec3& v : p) a.push_back(vec(v));
    return a;
}
}  // namespace

std::string toJson(const DomainTree& t, int indent) {
    json j;
    j["faceCount"] = t.faceCount;
    j["setups"] = json::array();
    for (const SetupDirection& s : t.setups) {
        j["setups"].push_back({{"id", s.id}, {"direction", vec(s.direction)}, {"name", s.name}, {"elements", s.elements}});
        if (std::isfinite(s.blankTop)) j["setups"].back()["blankTop"] = s.blankTop;
    }
    j["elements"] = json::array();
    for (const DomainElement& e : t.elements) {
        json o{{"id", e.id},
               {"setup", e.setup},
               {"parent", e.parent},
               {"children", e.children},
               {"type", toString(e.type)},
               {"level", e.level},
               {"top", e.top},
               {"depth", e.depth},
               {"floorArea", e.floorArea},
               {"area", e.area},
               {"minWidth", e.minWidth},
               {"minCornerRadius", e.minCornerRadius < 0 ? json(nullptr) : num(e.minCornerRadius)},
               {"floorFilletRadius", e.floorFilletRadius},
               {"contourFaces", e.contourFaces},
               {"islandFaces", e.islandFaces},
               {"floorFaces", e.floorFaces},
               {"topFaces", e.topFaces},
               {"filletFaces", e.filletFaces},
               {"chamferFaces", e.chamferFaces}};
        o["openEdges"] = json::array();
        for (auto& oe : e.openEdges) o["openEdges"].push_back(json::array({vec(oe.first), vec(oe.second)}));
        o["contour"] = poly(e.contour);
        o["islands"] = json::array();
        for (auto& p : e.islands) o["islands"].push_back(poly(p));
        if (!e.islandTops.empty()) o["islandTops"] = e.islandTops;
        o["attached"] = json::array();
        for (const AttachedFeature& a : e.attached) {
            o["attached"].push_back(
                {{"kind", a.kind}, {"faces", a.faces}, {"radius", a.radius}, {"size", a.size}, {"element", a.element}});
            if (a.angle > 0) o["attached"].back()["angle"] = a.angle;
            if (a.alongContour) {
                o["attached"].back()["lower"] = a.lower;
                o["attached"].back()["alongContour"] = true;
            }
            if (!a.alongIslands.empty()) {
                o["attached"].back()["lower"] = a.lower;
                o["attached"].back()["alongIslands"] = a.alongIslands;
            }
        }
        if (e.hole) {
            const HoleInfo& h = *e.hole;
            o["hole"] = {{"diameter", h.diameter},
                         {"depth", h.depth},
                         {"through", h.through},
                         {"axis", vec(h.axis)},
                         {"location", vec(h.location)},
                         {"counterboreDiameter", h.counterboreDiameter},
                         {"counterboreDepth", h.counterboreDepth},
                         {"countersinkDiameter", h.countersinkDiameter},
                         {"countersinkAngle", h.countersinkAngle}};
            if (h.overhung) o["hole"]["overhung"] = true;
        } else {
            o["hole"] = nullptr;
        }
        j["elements"].push_back(std::move(o));
    }
    j["faceRoles"] = json::array();
    for (FaceRole r : t.faceRoles) j["faceRoles"].push_back(toString(r));
    j["faceElement"] = t.faceElement;
    j["unclaimedFaces"] = t.unclaimedFaces;
    j["leftOutFaces"] = t.leftOutFaces;
    j["warnings"] = t.warnings;
    return j.dump(indent);
}

namespace {

// A JSON value and where it sits in the tree ("elements[3].contour[2]"), so that every
// complaint names the field at fault.
class Field {
public:
    Field(const json& value, std::string where) : j_(value), where_(std::move(where)) {}

    [[noreturn]] void fail(const std::string& what) const {
        throw inputError("domain tree: " + (where_.empty() ? std::string("top level") : where_) + ": " + what);
    }
    void expect(bool ok, const char* wanted) const {
        if (!ok) fail(std::string("expected ") + wanted + ", got " + j_.type_name());
    }

    Field operator[](const char* key) const {
        expect(j_.is_object(), "an object");
        const auto it = j_.find(key);
        if (it == j_.end()) fail(std::string("missing field '") + key + "'");
        return Field(*it, where_.empty() ? key : where_ + "." + key);
    }
    std::size_t size() const {
        expect(j_.is_array(), "an array");
        return j_.size();
    }
    Field at(std::size_t i) const {
        return Field(j_.at(i), where_ + "[" + std::to_string(i) + "]");
    }
    bool isNull() const { return j_.is_null(); }
    bool has(const char* key) const {
        expect(j_.is_object(), "an object");
        return j_.contains(key);
    }

    int integer() const {
        expect(j_.is_number_integer(), "a whole number");
        const bool fits = j_.is_number_unsigned()
                              ? j_.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<int>::max())
                              : j_.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                                    j_.get<std::int64_t>() <= std::numeric_limits<int>::max();
        if (!fits) fail("whole number " + shown() + " out of range");
        return j_.get<int>();
    }
    double number() const {
        expect(j_.is_number(), "a number");
        return j_.get<double>();
    }
    bool boolean() const {
        expect(j_.is_boolean(), "true or false");
        return j_.get<bool>();
    }
    std::string text() const {
        expect(j_.is_string(), "a string");
        return j_.get<std::string>();
    }

    template <class F>
    auto list(F item) const -> std::vector<decltype(item(std::declval<Field>()))> {
        std::vector<decltype(item(std::declval<Field>()))> out;
        const std::size_t n = size();
        out.reserve(n);
        for (std::size_t i = 0; i < n; ++i) out.push_back(item(at(i)));
        return out;
    }
    std::vector<int> integers() const {
        return list([](const Field& f) { return f.integer(); });
    }
    Vec3 vec() const {
        if (!j_.is_array() || j_.size() != 3) fail("expected [x, y, z], got " + shown());
        return {at(0).number(), at(1).number(), at(2).number()};
    }
    Polyline polyline() const {
        return list([](const Field& f) { return f.vec(); });
    }

private:
    // The value as text, cut short: a whole polyline where a point belongs would flood the message.
    std::string shown() const {
        const std::string s = j_.dump();
        return s.size() <= 60 ? s : s.substr(0, 57) + "...";
    }

    const json& j_;
    std::string where_;
};

ElementType elementType(const Field& f) {
    const std::string s = f.text();
    for (ElementType t : {ElementType::ClosedPocket, ElementType::OpenPocket, ElementType::Opening, ElementType::Hole})
        if (s == toString(t)) return t;
    f.fail("unknown element type '" + s + "' (closed_pocket, open_pocket, opening or hole)");
}

FaceRole faceRole(const Field& f) {
    const std::string s = f.text();
    // Stock is the last role of the enumeration.
    for (int r = static_cast<int>(FaceRole::Unclaimed); r <= static_cast<int>(FaceRole::Stock); ++r)
        if (s == toString(static_cast<FaceRole>(r))) return static_cast<FaceRole>(r);
    f.fail("unknown face role '" + s + "'");
}

HoleInfo hole(const Field& f) {
    HoleInfo h;
    h.diameter = f["diameter"].number();
    h.depth = f["depth"].number();
    h.through = f["through"].boolean();
    h.axis = f["axis"].vec();
    h.location = f["location"].vec();
    h.counterboreDiameter = f["counterboreDiameter"].number();
    h.counterboreDepth = f["counterboreDepth"].number();
    h.countersinkDiameter = f["countersinkDiameter"].number();
    h.countersinkAngle = f["countersinkAngle"].number();
    if (f.has("overhung")) h.overhung = f["overhung"].boolean();
    return h;
}

DomainElement element(const Field& f) {
    DomainElement e;
    e.id = f["id"].integer();
    e.setup = f["setup"].integer();
    e.parent = f["parent"].integer();
    e.children = f["children"].integers();
    e.type = elementType(f["type"]);
    e.level = f["level"].number();
    e.top = f["top"].number();
    e.depth = f["depth"].number();
    e.floorArea = f["floorArea"].number();
    e.area = f["area"].number();
    e.minWidth = f["minWidth"].number();
    const Field r = f["minCornerRadius"];
    e.minCornerRadius = r.isNull() ? -1 : r.number();
    e.floorFilletRadius = f["floorFilletRadius"].number();
    e.contourFaces = f["contourFaces"].integers();
    e.islandFaces = f["islandFaces"].list([](const Field& l) { return l.integers(); });
    e.floorFaces = f["floorFaces"].integers();
    e.topFaces = f["topFaces"].integers();
    e.filletFaces = f["filletFaces"].integers();
    e.chamferFaces = f["chamferFaces"].integers();
    e.openEdges = f["openEdges"].list([](const Field& p) {
        if (p.size() != 2) p.fail("expected [start, end], got " + std::to_string(p.size()) + " points");
        return std::make_pair(p.at(0).vec(), p.at(1).vec());
    });
    e.contour = f["contour"].polyline();
    e.islands = f["islands"].list([](const Field& p) { return p.polyline(); });
    // Added later: optional, so that older trees still read.
    if (f.has("islandTops")) {
        e.islandTops = f["islandTops"].list([](const Field& t) { return t.number(); });
        if (e.islandTops.size() != e.islands.size())
            f["islandTops"].fail("expected one height per island (" + std::to_string(e.islands.size()) + "), got " +
                                 std::to_string(e.islandTops.size()));
    }
    e.attached = f["attached"].list([](const Field& a) {
        AttachedFeature x;
        x.kind = a["kind"].text();
        x.faces = a["faces"].integers();
        x.radius = a["radius"].number();
        x.size = a["size"].number();
        x.element = a["element"].integer();
        if (a.has("angle")) x.angle = a["angle"].number();  // chamfers, since the edge step
        if (a.has("alongContour")) {                          // chamfers the edge step cuts
            x.alongContour = a["alongContour"].boolean();
            x.lower = a["lower"].number();
        }
        if (a.has("alongIslands")) {  // chamfers round every island
            x.alongIslands = a["alongIslands"].integers();
            x.lower = a["lower"].number();
        }
        return x;
    });
    const Field h = f["hole"];
    if (!h.isNull()) e.hole = hole(h);
    return e;
}

std::string range(int count) { return count > 0 ? "0.." + std::to_string(count - 1) : "none"; }

// The links and numbers the schema cannot say: ids are positions, parents and children agree,
// setups list their root elements, faces exist. Numbers out of range first, so that a later
// check can follow every link.
void checkLinks(const DomainTree& t, const Field& root) {
    const int n = static_cast<int>(t.elements.size());
    const int ns = static_cast<int>(t.setups.size());
    const Field setups = root["setups"], elements = root["elements"];
    const auto element = [&](int i) -> const DomainElement& { return t.elements[static_cast<std::size_t>(i)]; };
    const auto face = [&](const Field& where, const std::vector<int>& faces) {
        for (std::size_t k = 0; k < faces.size(); ++k)
            if (faces[k] < 1 || faces[k] > t.faceCount)
                where.at(k).fail("face " + std::to_string(faces[k]) + " is not a face of the part (1.." +
                                 std::to_string(t.faceCount) + ")");
    };
    const auto noRepeat = [](const Field& where, const std::vector<int>& ids, std::size_t k) {
        const auto before = ids.begin() + static_cast<std::ptrdiff_t>(k);
        if (std::find(ids.begin(), before, ids[k]) != before)
            where.at(k).fail("element " + std::to_string(ids[k]) + " is listed twice");
    };

    for (int i = 0; i < n; ++i) {
        const DomainElement& e = element(i);
        const Field f = elements.at(static_cast<std::size_t>(i));
        if (e.id != i) f["id"].fail(std::to_string(e.id) + ", but an element's id is its position " + std::to_string(i));
        if (e.setup < 0 || e.setup >= ns)
            f["setup"].fail("setup " + std::to_string(e.setup) + " does not exist (" + range(ns) + ")");
        if (e.parent < -1 || e.parent >= n || e.parent == i)
            f["parent"].fail("element " + std::to_string(e.parent) + " cannot be the parent (-1 or " + range(n) +
                             ", not itself)");
        for (std::size_t k = 0; k < e.children.size(); ++k)
            if (e.children[k] < 0 || e.children[k] >= n)
                f["children"].at(k).fail("element " + std::to_string(e.children[k]) + " does not exist (" + range(n) +
                                         ")");
        face(f["contourFaces"], e.contourFaces);
        for (std::size_t k = 0; k < e.islandFaces.size(); ++k) face(f["islandFaces"].at(k), e.islandFaces[k]);
        face(f["floorFaces"], e.floorFaces);
        face(f["topFaces"], e.topFaces);
        face(f["filletFaces"], e.filletFaces);
        face(f["chamferFaces"], e.chamferFaces);
        for (std::size_t k = 0; k < e.attached.size(); ++k) {
            const AttachedFeature& a = e.attached[k];
            const Field fa = f["attached"].at(k);
            face(fa["faces"], a.faces);
            if (a.element < -1 || a.element >= n)
                fa["element"].fail("element " + std::to_string(a.element) + " does not exist (-1 or " + range(n) + ")");
        }
    }

    for (int s = 0; s < ns; ++s) {
        const SetupDirection& sd = t.setups[static_cast<std::size_t>(s)];
        const Field f = setups.at(static_cast<std::size_t>(s));
        if (sd.id != s) f["id"].fail(std::to_string(sd.id) + ", but a setup's id is its position " + std::to_string(s));
        for (std::size_t k = 0; k < sd.elements.size(); ++k) {
            const int e = sd.elements[k];
            const Field fe = f["elements"].at(k);
            if (e < 0 || e >= n) fe.fail("element " + std::to_string(e) + " does not exist (" + range(n) + ")");
            if (element(e).parent != -1 || element(e).setup != s)
                fe.fail("element " + std::to_string(e) + " is not a root element of setup " + std::to_string(s) +
                        " (its parent is " + std::to_string(element(e).parent) + ", its setup " +
                        std::to_string(element(e).setup) + ")");
            noRepeat(f["elements"], sd.elements, k);
        }
    }

    for (int i = 0; i < n; ++i) {
        const DomainElement& e = element(i);
        const Field f = elements.at(static_cast<std::size_t>(i));
        const std::string me = std::to_string(i);
        if (e.parent == -1) {
            const auto& roots = t.setups[static_cast<std::size_t>(e.setup)].elements;
            if (std::find(roots.begin(), roots.end(), i) == roots.end())
                f["parent"].fail("-1 (a root), but setups[" + std::to_string(e.setup) + "].elements does not list " +
                                 me);
        } else {
            const auto& siblings = element(e.parent).children;
            if (std::find(siblings.begin(), siblings.end(), i) == siblings.end())
                f["parent"].fail(std::to_string(e.parent) + ", but elements[" + std::to_string(e.parent) +
                                 "].children does not list " + me);
            // A chain of parents longer than the tree goes round in a circle.
            int up = e.parent, steps = 0;
            while (up >= 0 && steps <= n) up = element(up).parent, ++steps;
            if (up >= 0) f["parent"].fail("the chain of parents from element " + me + " goes round in a circle");
        }
        for (std::size_t k = 0; k < e.children.size(); ++k) {
            const int c = e.children[k];
            const Field fc = f["children"].at(k);
            if (element(c).parent != i)
                fc.fail("element " + std::to_string(c) + " has parent " + std::to_string(element(c).parent) +
                        ", not " + me);
            if (element(c).setup != e.setup)
                fc.fail("element " + std::to_string(c) + " is in setup " + std::to_string(element(c).setup) +
                        ", its parent in setup " + std::to_string(e.setup));
            noRepeat(f["children"], e.children, k);
        }
    }

    const std::size_t faces = static_cast<std::size_t>(t.faceCount);
    if (t.faceRoles.size() != faces)
        root["faceRoles"].fail(std::to_string(t.faceRoles.size()) + " roles for " + std::to_string(faces) + " faces");
    if (t.faceElement.size() != faces)
        root["faceElement"].fail(std::to_string(t.faceElement.size()) + " entries for " + std::to_string(faces) +
                                 " faces");
    if (root.has("unclaimedFaces")) face(root["unclaimedFaces"], t.unclaimedFaces);
    if (root.has("leftOutFaces")) face(root["leftOutFaces"], t.leftOutFaces);
    for (std::size_t k = 0; k < faces; ++k)
        if (t.faceElement[k] < -1 || t.faceElement[k] >= n)
            root["faceElement"].at(k).fail("element " + std::to_string(t.faceElement[k]) + " does not exist (-1 or " +
                                           range(n) + ")");
}

}  // namespace

DomainTree fromJson(const std::string& text) {
    checkJsonNesting(text, "domain tree");  // Field::shown() writes values back
    json j;
    try {
        j = json::parse(text);
    } catch (const json::exception& e) {  // a number overflow is out_of_range, not parse_error
        throw inputError(std::string("domain tree: not valid JSON: ") + e.what());
    }
    const Field root(j, "");
    root.expect(j.is_object(), "an object");
    DomainTree t;
    t.faceCount = root["faceCount"].integer();
    if (t.faceCount < 0) root["faceCount"].fail("a face count cannot be negative");
    t.setups = root["setups"].list([](const Field& f) {
        SetupDirection s;
        s.id = f["id"].integer();
        s.direction = f["direction"].vec();
        s.name = f["name"].text();
        s.elements = f["elements"].integers();
        if (f.has("blankTop")) s.blankTop = f["blankTop"].number();  // added later
        return s;
    });
    t.elements = root["elements"].list(element);
    t.faceRoles = root["faceRoles"].list(faceRole);
    t.faceElement = root["faceElement"].integers();
    // Added later: optional, so that older trees still read.
    if (root.has("unclaimedFaces")) t.unclaimedFaces = root["unclaimedFaces"].integers();
    if (root.has("leftOutFaces")) t.leftOutFaces = root["leftOutFaces"].integers();
    t.warnings = root["warnings"].list([](const Field& f) { return f.text(); });
    checkLinks(t, root);
    return t;
}

}  // namespace aeronc::recognition
