#pragma once
// The part seen along one setup direction: the setup's frame, how each face stands in it,
// the part's extent and the blank there, and rays along the axis. The per-setup algorithms
// (level slicing, holes, attached features) share it.
#include <aeronc/recognition/Recogniser.h>
#include <aeronc/recognition/SetupFrame.h>

#include "AxisRays.h"
#include "FaceCatalogue.h"
#include "FaceInSetup.h"
#include "MeshSection.h"
#include "Tolerances.h"

#include <memory>
#include <mutex>
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
    MeshSection* meshes = nullptr;  // the part's section of blends and splines, shared by the setups
    double blankH0 = 0, blankH1 = 0;  // and its height range: the part's, or the given blank's
    // The highest corner along the axis of the blank as clamped: the given blank, else the part's
    // box square to its principal axes grown by the allowance. On a tilted axis it stands above
    // h1: over an exterior region all of it is there to cut.
    double clampedBlankTop = 0;

    // The box of face i (0-based) seen along the axis, in the slicing plane.
    void faceBox(int i, P2& lo, P2& hi) const;
    // Rays along the axis, one caster per worker (a caster keeps per-face state).
    AxisRays& rays() const;
    // Whether the tool reaches face i from this side, computed once per face.
    bool reachable(int i) const;

private:
    mutable std::vector<std::unique_ptr<AxisRays>> rays_;  // by worker
    mutable std::mutex raysMutex_;
    mutable std::vector<signed char> reach_;  // -1 unknown, 0/1; reachable() before any thread
};

}  // namespace aeronc::recognition
