#pragma once
// The hole chains along one setup direction become hole elements of that setup, in place of
// whatever the slicing made of their faces (a partial hole in a pocket's wall, a hole on a
// recessed face left as stock). One element per diameter, from the mouth in, so that a
// counterbore is the parent of its hole as in the slicing's holes.
#include "ElementDraft.h"
#include "HoleChains.h"
#include "SetupView.h"

#include <vector>

namespace aeronc::recognition {

// Appends the drafts of the chain segments a tool reaches along view's direction (taken: per
// chain and segment, a setup made it; claimed: per face, an earlier setup owns it), links them
// into the tree, drops the slicing's drafts they replace and takes their faces out of the
// other drafts.
void addChainHoles(std::vector<ElementDraft>& made, const SetupView& view, const std::vector<HoleChain>& chains,
                   std::vector<std::vector<bool>>& taken, const std::vector<bool>& claimed);

// Takes the faces of chains left for other setups (reserved, per face) out of the drafts
// that are not holes, so that no pocket of this setup owns a hole's wall as its own, and
// drops this setup's holes bounded by such walls alone.
void releaseReservedFaces(std::vector<ElementDraft>& made, const std::vector<bool>& reserved);

}  // namespace aeronc::recognition
