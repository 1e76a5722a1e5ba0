#include <aeronc/toolpath/Profile.h>

#include "Arcs.h"
#include "Clip.h"
#include "MoveWriter.h"
#include "Validate.h"

#include <aeronc/toolpath/FloorFillet.h>

#include <aeronc/core/Error.h>
#include <aeronc/toolpath/Levels.h>

#include <algorithm>
#include <map>
#include <cmath>

namespace aeronc::toolpath {

namespace {

using Polyline = std::vector<Point>;

double cross(const Point& a, const Point& b) { return a[0] * b[1] - a[1] * b[0]; }
Point sub(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1]}; }
Point unit(const Point& v) {
    const double l = std::hypot(v[0], v[1]);
    return l > 0 ? Point{v[0] / l, v[1] / l} : Point{1, 0};
}

// Where p projects onto the polyline: the segment, the parameter on it, the arc length.
struct Projection {
    std::size_t segment = 0;
    double t = 0, along = 0, distance = 0;
    Point at{};
};
Projection project(const Polyline& line, const Point& p) {
    Projection best;
    best.distance = 1e300;
    double along = 0;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) {
        const Point d = sub(line[i + 1], line[i]);
        const double l2 = d[0] * d[0] + d[1] * d[1];
        const double t = l2 > 0 ? ((p[0] - line[i][0]) * d[0] + (p[1] - line[i][1]) * d[1]) / l2 : 0;
        const double tc = std::clamp(t, 0.0, 1.0);
        const Point q{line[i][0] + tc * d[0], line[i][1] + tc * d[1]};
        const double dist = clip::distance(p, q);
        if (dist < best.distance) best = {i, t, along + tc * std::sqrt(l2), dist, q};
        along += std::sqrt(l2);
    }
    return best;
}

Polyline checkedPolyline(const Loop& in) {
    Polyline l;
    for (const Point& p : in) {
        requireFinite(p[0], "the drive's coordinate");
        requireFinite(p[1], "the drive's coordinate");
        if (l.empty() || clip::distance(p, l.back()) > 1e-9) l.push_back(p);
    }
    if (l.size() < 2) throw inputError("the drive needs at least 2 distinct points");
    for (std::size_t i = 0; i + 1 < l.size(); ++i)
        for (std::size_t j = i + 2; j + 1 < l.size(); ++j) {
            const Point &a = l[i], &b = l[i + 1], &c = l[j], &d = l[j + 1];
            const double d1 = cross(sub(b, a), sub(c, a)), d2 = cross(sub(b, a), sub(d, a));
            const double d3 = cross(sub(d, c), sub(a, c)), d4 = cross(sub(d, c), sub(b, c));
            if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
                throw inputError("the drive crosses itself");
        }
    return l;
}

// The drive between the points nearest the limits.
Polyline trimmed(const Polyline& drive, const std::optional<Point>& from, const std::optional<Point>& to) {
    if (!from && !to) return drive;
    const Projection a = from ? project(drive, *from) : Projection{0, 0, 0, 0, drive.front()};
    const Projection b = to ? project(drive, *to) : project(drive, drive.back());
    if (!(a.along < b.along - 1e-6)) throw inputError("the start limit must come before the end limit along the drive");
    Polyline out{a.at};
    for (std::size_t i = a.segment + 1; i <= b.segment; ++i)
        if (clip::distance(drive[i], out.back()) > 1e-9) out.push_back(drive[i]);
    if (clip::distance(b.at, out.back()) > 1e-9) out.push_back(b.at);
    if (out.size() < 2) throw inputError("the limits leave nothing of the drive");
    return out;
}

