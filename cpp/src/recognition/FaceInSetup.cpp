#include "FaceInSetup.h"

#include <cmath>

namespace aeronc::recognition {

std::vector<FaceInSetup> classifyFaces(const FaceCatalogue& faces, const SetupFrame& frame, const Tolerances& tol) {
    const Vec3& w = frame.w;
    const auto ranges = faces.heightRanges(frame.u, frame.v, w);
    std::vector<FaceInSetup> out(static_cast<std::size_t>(faces.size()));
    for (int i = 0; i < faces.size(); ++i) {
        const FaceInfo& f = faces[i];
        FaceInSetup& s = out[static_cast<std::size_t>(i)];
        s.lo = ranges[static_cast<std::size_t>(i)].lo;
        s.hi = ranges[static_cast<std::size_t>(i)].hi;
        s.base = ranges[static_cast<std::size_t>(i)].base;
        if (f.kind == SurfaceKind::Plane) {
            const double c = dot(f.normal, w);
            if (c >= tol.parallelCos) s.att = Attitude::Up;
            else if (c <= -tol.parallelCos) s.att = Attitude::Down;
            else if (std::fabs(c) <= tol.squareSin) s.att = Attitude::Vertical;
            else s.att = Attitude::Inclined;
            if (s.att == Attitude::Up || s.att == Attitude::Down) s.h = 0.5 * (s.lo + s.hi);
        } else if ((f.kind == SurfaceKind::Cylinder) && std::fabs(dot(f.axisDir, w)) >= tol.parallelCos) {
            s.att = Attitude::Vertical;
        } else {
            s.att = Attitude::Curved;
        }
    }
    return out;
}

}  // namespace aeronc::recognition
