#include "HoleChecks.h"

#include "Validate.h"

#include <aeronc/core/Error.h>

#include <cmath>

namespace aeronc::toolpath {

void checkHoles(const std::vector<Hole>& holes) {
    if (holes.empty()) throw inputError("no holes given");
    for (std::size_t i = 0; i < holes.size(); ++i) {
        const Hole& h = holes[i];
        const std::string what = "hole " + std::to_string(i + 1);
        for (double v : {h.centre[0], h.centre[1], h.diameter, h.top, h.bottom, h.floorFilletRadius})
            requireFinite(v, what + "'s value");
        if (h.floorFilletRadius < 0) throw inputError(what + ": negative floor fillet radius");
        if (std::abs(h.centre[0]) > 1e6 || std::abs(h.centre[1]) > 1e6) throw inputError(what + " lies beyond 10^6 mm");
        if (!(h.bottom < h.top)) throw inputError(what + ": bottom must lie below top");
        if (h.diameter < 0) throw inputError(what + ": negative diameter");
    }
}

}  // namespace aeronc::toolpath