// The tool-centre path of an open drive at distance d on its left (side +1) or right (-1),
// in the drive's direction: the longest run of that side's vertices on the boundary of the
// drive's butt-ended offset.
Polyline sideOffset(const Polyline& drive, double d, int side, double tol) {
    ClipperLib::ClipperOffset off(2.0, clip::arcTolerance(tol));
    clip::Path dp;
    for (const Point& p : drive) dp.push_back(clip::toInt(p));
    off.AddPath(dp, ClipperLib::jtRound, ClipperLib::etOpenButt);
    clip::Paths band;
    off.Execute(band, d * clip::kScale);
    Polyline best;
    for (const auto& path : band) {
        const std::size_t n = path.size();
        std::vector<int> sideOf(n);
        for (std::size_t i = 0; i < n; ++i) {
            const Point p = clip::toPoint(path[i]);
            const Projection pr = project(drive, p);
            // Every point of the band's outline but those on its butt ends lies at d from the
            // drive; a vertex nearer lies on an end (where the band meets itself) and would take
            // the cutter over the drive's end into what lies beyond it.
            const bool beyond = (pr.segment == 0 && pr.t < -1e-6) || (pr.segment + 2 == drive.size() && pr.t > 1 + 1e-6) ||
                                pr.distance < d - tol;
            const double c = cross(sub(drive[pr.segment + 1], drive[pr.segment]), sub(p, pr.at));
            sideOf[i] = beyond ? 0 : (c > 0 ? 1 : c < 0 ? -1 : 0);
        }
        std::size_t start = 0;
        while (start < n && sideOf[start] == side) ++start;
        if (start == n) continue;  // all on one side: a closed hole, not a side of the drive
        for (std::size_t k = 0; k < n;) {
            std::size_t i = (start + k) % n;
            if (sideOf[i] != side) {
                ++k;
                continue;
            }
            Polyline run;
            while (k < n && sideOf[(start + k) % n] == side) run.push_back(clip::toPoint(path[(start + k) % n])), ++k;
            if (clip::length(run) > clip::length(best)) best = std::move(run);
        }
    }
    if (best.size() < 2) throw inputError("the cutter finds no room along the drive");
    if (project(drive, best.front()).along > project(drive, best.back()).along) std::reverse(best.begin(), best.end());
    return best;
}

struct Cut {
    Polyline path;  // closed loops end where they start
    Polyline leadIn, leadOut;
};

class Leads {
public:
    Leads(const Polyline& drive, bool closed, ToolSide side, double d, const ProfileParameters& p,
          const std::vector<Polyline>& clearOf)
        : drive_(drive), closed_(closed), side_(side), d_(d), p_(p), clearOf_(clearOf) {
        if (closed) {
            region_ = {clip::toPath(drive)};
            if (!ClipperLib::Orientation(region_[0])) ClipperLib::ReversePath(region_[0]);  // for contains()
        }
    }

    void add(Cut& c, double radius) const {
        for (double r = radius; r >= radius / 8 && p_.lead != Lead::None; r /= 2) {
            Polyline in = lead(c.path, true, r), out = lead(c.path, false, r);
            if (clear(in) && clear(out)) {
                c.leadIn = std::move(in), c.leadOut = std::move(out);
                return;
            }
        }
    }

private:
    // Lead-in (ending at the path's start) or lead-out (starting at its end), away from the wall.
    Polyline lead(const Polyline& path, bool in, double r) const {
        const Point s = in ? path.front() : path.back();
        const Point t = in ? unit(sub(path[1], path[0])) : unit(sub(path.back(), path[path.size() - 2]));
        const Point foot = closed_ ? clip::nearestOnLoop(drive_, s).at : project(drive_, s).at;
        const Point n = unit(sub(s, foot));
        if (p_.lead == Lead::Line)
            return in ? Polyline{{s[0] - r * t[0], s[1] - r * t[1]}, s} : Polyline{s, {s[0] + r * t[0], s[1] + r * t[1]}};
        const Point o{s[0] + r * n[0], s[1] + r * n[1]};
        const double sense = cross(sub(s, o), t) > 0 ? 1 : -1;  // counter-clockwise at s
        const double as = std::atan2(s[1] - o[1], s[0] - o[0]);
        const std::size_t m = arcSegments(r, M_PI / 2, p_.chordTolerance);
        Polyline arc;
        for (std::size_t i = 0; i <= m; ++i) {
            const double f = double(i) / m;
            arc.push_back(onCircle(o, r, in ? as - sense * (M_PI / 2) * (1 - f) : as + sense * (M_PI / 2) * f));
        }
        if (in) arc.back() = s;
        else arc.front() = s;
        return arc;
    }

    // No point of the lead nearer the drive than the path, nor on the part's side. Within the
    // chord tolerance only: the lead's points lie on its arc, and any more would take the
    // cutter into the allowance of a wall across a narrow slot.
    bool clear(const Polyline& lead) const {
        const double tol = p_.chordTolerance;
        for (const Point& q : lead) {
            const double dist = closed_ ? clip::nearestOnLoop(drive_, q).distance : project(drive_, q).distance;
            if (dist < d_ - tol) return false;
            if (closed_ && (clip::contains(region_, q) != (side_ == ToolSide::Inside)) && dist > tol) return false;
            for (const Polyline& wall : clearOf_)
                if (project(wall, q).distance < d_ - tol) return false;
        }
        return true;
    }

