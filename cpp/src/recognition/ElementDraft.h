#pragma once
// An element while its setup is recognised. Its region at the slicing level and a point
// inside it place it in the pocket tree; ids and face numbers are final only once the
// setup's faces are claimed.
#include <aeronc/recognition/DomainTree.h>

#include "Region.h"

namespace aeronc::recognition {

struct ElementDraft {
    DomainElement el;  // id, parent and children index the setup's drafts
    Region region;
    P2 sample;
    bool fromChain = false;  // a hole of the face-adjacency pass (HoleChains)
    bool dropped = false;    // replaced by such a hole: kept out of the tree
};

}  // namespace aeronc::recognition
