// What the chain leaves, with the reason (see Unmachined.h).
#include "Unmachined.h"

#include "ElementTools.h"

#include <aeronc/chain/Fusing.h>

#include <algorithm>
#include <cmath>

namespace aeronc::chain::detail {

using recognition::DomainElement;
using recognition::ElementType;

void listUnmachined(const DomainElement& e, const ElementState& st, const ProcessTemplate& tmpl,
                    std::vector<Unmachined>& out) {
    const std::string ft = featureTypeOf(e);
    bool anyStep = false;
    std::set<StepCode> listed;
    // Roughed only as deep as the crib reaches: listed first, with what it still needs (the
    // finishing steps' own reasons follow).
    if (!st.shortOfFloor.empty()) {
        out.push_back({e.id, StepCode::Rough, st.shortOfFloor, {}});
        listed.insert(StepCode::Rough);
    }
    for (const TemplateStep& s : tmpl.steps) {
        if (s.existence == Existence::MustNot || !s.machines(ft)) continue;
        anyStep = true;
        if (s.existence != Existence::Must) continue;
        if (st.steps.count(s.code)) continue;
        // A must-step with nothing to do (a floor already finished) is no gap.
        const auto g = st.gaps.find(s.code);
        if (g == st.gaps.end()) continue;
        out.push_back({e.id, s.code, g->second, {}});
        listed.insert(s.code);
    }
    if (!anyStep) {
        out.push_back(
            {e.id, std::nullopt, "no step of template '" + tmpl.name + "' machines feature type " + ft, {}});
        return;
    }
    if (st.units == 0 && listed.empty()) {
        std::string why;
        for (const auto& [code, text] : st.gaps)
            why += (why.empty() ? "" : "; ") + std::string(toString(code)) + ": " + text;
        if (why.empty()) why = "no step made a unit for it";
        out.push_back({e.id, std::nullopt, why, {}});
    }
    // Attached features no unit cuts.
    if (e.hole && e.hole->countersinkDiameter > 0 && !st.countersunk)
        out.push_back({e.id, std::nullopt,
                       "its " + fmt(e.hole->countersinkAngle) + " degree countersink (diameter " +
                           fmt(e.hole->countersinkDiameter) + " mm) is not cut: " +
                           (st.countersinkWhy.empty() ? std::string("no chamfer mill was offered") : st.countersinkWhy),
                       {}});
    const bool countersunk = std::any_of(e.attached.begin(), e.attached.end(),
                                         [](const recognition::AttachedFeature& a) { return a.kind == "countersink"; });
    if (!e.chamferFaces.empty() && !countersunk && !st.chamfered)
        listFaces(e,
                  std::to_string(e.chamferFaces.size()) + " chamfer face(s)" +
                      (st.chamferWhy.empty() ? std::string(" need a chamfer tool; the chain has none") : st.chamferWhy),
                  e.chamferFaces, out);
    // Walls leaning away from the axis: a flat end mill finishing them square to the floor leaves
    // depth x tan(lean) at their top. A drafted wall keeps within the tolerance; a bevel does not.
    // (An element no unit machines is listed whole above.)
    constexpr double kLeftOnLeaningWall = 0.1;  // mm
    if (st.units == 0) return;
    std::vector<int> leaning;
    double most = 0, steepest = 0;
    for (const recognition::AttachedFeature& a : e.attached) {
        if (a.kind != "open_corner" || a.faces.empty()) continue;
        const double left = e.depth * std::tan(a.size * M_PI / 180);
        if (!(left > kLeftOnLeaningWall)) continue;
        leaning.insert(leaning.end(), a.faces.begin(), a.faces.end());
        most = std::max(most, left), steepest = std::max(steepest, a.size);
    }
    if (!leaning.empty()) {
        std::string faces;
        for (int f : leaning) faces += (faces.empty() ? "" : ", ") + std::to_string(f);
        listFaces(e,
                  "face(s) " + faces + " lean up to " + fmt(steepest) +
                      " degrees from the tool axis (bevels with their blends): a flat end mill along this setup's "
                      "axis leaves up to " + fmt(most) + " mm on them; they need a setup along their normal",
                  leaning, out);
    }
}

void listFaces(const DomainElement& e, const std::string& reason, const std::vector<int>& faces,
               std::vector<Unmachined>& out) {
    std::set<int> named;
    for (const Unmachined& u : out) named.insert(u.faces.begin(), u.faces.end());
    std::vector<int> left;
    for (int f : faces)
        if (named.insert(f).second) left.push_back(f);
    if (!left.empty()) out.push_back({e.id, std::nullopt, reason, left});
}

void listIslandTops(const recognition::DomainTree& tree, const std::set<int>& faced, std::vector<Unmachined>& out) {
    // Island tops below the pocket's top: no step of the templates faces them, so the material
    // above them stays. Said, with the faces, rather than left unnoticed.
    std::set<int> topsListed = faced;  // a parent pocket names its child's island top too: once is enough
    for (const DomainElement& e : tree.elements)
        for (const recognition::AttachedFeature& a : e.attached)
            if (a.kind == "island_top" && !a.faces.empty() && e.type != ElementType::Hole &&
                !std::all_of(a.faces.begin(), a.faces.end(), [&](int f) { return topsListed.count(f) > 0; })) {
                topsListed.insert(a.faces.begin(), a.faces.end());
                Unmachined m;
                m.element = e.id;
                m.faces = a.faces;
                m.reason = "the top of an island below the top of " + elementName(e) +
                           " is not finished: no floor unit of the element faces it";
                out.push_back(m);
            }
}

}  // namespace aeronc::chain::detail
