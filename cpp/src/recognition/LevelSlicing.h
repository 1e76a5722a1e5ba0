#pragma once
// Layered slicing of one setup: the part is cut at each level where a floor, an exit or a
// hole bottom lies, just above it, and the void regions there become elements (closed and
// open pockets, openings; holes are told apart later). LevelSlicer makes the sections.
#include "ElementDraft.h"
#include "ElementMeasures.h"
#include "SetupView.h"
#include "VoidRegions.h"

#include <functional>
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
    // indices in made, their faces FaceN. Section warnings go to `warnings`.
    void slice(std::size_t k, int setupId, std::vector<ElementDraft>& made, std::vector<std::string>& warnings);

    // Slices every level that can make an element no earlier setup took (claimed: per face,
    // an earlier setup machines it), on up to `threads` threads (the levels are independent),
    // and appends the elements in level order as slice() would. progress(fraction) is called
    // from this thread; returning false stops the work and throws the cancel.
    void sliceAll(int setupId, std::vector<ElementDraft>& made, int threads,
                  const std::function<bool(double)>& progress, const std::vector<bool>& claimed);

private:
    // The height the level is cut at (above its floor fillets), with the floors there; `low`:
    // just above the fillets, where the material a leaning wall stands on is widest.
    double sliceHeight(std::size_t k, std::vector<int>& ups, double* low = nullptr) const;
    // The pieces of c's region reachable from above: what lies under material between the slice
    // z and `top` (an undercut, with a warning) and the material that walls leaning back from
    // the floor (a bevel facing up, a round falling past the floor) hold between the slice and
    // `low`, or the floor h where they go on down, and B-spline floor fillets are left out. Of a region with floors each piece holding some of them (with those
    // floors), else the largest piece; none when nothing is reachable.
    std::vector<VoidRegion> trimToReach(const VoidRegion& c, double h, double z, double low, double top,
                                        std::vector<std::string>& warnings) const;
    // The material at height zl within the boxes of c's contour faces that lean back between
    // zl and z, and at the floor h within the boxes of those going on down past zl and of the
    // floor fillets without a radius (B-spline blends), as paths; empty when none leans.
    // `leaning` receives the leaning walls.
    ClipperLib::Paths leaningMaterial(const VoidRegion& c, double h, double zl, double z,
                                      std::vector<int>& leaning) const;
    // The material that walls leaning over the region hold between the slice z and `top` (an
    // island wider at its top than at the slice, a drafted boss, a dovetail side), within the
    // boxes of those faces, as paths; empty when none leans over. A tool from above keeps off
    // it all the way down.
    ClipperLib::Paths overhangingMaterial(const VoidRegion& c, double z, double top) const;
    // How high the island around `hole` (one of c's region holes) stands, at most `top`.
    double islandTop(const VoidRegion& c, const ClipperLib::Path& hole, double top) const;
    // The part's section at height z: outer loops and holes, to be read even-odd.
    ClipperLib::Paths materialAt(double z) const;
    // The faces a plane at height z may cut.
    std::vector<int> cutFaces(double z) const;
    bool useful(std::size_t k, const std::vector<bool>& claimed) const;
    bool leavesPart(VoidRegion& c, double h, double z) const;
    // Drops the floors and rib tops of c that its (trimmed) region no longer holds; false when
    // no floor is left.
    bool keepReachedFloors(VoidRegion& c) const;
    // Whether the part holds material a little under the level inside c's region (away from
    // its walls): walls ending there end on it, so no opening leaves the part there.
    bool materialUnder(const VoidRegion& c, double h) const;
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
