#pragma once
// The long-reach reduction of the handbook's cutting data: a necked tool reaching more than
// long_reach_ratio diameters bends and chatters at the data of a short one, so the catalogues
// lower its a_p and f_z (thresholds long_reach_ap_factor, long_reach_fz_factor; docs/tool-crib.md).
#include <aeronc/kb/KnowledgeBase.h>
#include <aeronc/toolselect/Tool.h>

namespace aeronc::kb {

struct LongReach {
    double ratio;     // reach / diameter above which the reduction applies; infinity: never
    double apFactor;  // a_p times this
    double fzFactor;  // f_z times this

    // From the knowledge base's thresholds; absent ones reduce nothing.
    static LongReach of(const KnowledgeBase& kb);
    bool applies(const toolselect::Tool& t) const;
    // The condition as the tool should use it.
    CuttingCondition applied(const toolselect::Tool& t, const CuttingCondition& c) const;
};

}  // namespace aeronc::kb
