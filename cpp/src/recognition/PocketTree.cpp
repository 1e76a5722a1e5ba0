#include "PocketTree.h"

#include <limits>

namespace aeronc::recognition {

void linkPocketTree(std::vector<ElementDraft>& made, double linTol) {
    for (std::size_t k = 0; k < made.size(); ++k) {
        ElementDraft& in = made[k];
        int best = -1;
        double bestLevel = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < made.size(); ++j) {
            const ElementDraft& o = made[j];
            if (o.el.level <= in.el.level + 10 * linTol || o.el.level >= bestLevel) continue;
            if (o.region.contains(in.sample)) best = static_cast<int>(j), bestLevel = o.el.level;
        }
        in.el.parent = best;
    }
    for (ElementDraft& in : made)
        if (in.el.parent >= 0) made[static_cast<std::size_t>(in.el.parent)].el.children.push_back(in.el.id);
}

}  // namespace aeronc::recognition
