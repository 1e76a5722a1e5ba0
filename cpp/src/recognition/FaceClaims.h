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
// chamferOf: per face, the element whose chamfer it is (-1: none). A chamfer is claimed
// weakly: a slanted face beside a wall may be the wall of a feature crossing it that a later
// setup finds, and then that feature takes it (and it counts as claimed from then on).
void claimFaces(std::vector<ElementDraft>& made, SetupDirection& setup, std::vector<bool>& claimed,
                std::vector<int>& chamferOf, DomainTree& tree);

// Whether an earlier setup owns the element already: one of its floors, or without a floor
// all its walls, are claimed.
bool takenEarlier(const DomainElement& e, const std::vector<bool>& claimed);

}  // namespace aeronc::recognition
