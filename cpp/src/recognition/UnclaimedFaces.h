#pragma once
// Faces no element machines although they lie inside the blank: material the recognition
// did not account for. They are reported, never dropped in silence.
#include <aeronc/recognition/DomainTree.h>

#include "SetupView.h"

#include <vector>

namespace aeronc::recognition {

// Marks the planar faces of the part that lie on a face of the setup's blank box (the
// part's outside that no tool has to cut).
void markBlankBoundaryFaces(const SetupView& view, std::vector<bool>& onBlank);

// Lists in tree.unclaimedFaces (FaceN) and in one warning the faces that no element claims
// and that are not on the blank's boundary.
void reportUnclaimedFaces(DomainTree& tree, const std::vector<bool>& onBlank);

}  // namespace aeronc::recognition
