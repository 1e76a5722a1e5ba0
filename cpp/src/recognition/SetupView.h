#pragma once
// The part seen along one setup direction: the setup's frame, how each face stands in it,
// the part's extent and the blank there, and rays along the axis. The per-setup algorithms
// (level slicing, holes, attached features) share it.
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/recognition/SetupFrame.h>

#include "AxisRays.h"
#include "FaceCatalogue.h"
#include "FaceInSetup.h"
#include "Tolerances.h"

#include <memory>
#include <vector>

namespace aeronc::recognition {

class SetupView {
public:
    // d: the tool axis; its frame's u is aligned with the first of `principalAxes` square
    // to d, so the blank box in this frame fits a rotated part.
    SetupView(const FaceCatalogue& faces, const Tolerances& tol, const Vec3& d, const std::vector<Vec3>& principalAxes,
              const RecogniseOptions& options);

    const FaceCatalogue& faces;
    const Tolerances tol;
    const Vec3 axis;  // as given; frame.w is its unit vector
    const SetupFrame frame;
    std::vector<FaceInSetup> fs;  // index: face (0-based)
    double h0 = 0, h1 = 0;        // the part's height range
    P2 blankLo, blankHi;          // the blank's rectangle in the slicing plane
    double blankH0 = 0, blankH1 = 0;  // and its height range: the part's, or the given blank's

    AxisRays& rays() const { return *rays_; }
    // Whether the tool reaches face i from this side, computed once per face.
    bool reachable(int i) const;

private:
    std::unique_ptr<AxisRays> rays_;
    mutable std::vector<signed char> reach_;  // -1 unknown, 0/1
};

}  // namespace aeronc::recognition
