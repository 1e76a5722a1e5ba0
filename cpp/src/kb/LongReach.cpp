#include <aeronc/kb/LongReach.h>

#include <limits>

namespace aeronc::kb {

LongReach LongReach::of(const KnowledgeBase& kb) {
    return {kb.findThreshold("long_reach_ratio").value_or(std::numeric_limits<double>::infinity()),
            kb.findThreshold("long_reach_ap_factor").value_or(1.0),
            kb.findThreshold("long_reach_fz_factor").value_or(1.0)};
}

bool LongReach::applies(const toolselect::Tool& t) const {
    return t.necked() && t.reach > ratio * t.diameter + 1e-9;
}

CuttingCondition LongReach::applied(const toolselect::Tool& t, const CuttingCondition& c) const {
    CuttingCondition r = c;
    if (applies(t)) r.ap *= apFactor, r.fz *= fzFactor;
    return r;
}

}  // namespace aeronc::kb
