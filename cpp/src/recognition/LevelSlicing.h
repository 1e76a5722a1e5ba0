#pragma once
// Layered slicing of one setup: the part is cut at each level where a floor, an exit or a
// hole bottom lies, just above it, and the void regions there become elements (closed and
// open pockets, openings; holes are told apart later). LevelSlicer makes the sections.
#include "ElementDraft.h"
#include "ElementMeasures.h"
#include "SetupView.h"
#include "VoidRegions.h"

#include <string>
#include <vector>

namespace aeronc::recognition {

class LevelSlicing {
public:
    // Finds the levels; widths is shared by the setups, warnings collects the sections'.
    LevelSlicing(const SetupView& view, RegionWidths& widths, std::vector<std::string>& warnings);

    // Ascending: the part's bottom, floors the tool reaches, faces that openings leave the
    // part by, hole bottoms on a drill point or on a transverse bore.
    const std::vector<double>& levels() const { return levels_; }

    // Appends the elements whose floor (or exit) is levels()[k] to made; their ids are their
    // indices in made, their faces FaceN.
    void slice(std::size_t k, int setupId, std::vector<ElementDraft>& made);

private:
    bool leavesPart(VoidRegion& c, double h, double z) const;
    // Whether material lies above the region anywhere, seen from the slice at z.
    bool capped(const VoidRegion& c, double z) const;

    const SetupView& view_;
    const FaceCatalogue& faces_;
    RegionWidths& widths_;
    std::vector<std::string>& warnings_;
    std::vector<double> levels_;
    std::vector<double> critical_;  // heights where faces start or end, ascending
};

}  // namespace aeronc::recognition
