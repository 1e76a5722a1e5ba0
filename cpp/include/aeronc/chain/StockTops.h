#pragma once
// How high the material may still stand over each unit when it runs, from the chain's order:
// walls of the element that rise above the unit's top keep what earlier units left along them,
// and an ancestor not yet cleared (a counterbore milled after its hole is drilled) keeps its
// whole height. The toolpaths rapid above it and enter from it.
#include <aeronc/chain/MachiningChain.h>

namespace aeronc::chain {

// Sets MachiningUnit::stockTop (empty where nothing stands above the unit's top). Needs the
// units' order; arrange() calls it.
void setStockTops(MachiningChain& chain);

}  // namespace aeronc::chain
