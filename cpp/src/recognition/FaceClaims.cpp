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

namespace {

void erase(std::vector<int>& v, int f) { v.erase(std::remove(v.begin(), v.end(), f), v.end()); }

// Face f (FaceN) leaves the chamfers of the element that held it.
void unchamfer(DomainElement& e, int f) {
    erase(e.chamferFaces, f);
    for (AttachedFeature& a : e.attached)
        if (a.kind == "chamfer") erase(a.faces, f);
    e.attached.erase(std::remove_if(e.attached.begin(), e.attached.end(),
                                    [](const AttachedFeature& a) { return a.kind == "chamfer" && a.faces.empty(); }),
                     e.attached.end());
}

}  // namespace

void claimFaces(std::vector<ElementDraft>& made, SetupDirection& setup, std::vector<bool>& claimed,
                std::vector<int>& chamferOf, DomainTree& tree) {
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
            // A chamfer already some element's stays with it.
            for (int f : std::vector<int>(el.chamferFaces))
                if (chamferOf[static_cast<std::size_t>(f - 1)] >= 0) unchamfer(el, f);
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
            for (int f : v) {
                int& owner = chamferOf[static_cast<std::size_t>(f - 1)];
                if (owner >= 0 && owner < base) unchamfer(tree.elements[static_cast<std::size_t>(owner)], f);
                owner = -1;
                claimed[static_cast<std::size_t>(f - 1)] = true;
            }
        };
        claim(e.floorFaces), claim(e.contourFaces), claim(e.filletFaces);
        for (auto& isl : e.islandFaces) claim(isl);
        for (auto& a : e.attached)  // a joggle's faces are its own pocket's floor: that pocket claims them
            if (a.kind != "chamfer" && a.kind != "joggle") claim(a.faces);
    }
    // Chamfers last: a face that is another kept element's wall is that element's.
    for (std::size_t k = 0; k < kept.size(); ++k) {
        DomainElement& e = kept[k].el;
        for (int f : std::vector<int>(e.chamferFaces)) {
            int& owner = chamferOf[static_cast<std::size_t>(f - 1)];
            if (claimed[static_cast<std::size_t>(f - 1)] || owner >= 0) unchamfer(e, f);
            else owner = e.id;
        }
    }
    for (auto& in : kept) tree.elements.push_back(std::move(in.el));
}

}  // namespace aeronc::recognition
