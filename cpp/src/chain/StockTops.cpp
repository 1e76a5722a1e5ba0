#include <aeronc/chain/StockTops.h>

#include <algorithm>
#include <map>

namespace aeronc::chain {

namespace {

// The steps that clear an element's whole region down to their bottom (plus the axial allowance).
bool clears(StepCode s) { return s == StepCode::Rough || s == StepCode::Web || s == StepCode::HoleMill; }

}  // namespace

void setStockTops(MachiningChain& chain) {
    // Per element, the enabled clearing units in order: (order, the height they leave). A
    // roughing short of its element's floor is not counted on: the gate may leave it out alone.
    std::map<int, std::vector<std::pair<int, double>>> cleared;
    for (const MachiningUnit& u : chain.units)
        if (u.enabled && clears(u.step) && !u.shortOfFloor)
            cleared[u.element].push_back({u.order, u.bottom + u.axialAllowance});

    // What stands over an ancestor's region before unit `order` runs: its top, or the lowest
    // height its clearing units that ran before left.
    auto standing = [&](const ChainElement& a, int order) {
        double h = a.top;
        const auto it = cleared.find(a.id);
        if (it != cleared.end())
            for (const auto& [o, left] : it->second)
                if (o < order) h = std::min(h, left);
        return h;
    };

    std::map<int, double> blankTops;
    for (const ChainSetup& s : chain.setups)
        if (s.blankTop) blankTops[s.id] = *s.blankTop;
    for (MachiningUnit& u : chain.units) {
        double top = u.top;
        const ChainElement* e = chain.element(u.element);
        if (e) {
            top = std::max(top, e->top);
            const ChainElement* root = e;
            int guard = 0;  // a parent loop in a damaged chain must not hang
            for (const ChainElement* a = chain.element(e->parent); a && guard < 64; a = chain.element(a->parent), ++guard)
                top = std::max(top, standing(*a, u.order)), root = a;
            // Over a root below the blank's top (a pocket in a face another setup or nothing
            // here lowers) anything of the blank may still stand: come down at feed from there.
            const auto b = blankTops.find(e->setup);
            if (b != blankTops.end() && root->top < b->second - 1e-6) top = std::max(top, b->second);
        }
        u.stockTop.reset();
        if (top > u.top + 1e-9) u.stockTop = top;
    }
}

}  // namespace aeronc::chain
