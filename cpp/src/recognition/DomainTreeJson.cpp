#include <aeronc/recognition/Recogniser.h>

#include <nlohmann/json.hpp>

#include <cmath>

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
    for (const SetupDirection& s : t.setups)
        j["setups"].push_back({{"id", s.id}, {"direction", vec(s.direction)}, {"name", s.name}, {"elements", s.elements}});
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
        o["attached"] = json::array();
        for (const AttachedFeature& a : e.attached)
            o["attached"].push_back(
                {{"kind", a.kind}, {"faces", a.faces}, {"radius", a.radius}, {"size", a.size}, {"element", a.element}});
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
        } else {
            o["hole"] = nullptr;
        }
        j["elements"].push_back(std::move(o));
    }
    j["faceRoles"] = json::array();
    for (FaceRole r : t.faceRoles) j["faceRoles"].push_back(toString(r));
    j["faceElement"] = t.faceElement;
    j["warnings"] = t.warnings;
    return j.dump(indent);
}

}  // namespace aeronc::recognition
