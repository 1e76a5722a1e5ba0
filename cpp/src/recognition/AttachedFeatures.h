#pragma once
// Features attached to the elements: what a pocket carries besides its floor and walls.
#include "ElementDraft.h"
#include "SetupView.h"

#include <vector>

namespace aeronc::recognition {

// Of each element on its own: floor fillets (and the corner blends between them), bevels
// and chamfers on the walls, island tops, and the top faces at the top of the walls.
// boxSides (per face): the part's box sides, which are nobody's chamfer.
void attachElementFeatures(std::vector<ElementDraft>& made, const SetupView& view, const std::vector<bool>& boxSides);

// Between elements of the linked tree: joggles (a shallow child sharing a wall with its
// parent), ribs (the floor of a region joining several pockets) and flanges.
void attachTreeFeatures(std::vector<ElementDraft>& made);

}  // namespace aeronc::recognition