    const Polyline& drive_;
    bool closed_;
    ToolSide side_;
    double d_;
    const ProfileParameters& p_;
    const std::vector<Polyline>& clearOf_;
    clip::Paths region_;
};

// The stretches of a path (closed: ending where it starts) that keep at least `keep` from every
// polyline of clearOf: the cutter runs along a wall only where it fits beside the element's
// other walls. Segments are split where the distance (1-Lipschitz along them) could dip below.
std::vector<Polyline> clearStretches(const Polyline& path, const std::vector<Polyline>& clearOf, double keep) {
    if (clearOf.empty() || path.size() < 2) return {path};
    auto clearance = [&](const Point& q) {
        double d = 1e300;
        for (const Polyline& wall : clearOf) d = std::min(d, project(wall, q).distance);
        return d;
    };
    std::vector<Point> pts;
    std::vector<bool> good;
    auto add = [&](const Point& q, double c) { pts.push_back(q), good.push_back(c >= keep); };
    double ca = clearance(path[0]);
    add(path[0], ca);
    for (std::size_t i = 1; i < path.size(); ++i) {
        const Point a = path[i - 1], b = path[i];
        const double cb = clearance(b);
        const double len = clip::distance(a, b);
        // Nowhere below keep between a and b when (ca + cb - len) / 2 >= keep.
        if ((ca + cb - len) / 2 < keep && len > 0.05) {
            const int n = int(std::ceil(len / 0.05));
            for (int k = 1; k < n; ++k) {
                const Point q{a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n};
                add(q, clearance(q));
            }
        }
        add(b, cb);
        ca = cb;
    }
    if (std::all_of(good.begin(), good.end(), [](bool g) { return g; })) return {path};
    const bool closed = clip::distance(path.front(), path.back()) < 1e-9;
    std::size_t start = 0;
    if (closed) {
        pts.pop_back(), good.pop_back();  // the closing point is the first one
        while (good[start]) ++start;      // from a point in the way, round again to it
    }
    std::vector<Polyline> out;
    Polyline run;
    const std::size_t n = pts.size();
    for (std::size_t k = 0; k <= n; ++k) {
        const std::size_t j = closed ? (start + k) % n : k;
        if (k < n && good[j]) {
            run.push_back(pts[j]);
            continue;
        }
        if (run.size() >= 2) out.push_back(run);
        run.clear();
        if (!closed && k >= n) break;
        if (closed && k == n) break;
    }
    return out;
}

// A closed loop as a path from the middle of its longest edge round to there again.
Polyline fromLongestEdge(const Loop& loop) {
    std::size_t longest = 0;
    const std::size_t n = loop.size();
    for (std::size_t i = 1; i < n; ++i)
        if (clip::distance(loop[i], loop[(i + 1) % n]) > clip::distance(loop[longest], loop[(longest + 1) % n])) longest = i;
    const Point& a = loop[longest];
    const Point& b = loop[(longest + 1) % n];
    return clip::loopFrom(loop, {{(a[0] + b[0]) / 2, (a[1] + b[1]) / 2}, longest, 0});
}

}  // namespace

