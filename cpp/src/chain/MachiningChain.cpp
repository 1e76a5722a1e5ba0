#include <aeronc/chain/MachiningChain.h>

namespace aeronc::chain {

const ChainTool* MachiningChain::tool(const std::string& id) const {
    for (const ChainTool& t : tools)
        if (t.id == id) return &t;
    return nullptr;
}

const ChainElement* MachiningChain::element(int id) const {
    for (const ChainElement& e : elements)
        if (e.id == id) return &e;
    return nullptr;
}

const ChainSetup* MachiningChain::setup(int id) const {
    for (const ChainSetup& s : setups)
        if (s.id == id) return &s;
    return nullptr;
}

const char* settingOperation(StepCode step) {
    switch (step) {
        case StepCode::Rough:
        case StepCode::Corner:
        case StepCode::CutOff:
        case StepCode::HoleMill: return "roughing";
        case StepCode::Drill: return "drilling";
        default: return "finishing";
    }
}

}  // namespace aeronc::chain
