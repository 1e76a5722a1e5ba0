#pragma once
// The pocket tree of one setup: each element's parent is the element at the nearest
// higher level whose region holds its sample point.
#include "ElementDraft.h"

#include <vector>

namespace aeronc::recognition {

// Sets parent and children of the drafts (indices into made); levels closer than
// 10 * linTol are one level.
void linkPocketTree(std::vector<ElementDraft>& made, double linTol);

}  // namespace aeronc::recognition