Toolpath profile(const ProfileUnit& unit, const Cutter& cutter, const ProfileParameters& p) {
    checkMilling(p, cutter, unit.top, unit.bottom);
    const double R = cutter.radius(), d0 = R + p.radialAllowance, tol = p.chordTolerance;
    const double leadRadius = p.leadRadius ? *p.leadRadius : R;
    requireFinite(leadRadius, "leadRadius");
    if (!(leadRadius > 0)) throw inputError("leadRadius must be positive");
    requireFinite(unit.floorFilletRadius, "floorFilletRadius");
    Polyline drive;
    ToolSide side = p.side;
    if (unit.closed) {
        if (unit.startLimit || unit.endLimit) throw inputError("start and end limits need an open drive");
        drive = checkedLoop(unit.drive, "the drive");
        const bool ccw = clip::signedArea(drive) > 0;
        if (side == ToolSide::Left) side = ccw ? ToolSide::Inside : ToolSide::Outside;
        if (side == ToolSide::Right) side = ccw ? ToolSide::Outside : ToolSide::Inside;
    } else {
        if (side == ToolSide::Outside || side == ToolSide::Inside)
            throw inputError("an open drive takes the side left or right");
        drive = trimmed(checkedPolyline(unit.drive), unit.startLimit, unit.endLimit);
    }
    // The cuts with the tool's axis at d from the drive.
    auto cutsAt = [&](double d) {
        std::vector<Cut> cuts;
        if (unit.closed) {
            clip::Paths region{clip::toPath(drive)};
            if (!ClipperLib::Orientation(region[0])) ClipperLib::ReversePath(region[0]);
            // Round a convex corner the floor fillets meet in a mitre (Clip.h).
            const double by = side == ToolSide::Outside ? d : -d;
            const clip::Paths centres = unit.floorFilletRadius > 0 ? clip::offsetMitred(region, by, tol)
                                                                   : clip::offset(region, by, tol);
            if (centres.empty()) throw inputError("the cutter does not fit inside the drive");
            for (const auto& path : centres) {
                Loop l = clip::toLoop(path);
                // Clipper's orientation keeps the part on the left outside the loop and on the right
                // inside it: climb milling (part on the left) as is outside, reversed inside.
                if ((side == ToolSide::Inside) == p.climb) std::reverse(l.begin(), l.end());
                cuts.push_back({fromLongestEdge(l), {}, {}});
            }
        } else {
            Polyline path = sideOffset(drive, d, side == ToolSide::Left ? 1 : -1, tol);
            // The part lies opposite the cutter: on the left of travel (climb) when the cutter runs right.
            if ((side == ToolSide::Left) == p.climb) std::reverse(path.begin(), path.end());
            cuts.push_back({path, {}, {}});
        }
        // Where the element's other walls leave the cutter no room, the pass is broken off.
        if (!unit.clearOf.empty()) {
            std::vector<Cut> kept;
            for (const Cut& c : cuts)
                for (Polyline& piece : clearStretches(c.path, unit.clearOf, d - tol)) kept.push_back({piece, {}, {}});
            cuts = std::move(kept);
        }
        const Leads leads(drive, unit.closed, side, d, p, unit.clearOf);
        for (Cut& c : cuts) leads.add(c, leadRadius);
        return cuts;
    };

    const double floorLevel = unit.bottom + p.axialAllowance;
    const std::vector<double> levels = cuttingLevels(unit.top, floorLevel, p.stepDown);
    // Near the floor a fillet holds the cutter off the wall by more: cuts per offset, computed once.
    std::map<long long, std::vector<Cut>> byOffset;
    std::vector<const std::vector<Cut>*> cutsOfLevel;
    for (double level : levels) {
        const double e = wallFilletOffset(unit.floorFilletRadius, cutter.cornerRadius, p.radialAllowance,
                                          level - floorLevel);
        const long long key = std::llround(e * 1e6);
        auto it = byOffset.find(key);
        if (it == byOffset.end()) it = byOffset.emplace(key, cutsAt(d0 + e)).first;
        cutsOfLevel.push_back(&it->second);
    }
    const Heights hs = heightsOf(p, unit.top);
    const double approach = std::min(p.clearance, 1.0);
    Toolpath tp;
    MoveWriter w(tp);
    const Cut* c0 = nullptr;
    for (const auto* cuts : cutsOfLevel)
        if (!cuts->empty()) {
            c0 = &cuts->front();
            break;
        }
    if (!c0) throw inputError("the cutter finds no room along the wall beside the element's other walls");
    const Point& first = c0->leadIn.empty() ? c0->path.front() : c0->leadIn.front();
    w.rapid(first[0], first[1], hs.safe);
    for (std::size_t i = 0; i < levels.size(); ++i)
        for (const Cut& c : *cutsOfLevel[i]) {
            const Point& a = c.leadIn.empty() ? c.path.front() : c.leadIn.front();
            w.rapidOver(a, hs.clearance, (i == 0 ? entryTop(p, unit.top) : levels[i - 1]) + approach);
            w.plunge(a[0], a[1], levels[i]);
            for (const Point& q : c.leadIn) w.feed(q, levels[i]);
            for (const Point& q : c.path) w.feed(q, levels[i]);
            for (const Point& q : c.leadOut) w.feed(q, levels[i]);
        }
    w.retract(hs.safe);
    return tp;
}

}  // namespace aeronc::toolpath
