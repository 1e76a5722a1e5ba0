#include "FaceClaims.h"

#include <algorithm>

namespace aeronc::recognition {

bool takenEarlier(const DomainElement& e, const std::vector<bool>& claimed) {
    bool taken = false;
    if (!e.floorFaces.empty()) {
        for (int f : e.floorFaces) taken |= claimed[static_cast<std::size_t>(f - 1)];
    } else {
        taken = !e.contourFaces.empty();
        for (int f : e.contourFaces) taken &= claimed[static_cast<std::size_t>(f - 1)];
    }
    return taken;
}

void claimFaces(std::vector<ElementDraft>& made, SetupDirection& setup, std::vector<bool>& claimed, DomainTree& tree) {
    std::vector<int> remap(made.size(), -1);
    std::vector<ElementDraft> kept;
    for (std::size_t k = 0; k < made.size(); ++k) {
        const DomainElement& e = made[k].el;
        const bool taken = takenEarlier(e, claimed) || made[k].dropped;  // dropped: a hole of the adjacency pass replaced it
        if (!taken) {
            remap[k] = static_cast<int>(tree.elements.size() + kept.size());
            kept.push_back(made[k]);
            // Faces an earlier setup machines stay with it: one owner per face.
            DomainElement& el = kept.back().el;
            auto mine = [&](std::vector<int>& v) {
                v.erase(std::remove_if(v.begin(), v.end(), [&](int f) { return claimed[static_cast<std::size_t>(f - 1)]; }),
                        v.end());
            };
            mine(el.contourFaces), mine(el.filletFaces), mine(el.chamferFaces), mine(el.topFaces);
            for (auto& isl : el.islandFaces) mine(isl);
            for (auto& a : el.attached) mine(a.faces);
        }
    }
    for (ElementDraft& in : kept) {
        DomainElement& e = in.el;
        // Parent dropped: attach to the nearest kept ancestor.
        int p = e.parent;
        while (p >= 0 && remap[static_cast<std::size_t>(p)] < 0) p = made[static_cast<std::size_t>(p)].el.parent;
        e.parent = p >= 0 ? remap[static_cast<std::size_t>(p)] : -1;
    }
    const int base = static_cast<int>(tree.elements.size());
    for (std::size_t k = 0; k < kept.size(); ++k) {
        DomainElement& e = kept[k].el;
        e.id = base + static_cast<int>(k);
        e.children.clear();
        for (auto& a : e.attached)
            if (a.element >= 0) a.element = remap[static_cast<std::size_t>(a.element)];
    }
    for (std::size_t k = 0; k < kept.size(); ++k) {
        DomainElement& e = kept[k].el;
        if (e.parent >= 0) kept[static_cast<std::size_t>(e.parent - base)].el.children.push_back(e.id);
        else setup.elements.push_back(e.id);
        auto claim = [&](const std::vector<int>& v) {
            for (int f : v) claimed[static_cast<std::size_t>(f - 1)] = true;
        };
        claim(e.floorFaces), claim(e.contourFaces), claim(e.filletFaces), claim(e.chamferFaces);
        for (auto& isl : e.islandFaces) claim(isl);
        for (auto& a : e.attached) claim(a.faces);
    }
    for (auto& in : kept) tree.elements.push_back(std::move(in.el));
}

}  // namespace aeronc::recognition
