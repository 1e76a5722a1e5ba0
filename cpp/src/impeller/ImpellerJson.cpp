#include <aeronc/impeller/ImpellerDimensions.h>

#include <nlohmann/json.hpp>

namespace aeronc::impeller {

std::string impellerToJson(const ImpellerFeatures& f, const ImpellerDimensions& d) {
    using nlohmann::json;
    json blades = json::array();
    for (const auto& b : f.blades)
        blades.push_back({{"kind", b.splitter ? "splitter" : "main"},
                          {"angleDeg", b.angleDeg},
                          {"pressure", b.pressure},
                          {"suction", b.suction},
                          {"leading", b.leading},
                          {"trailing", b.trailing},
                          {"walls", b.walls},
                          {"fillets", b.fillets},
                          {"shroud", b.shroud},
                          {"shroudFaces", b.shroudFaces}});
    json profile = json::array();  // [radius, depth, width] per station
    for (const auto& s : d.channelProfile) profile.push_back({s.radius, s.depth, s.width});
    json doc = {
        {"units", "mm"},
        {"faceCount", f.faceCount},
        {"axis", {{"point", f.axisPoint}, {"direction", f.axisDirection}}},
        {"bladeCount", f.bladeCount},
        {"splitterCount", f.splitterCount},
        {"hub", f.hub},
        {"hubFaces", f.hubFaces},
        {"bore", f.bore},
        {"holes", f.holes},
        {"planes", f.planes},
        {"turned", f.turned},
        {"blades", blades},
        {"closestPair", {f.closestPair[0], f.closestPair[1]}},
        {"closestShroudDistance", f.closestShroudDistance},
        {"dimensions",
         {{"boreDiameter", d.boreDiameter},
          {"boreDepth", d.boreDepth},
          {"minChannelWidth", d.minChannelWidth},
          {"channelBlades", {d.channelBlades[0], d.channelBlades[1]}},
          {"minChannelDepth", d.minChannelDepth},
          {"channelProfile", profile},
          {"filletRadius", d.filletRadius},
          {"bladeHeight", d.bladeHeight},
          {"splitterHeight", d.splitterHeight},
          {"outerRadius", d.outerRadius},
          {"axialLength", d.axialLength}}}};
    return doc.dump(1);
}

}  // namespace aeronc::impeller
