#pragma once
// Measures of an element that bound the tool: the narrowest passage of its region and the
// smallest concave corner radius along its walls.
#include <aeronc/recognition/DomainTree.h>

#include "ElementDraft.h"
#include "FaceCatalogue.h"
#include "FaceInSetup.h"
#include "Region.h"
#include "VoidRegions.h"

#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

namespace aeronc::recognition {

// Region::minWidth, computed once per region shape: repeated pockets share it.
class RegionWidths {
public:
    double minWidth(const Region& r);

private:
    std::unordered_map<std::string, double> widths_;  // by the region's shape, translation removed
    std::mutex mutex_;
};

// Sets the narrowest passage (minWidth) of the drafts that will stay in the tree (claimed:
// per face, an earlier setup machines it; see claimFaces), measuring them on up to `threads`
// threads: the erosions are the costliest step after the sections.
void measureWidths(std::vector<ElementDraft>& made, const std::vector<bool>& claimed, RegionWidths& widths,
                   int threads);

// Sets e.minCornerRadius from the region's loops (0 where two walls meet sharp, -1 when
// there is no corner) and attaches a corner_fillet feature per concave radius.
void measureCorners(const VoidRegion& c, const FaceCatalogue& faces, const std::vector<FaceInSetup>& fs,
                    DomainElement& e);

}  // namespace aeronc::recognition
