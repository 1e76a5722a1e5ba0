#include <aeronc/core/Error.h>
#include <aeronc/toolselect/Selection.h>

#include <cmath>
#include <sstream>

namespace aeronc::toolselect {

namespace {
constexpr double kTol = 1e-6;  // mm: radii stored as decimals compare equal
}

const Tool* finishingTool(const PocketGeometry& pocket, const std::vector<Tool>& tools) {
    const double fillet = std::max(0.0, pocket.floorFilletRadius);
    const Tool* best = nullptr;
    bool bestMatchesFillet = false;
    for (const Tool& t : tools) {
        t.validate();
        if (!t.isEndMill()) continue;
        if (pocket.minCornerRadius >= 0 && t.radius() > pocket.minCornerRadius + kTol) continue;
        if (t.cornerRadius > fillet + kTol) continue;
        if (t.usableLength() < pocket.depth - kTol) continue;
        // A corner radius equal to the floor fillet cuts the fillet as drawn, so such a
        // tool wins over a larger one that would leave it for another pass.
        const bool matches = fillet > 0 && std::fabs(t.cornerRadius - fillet) <= kTol;
        if (!best || (matches && !bestMatchesFillet) ||
            (matches == bestMatchesFillet && t.diameter > best->diameter + kTol))
            best = &t, bestMatchesFillet = matches;
    }
    if (best) return best;

    std::ostringstream m;
    m << "pocket '" << pocket.name << "': none of the " << tools.size()
      << " tools can finish it; it needs an end mill with radius <= ";
    if (pocket.minCornerRadius >= 0) m << pocket.minCornerRadius << " mm";
    else m << "any";
    m << ", corner radius <= " << fillet << " mm and flute length and reach >= " << pocket.depth << " mm";
    throw inputError(m.str());
}

}  // namespace aeronc::toolselect
