#include "SetupView.h"

#include "Workers.h"

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <TopLoc_Location.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <limits>

namespace aeronc::recognition {
namespace {

SetupFrame alignedFrame(const Vec3& d, const std::vector<Vec3>& axes, const Tolerances& tol) {
    const Vec3* ref = nullptr;
    for (const Vec3& a : axes)
        if (std::fabs(dot(a, d)) <= tol.squareSin) {
            ref = &a;
            break;
        }
    return SetupFrame(d, ref);
}

// Moves world coordinates into the orthonormal frame (a, b, c).
TopLoc_Location frameLocation(const Vec3& a, const Vec3& b, const Vec3& c) {
    gp_Trsf t;
    t.SetValues(a[0], a[1], a[2], 0, b[0], b[1], b[2], 0, c[0], c[1], c[2], 0);
    return TopLoc_Location(t);
}

void boxGet(const Bnd_Box& box, double lo[3], double hi[3]) {
    box.Get(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    const double gap = box.GetGap();
    for (int k = 0; k < 3; ++k) lo[k] += gap, hi[k] -= gap;
}

// The part's box in the orthonormal frame (a, b, c): a prismatic part's extremes lie on its
// edges, whose boxes are exact for lines and arcs (a face box can be loose, and the optimal
// one is slow).
void boxIn(const TopTools_IndexedMapOfShape& edges, const Vec3& a, const Vec3& b, const Vec3& c, double lo[3],
           double hi[3]) {
    const TopLoc_Location loc = frameLocation(a, b, c);
    Bnd_Box box;
    for (int e = 1; e <= edges.Extent(); ++e) BRepBndLib::Add(edges(e).Moved(loc), box, false);
    boxGet(box, lo, hi);
}

}  // namespace

SetupView::SetupView(const FaceCatalogue& faces, const Tolerances& tol, const Vec3& d,
                     const std::vector<Vec3>& principalAxes, const RecogniseOptions& options)
    : faces(faces), tol(tol), axis(d), frame(alignedFrame(d, principalAxes, tol)) {
    reach_.assign(static_cast<std::size_t>(faces.size()), -1);
    fs = classifyFaces(faces, frame, tol);

    // Part extent in the setup frame.
    const TopTools_IndexedMapOfShape& edges = faces.edges();
    double lo[3], hi[3];
    boxIn(edges, frame.u, frame.v, frame.w, lo, hi);
    const double x0 = lo[0], y0 = lo[1], x1 = hi[0], y1 = hi[1];
    h0 = lo[2], h1 = hi[2];
    blankLo = {x0 - options.blankAllowance, y0 - options.blankAllowance};
    blankHi = {x1 + options.blankAllowance, y1 + options.blankAllowance};
    blankH0 = h0, blankH1 = h1;
    clampedBlankTop = h1;
    if (!options.blank && principalAxes.size() >= 4) {
        // The box a machinist clamps: square to the part's principal axes, whatever the part's
        // placement in the world, grown by the allowance.
        const Vec3& a = principalAxes[0];
        Vec3 b = principalAxes[2];
        const double k = dot(a, b);
        b = {b[0] - k * a[0], b[1] - k * a[1], b[2] - k * a[2]};
        const double bn = norm(b);
        b = {b[0] / bn, b[1] / bn, b[2] / bn};
        const Vec3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        double plo[3], phi[3];
        boxIn(edges, a, b, c, plo, phi);
        const Vec3* axes[3] = {&a, &b, &c};
        clampedBlankTop = 0;
        for (int i = 0; i < 3; ++i) {
            const double ci = dot(frame.w, *axes[i]);
            clampedBlankTop += std::max(ci * (plo[i] - options.blankAllowance), ci * (phi[i] + options.blankAllowance));
        }
    }
    if (options.blank) {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        blankLo = {kInf, kInf}, blankHi = {-kInf, -kInf};
        blankH0 = kInf, blankH1 = -kInf;
        for (int c = 0; c < 8; ++c) {
            const Vec3 p{(c & 1) ? options.blank->max[0] : options.blank->min[0],
                         (c & 2) ? options.blank->max[1] : options.blank->min[1],
                         (c & 4) ? options.blank->max[2] : options.blank->min[2]};
            const P2 q = frame.project(p);
            blankLo.x = std::min(blankLo.x, q.x), blankLo.y = std::min(blankLo.y, q.y);
            blankHi.x = std::max(blankHi.x, q.x), blankHi.y = std::max(blankHi.y, q.y);
            blankH0 = std::min(blankH0, frame.height(p)), blankH1 = std::max(blankH1, frame.height(p));
        }
        clampedBlankTop = blankH1;
    }
}

void SetupView::faceBox(int i, P2& lo, P2& hi) const {
    Bnd_Box box;
    BRepBndLib::Add(faces[i].face.Moved(frameLocation(frame.u, frame.v, frame.w)), box, false);
    double l[3], h[3];
    boxGet(box, l, h);
    lo = {l[0], l[1]}, hi = {h[0], h[1]};
}

AxisRays& SetupView::rays() const {
    std::lock_guard<std::mutex> lock(raysMutex_);
    const std::size_t w = static_cast<std::size_t>(workerSlot());
    if (rays_.size() <= w) rays_.resize(w + 1);
    auto& r = rays_[w];
    if (!r) r = std::make_unique<AxisRays>(faces, frame);
    return *r;
}

bool SetupView::reachable(int i) const {
    signed char& r = reach_[static_cast<std::size_t>(i)];
    if (r < 0) r = rays().reachable(i) ? 1 : 0;
    return r == 1;
}

}  // namespace aeronc::recognition
