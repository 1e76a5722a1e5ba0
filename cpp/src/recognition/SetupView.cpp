#include "SetupView.h"

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

}  // namespace

SetupView::SetupView(const FaceCatalogue& faces, const Tolerances& tol, const Vec3& d,
                     const std::vector<Vec3>& principalAxes, const RecogniseOptions& options)
    : faces(faces), tol(tol), axis(d), frame(alignedFrame(d, principalAxes, tol)) {
    reach_.assign(static_cast<std::size_t>(faces.size()), -1);
    rays_ = std::make_unique<AxisRays>(faces, frame);
    fs = classifyFaces(faces, frame, tol);

    // Part extent in the setup frame.
    gp_Trsf t;
    t.SetValues(frame.u[0], frame.u[1], frame.u[2], 0, frame.v[0], frame.v[1], frame.v[2], 0, frame.w[0],
                frame.w[1], frame.w[2], 0);
    // The part's extremes in a prismatic part lie on its edges, whose boxes are exact
    // for lines and arcs (a face box can be loose, and the optimal one is slow).
    Bnd_Box box;
    const TopLoc_Location frameLoc(t);
    const TopTools_IndexedMapOfShape& edges = faces.edges();
    for (int e = 1; e <= edges.Extent(); ++e) BRepBndLib::Add(edges(e).Moved(frameLoc), box, false);
    double x0, y0, x1, y1;
    box.Get(x0, y0, h0, x1, y1, h1);
    const double gap = box.GetGap();
    x0 += gap, y0 += gap, h0 += gap, x1 -= gap, y1 -= gap, h1 -= gap;
    blankLo = {x0 - options.blankAllowance, y0 - options.blankAllowance};
    blankHi = {x1 + options.blankAllowance, y1 + options.blankAllowance};
    blankH0 = h0, blankH1 = h1;
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
    }
}

bool SetupView::reachable(int i) const {
    signed char& r = reach_[static_cast<std::size_t>(i)];
    if (r < 0) r = rays_->reachable(i) ? 1 : 0;
    return r == 1;
}

}  // namespace aeronc::recognition
