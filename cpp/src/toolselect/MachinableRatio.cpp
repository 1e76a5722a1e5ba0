#include "PocketRegion.h"

#include <aeronc/toolselect/Selection.h>

#include <algorithm>
#include <cmath>

namespace aeronc::toolselect {
using namespace ClipperLib;

namespace {

struct Box {
    double x0, y0, x1, y1;
};

struct Segment {
    double ax, ay, bx, by;
    Box box;
};

std::vector<Segment> segmentsOf(const Paths& ps) {
    std::vector<Segment> s;
    for (const Path& p : ps)
        for (std::size_t i = 0; i < p.size(); ++i) {
            const IntPoint& a = p[i];
            const IntPoint& b = p[(i + 1) % p.size()];
            Segment g{a.X / kScale, a.Y / kScale, b.X / kScale, b.Y / kScale, {}};
            g.box = {std::min(g.ax, g.bx), std::min(g.ay, g.by), std::max(g.ax, g.bx), std::max(g.ay, g.by)};
            s.push_back(g);
        }
    return s;
}

Box boxOf(const Path& p, double grow) {
    Box b{1e300, 1e300, -1e300, -1e300};
    for (const IntPoint& q : p) {
        b.x0 = std::min(b.x0, q.X / kScale), b.y0 = std::min(b.y0, q.Y / kScale);
        b.x1 = std::max(b.x1, q.X / kScale), b.y1 = std::max(b.y1, q.Y / kScale);
    }
    return {b.x0 - grow, b.y0 - grow, b.x1 + grow, b.y1 + grow};
}

bool overlaps(const Box& a, const Box& b) { return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1; }

double dist2(double px, double py, const Segment& s) {
    const double dx = s.bx - s.ax, dy = s.by - s.ay, l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((px - s.ax) * dx + (py - s.ay) * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    const double ex = s.ax + t * dx - px, ey = s.ay + t * dy - py;
    return ex * ex + ey * ey;
}

// Runs of a leftover piece's contour that lie off the pocket boundary, i.e. where the
// piece meets the reachable region. A corner leftover has one; a passage the tool
// cannot pass has one on each side.
int reachableSideRuns(const Path& piece, const std::vector<Segment>& boundary, double tol) {
    const Box box = boxOf(piece, tol);
    std::vector<const Segment*> near;
    for (const Segment& s : boundary)
        if (overlaps(box, s.box)) near.push_back(&s);
    const std::size_t n = piece.size();
    std::vector<char> off(n);
    for (std::size_t i = 0; i < n; ++i) {
        const IntPoint& a = piece[i];
        const IntPoint& b = piece[(i + 1) % n];
        const double mx = 0.5 * (a.X + b.X) / kScale, my = 0.5 * (a.Y + b.Y) / kScale;
        bool onBoundary = false;
        for (const Segment* s : near)
            if (dist2(mx, my, *s) <= tol * tol) {
                onBoundary = true;
                break;
            }
        off[i] = !onBoundary;
    }
    int runs = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (off[i] && !off[(i + n - 1) % n]) ++runs;
    if (runs == 0 && n > 0 && off[0]) runs = 1;  // the whole contour is off the boundary
    return runs;
}

void collectOuters(const PolyNode& node, std::vector<const PolyNode*>& out) {
    for (const PolyNode* c : node.Childs) {
        if (!c->IsHole()) out.push_back(c);
        collectOuters(*c, out);
    }
}

double holeArea(const PolyNode& outer) {
    double a = 0;
    for (const PolyNode* h : outer.Childs) a += std::fabs(Area(h->Contour));
    return a / (kScale * kScale);
}

// The erosion clipped to the boxes grown by `reach` mm: sweeping it by less than `reach`
// covers, within the boxes, what sweeping the whole erosion covers. With `orAll`, when the
// boxes cover much of the erosion's box (clipping would cost more than it saves), all of it.
Paths erosionNear(const Paths& eroded, const std::vector<Box>& boxes, double reach, bool orAll) {
    const double grow = reach * kScale;
    if (orAll) {
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        for (const Path& p : eroded)
            for (const IntPoint& q : p)
                x0 = std::min(x0, double(q.X)), y0 = std::min(y0, double(q.Y)), x1 = std::max(x1, double(q.X)),
                y1 = std::max(y1, double(q.Y));
        double covered = 0;
        for (const Box& b : boxes) covered += (b.x1 - b.x0 + 2 * reach) * (b.y1 - b.y0 + 2 * reach) * kScale * kScale;
        if (covered > 0.5 * (x1 - x0) * (y1 - y0)) return eroded;
    }
    Paths windows;
    for (const Box& b : boxes) {
        const cInt x0 = static_cast<cInt>(std::floor(b.x0 * kScale - grow)),
                   y0 = static_cast<cInt>(std::floor(b.y0 * kScale - grow)),
                   x1 = static_cast<cInt>(std::ceil(b.x1 * kScale + grow)),
                   y1 = static_cast<cInt>(std::ceil(b.y1 * kScale + grow));
        windows.push_back({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
    }
    Clipper c;
    c.AddPaths(eroded, ptSubject, true);
    c.AddPaths(windows, ptClip, true);
    Paths near;
    c.Execute(ctIntersection, near, pftNonZero, pftNonZero);
    return near;
}

}  // namespace

MachinableRatio machinableRatio(const PocketGeometry& pocket, double toolRadius) {
    const PocketRegion region = makeRegion(pocket);
    return machinableRatio(region, openRegion(region, toolRadius), toolRadius);
}

MachinableRatio machinableRatio(const PocketRegion& region, const Opening& o, double toolRadius) {
    MachinableRatio m;
    m.area = region.area;
    m.machinableArea = o.machinableArea;
    m.eta = m.machinableArea / m.area;
    if (m.eta >= 1 - 1e-12) return m;

    // Leftover pieces against an opening grown by eps, so the chord error along curved
    // walls leaves no hairline slivers to count.
    const double r = toolRadius, tol = arcToleranceFor(r), eps = 2 * tol + 1e-3;
    const double noise = 100 * eps * eps;
    // The opening grown by eps contains the opening (eps exceeds the equal-area radius's
    // excess plus a chord error), so the leftover lies in what the opening leaves, and a
    // piece of that no larger than the noise holds no piece that counts. Only the pieces
    // that are larger are cut again, and only the erosion near them is swept.
    std::vector<Box> boxes;
    PolyTree leftover;
    {
        Clipper c;
        for (const Opening::Piece& p : o.unreached)
            if (p.area > noise) {
                c.AddPath(p.outer, ptSubject, true);
                c.AddPaths(p.holes, ptSubject, true);
                boxes.push_back(boxOf(p.outer, 0));
            }
        if (boxes.empty()) return m;
        c.AddPaths(offsetRegion(erosionNear(o.eroded, boxes, r + eps + 4 * tol + 0.01, true), r + eps, tol), ptClip,
                   true);
        c.Execute(ctDifference, leftover, pftNonZero, pftNonZero);
    }
    std::vector<const PolyNode*> pieces;
    collectOuters(leftover, pieces);
    const std::vector<Segment> boundary = segmentsOf(region.paths);
    std::vector<const PolyNode*> undecided;
    for (const PolyNode* p : pieces) {
        if (std::fabs(Area(p->Contour)) / (kScale * kScale) - holeArea(*p) <= noise) continue;
        // A piece round an island means the tool cannot get round it.
        if (holeArea(*p) > noise || reachableSideRuns(p->Contour, boundary, 0.5 * eps) >= 2)
            ++m.narrowPassages;
        else undecided.push_back(p);
    }
    if (undecided.empty()) return m;

    // Material farther than r from the reachable region is no corner leftover (a corner
    // of angle θ leaves at most r(1/sin(θ/2) − 1), which is r at 60°): the parts of the
    // undecided pieces the erosion swept out by 2r does not cover. Only the erosion within
    // 2r of a piece can cover it, so only that part is swept: the erosion clipped to the
    // pieces' boxes grown by 2r and a margin beyond the arcs' chord error. The clip's own
    // new edges lie farther than 2r from every piece, so within the pieces the sweep is the
    // full erosion's.
    boxes.clear();
    for (const PolyNode* p : undecided) boxes.push_back(boxOf(p->Contour, 0));
    const Paths near = erosionNear(o.eroded, boxes, 2 * r + 4 * tol + 0.01, false);
    PolyTree far;
    {
        Clipper c;
        for (const PolyNode* p : undecided) {
            c.AddPath(p->Contour, ptSubject, true);
            for (const PolyNode* h : p->Childs) c.AddPath(h->Contour, ptSubject, true);
        }
        c.AddPaths(offsetRegionFast(near, 2 * r, tol), ptClip, true);
        c.Execute(ctDifference, far, pftNonZero, pftNonZero);
    }
    std::vector<const PolyNode*> farPieces;
    collectOuters(far, farPieces);
    std::vector<char> counted(undecided.size(), 0);
    for (const PolyNode* f : farPieces) {
        if (std::fabs(Area(f->Contour)) / (kScale * kScale) <= noise) continue;
        // The far part lies inside one leftover piece: the one holding most of its vertices.
        std::size_t best = undecided.size();
        int bestVotes = 0;
        for (std::size_t i = 0; i < undecided.size(); ++i) {
            int votes = 0;
            for (const IntPoint& q : f->Contour) votes += PointInPolygon(q, undecided[i]->Contour) != 0;
            if (votes > bestVotes) best = i, bestVotes = votes;
        }
        if (best < undecided.size() && !counted[best]) counted[best] = 1, ++m.narrowPassages;
    }
    return m;
}

}  // namespace aeronc::toolselect
