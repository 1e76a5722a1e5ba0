#pragma once
// The role of every face of the part (DomainTree::faceRoles and faceElement).
#include <aeronc/recognition/DomainTree.h>

#include "FaceCatalogue.h"
#include "Tolerances.h"

namespace aeronc::recognition {

// By priority over all elements: a face that is some element's floor is a floor, whatever
// else touches it; then walls; then blends and chamfers; then rib and island tops. A face
// keeps the first role it gets. What no element machines is the top of the part in the
// first setup, else stock.
void assignFaceRoles(DomainTree& tree, const FaceCatalogue& faces, const Tolerances& tol);

}  // namespace aeronc::recognition
