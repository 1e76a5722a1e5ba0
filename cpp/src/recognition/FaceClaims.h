#pragma once
// One owner per face across setups: the first setup to machine a face keeps it.
#include <aeronc/recognition/DomainTree.h>

#include "ElementDraft.h"

#include <vector>

namespace aeronc::recognition {

// Adds a setup's drafts to the tree. A draft whose floors (or, without floor, all walls)
// an earlier setup claimed already belongs to that setup and is dropped; the faces the
// kept ones share with earlier setups stay with those. Parents dropped give way to the
// nearest kept ancestor. Drafts get their ids in the tree, and their faces are claimed.
// claimed: per face (0-based), whether some setup machines it.
void claimFaces(std::vector<ElementDraft>& made, SetupDirection& setup, std::vector<bool>& claimed, DomainTree& tree);

// Whether an earlier setup owns the element already: one of its floors, or without a floor
// all its walls, are claimed.
bool takenEarlier(const DomainElement& e, const std::vector<bool>& claimed);

}  // namespace aeronc::recognition
