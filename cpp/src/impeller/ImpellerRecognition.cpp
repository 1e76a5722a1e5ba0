// Rule-based impeller recognition (impeller paper §1):
//   1. planes and holes (concave cylinders) are classified directly;
//   2. the axis and the blade count m come from the part's rotational symmetry: the turn by
//      2π/m about the axis takes points sampled on the faces back onto the part
//      (RotationalSymmetry.h); the faces it takes onto one another are the patterns. A face
//      without a copy a turn on means unequal blades;
//   3. the hub is the single face tangent to the root fillets: every member of some pattern;
//   4. the blade walls are the patterns tangent to the fillets, the shroud faces the patterns
//      that meet the walls;
//   5. each blade is a connected set of walls, fillets and one shroud; main and splitter blades
//      differ by shroud area, and the closest pair of shroud faces is an adjacent pair.
#include <aeronc/impeller/ImpellerFeatures.h>

#include "FaceGraph.h"
#include "RotationalSymmetry.h"

#include <aeronc/core/Error.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <GCPnts_AbscissaPoint.hxx>
#include <NCollection_IndexedDataMap.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <ElCLib.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Lin.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>

namespace aeronc::impeller {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSplitterShare = 0.1;
constexpr double kHubShare = 0.25;  // a hub face carries at least this share of the longest blade root a face carries
constexpr double kMeridianSine = 0.05;  // the normal of a face of revolution leaves its meridian plane by this much at most (an exporter's B-spline)   // a splitter's shroud is this much smaller than a main blade's at least (exported copies differ by 1 %)

struct Axis {
    gp_Pnt point;
    gp_Dir dir;
    double axial(const gp_Pnt& p) const { return gp_Vec(point, p).Dot(gp_Vec(dir)); }
    gp_Vec radial(const gp_Pnt& p) const {
        gp_Vec v(point, p);
        return v - gp_Vec(dir) * v.Dot(gp_Vec(dir));
    }
};

// Whether two faces share an edge running along dir (a ruling of a cylinder with that axis), as
// a root fillet meets its wall and hub; a bore meets its end rounds along circles instead.
bool meetAlongRuling(const TopoDS_Face& a, const TopoDS_Face& b, const gp_Dir& dir) {
    TopTools_IndexedMapOfShape edgesOfB;
    TopExp::MapShapes(b, TopAbs_EDGE, edgesOfB);
    for (TopExp_Explorer e(a, TopAbs_EDGE); e.More(); e.Next()) {
        if (!edgesOfB.Contains(e.Current())) continue;
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        if (BRep_Tool::Degenerated(edge)) continue;
        BRepAdaptor_Curve curve(edge);
        const gp_Vec chord(curve.Value(curve.FirstParameter()), curve.Value(curve.LastParameter()));
        if (chord.Magnitude() > 1e-6 && std::abs(chord.Normalized().Dot(gp_Vec(dir))) > 0.98) return true;
    }
    return false;
}

// A hole: a concave cylinder (its outward normal points towards its own axis) that is no blend.
bool isHole(const FaceGraph& g, int f) {
    if (g[f].type != GeomAbs_Cylinder) return false;
    BRepAdaptor_Surface s(g[f].face);
    const gp_Cylinder c = s.Cylinder();
    const Axis a{c.Location(), c.Axis().Direction()};
    // A point inside the parameter range (a full cylinder's centroid is on its axis).
    double u0, u1, v0, v1;
    BRepTools::UVBounds(g[f].face, u0, u1, v0, v1);
    gp_Pnt p;
    gp_Vec du, dv;
    s.D1(0.5 * (u0 + u1), 0.5 * (v0 + v1), p, du, dv);
    gp_Vec n = du.Crossed(dv);
    if (g[f].face.Orientation() == TopAbs_REVERSED) n.Reverse();
    const gp_Vec r = a.radial(p);
    if (r.Magnitude() <= 1e-9 || n.Dot(r) >= 0) return false;
    // A concave cylinder tangent to two faces along its rulings is a blend: a root fillet between
    // a plane wall and a plane hub (a straight blade on a pump's back plate), not a hole. A bore
    // meets its end rounds along circles, and pieces of the same cylinder (a bore an exporter
    // split at its seams) do not count.
    const auto& nbs = g.neighbours(f);
    return std::count_if(nbs.begin(), nbs.end(), [&](const Neighbour& nb) {
               if (!nb.tangent) return false;
               if (g[nb.face].type == GeomAbs_Cylinder) {
                   const gp_Cylinder o = BRepAdaptor_Surface(g[nb.face].face).Cylinder();
                   if (std::abs(o.Radius() - c.Radius()) <= 1e-6 && o.Axis().IsCoaxial(c.Axis(), 1e-6, 1e-6))
                       return false;
               }
               return meetAlongRuling(g[f].face, g[nb.face].face, c.Axis().Direction());
           }) < 2;
}

// Angle of p about the axis from a fixed reference direction, in [0, 2π).
double angleAbout(const Axis& a, const gp_Pnt& p) {
    gp_Dir ref = std::abs(a.dir.X()) < 0.9 ? gp_Dir(1, 0, 0) : gp_Dir(0, 1, 0);
    const gp_Vec x = gp_Vec(ref) - gp_Vec(a.dir) * gp_Vec(ref).Dot(gp_Vec(a.dir));
    const gp_Vec xn = x.Normalized(), yn = gp_Vec(a.dir).Crossed(xn);
    const gp_Vec r = a.radial(p);
    double t = std::atan2(r.Dot(yn), r.Dot(xn));
    return t < 0 ? t + 2 * kPi : t;
}

// The exact axis of a face of revolution (cylinder, cone, torus, sphere, swept), if it has one.
bool revolutionAxis(const FaceGraph& g, int f, gp_Ax1& ax) {
    BRepAdaptor_Surface s(g[f].face);
    switch (s.GetType()) {
        case GeomAbs_Cylinder: ax = s.Cylinder().Axis(); return true;
        case GeomAbs_Cone: ax = s.Cone().Axis(); return true;
        case GeomAbs_Torus: ax = s.Torus().Axis(); return true;
        case GeomAbs_Sphere: return false;
        case GeomAbs_SurfaceOfRevolution: ax = s.AxeOfRevolution(); return true;
        default: return false;
    }
}

double shapeDistance(const TopoDS_Shape& a, const TopoDS_Shape& b) {
    BRepExtrema_DistShapeShape d(a, b);
    if (!d.IsDone() || d.NbSolution() == 0) throw geometryError("impeller: distance between shroud faces failed");
    return d.Value();
}


// How far a face's normal turns round the axis: the largest and the mean |n . theta| over a grid
// of its points (theta the direction round the axis). 0 on a face of revolution about the axis
// (a hub, a turned tip, a plane across the axis), whatever its surface type (an exporter writes
// such faces as B-splines); near 1 on a blade's side wall.
struct NormalTurn {
    double largest = 0, mean = 0;
    bool known = false;
};

NormalTurn normalTurn(const FaceGraph& g, int f, const Axis& axis) {
    BRepAdaptor_Surface s(g[f].face);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(g[f].face, u0, u1, v0, v1);
    NormalTurn out;
    int tried = 0;
    for (int i = 1; i <= 5; ++i)
        for (int j = 1; j <= 5; ++j) {
            gp_Pnt p;
            gp_Vec du, dv;
            s.D1(u0 + (u1 - u0) * i / 6.0, v0 + (v1 - v0) * j / 6.0, p, du, dv);
            const gp_Vec n = du.Crossed(dv), r = axis.radial(p);
            if (n.Magnitude() < 1e-12 || r.Magnitude() < 1e-6) continue;
            const double t = std::abs(n.Normalized().Dot(gp_Vec(axis.dir).Crossed(r).Normalized()));
            out.largest = std::max(out.largest, t);
            out.mean += t;
            ++tried;
        }
    if (tried) out.mean /= tried, out.known = true;
    return out;
}

// The angle about the axis a face's boundary spans, radians (2π for a face all round).
double angularSpan(const FaceGraph& g, int f, const Axis& axis) {
    std::vector<double> t;
    for (TopExp_Explorer e(g[f].face, TopAbs_EDGE); e.More(); e.Next()) {
        if (BRep_Tool::Degenerated(TopoDS::Edge(e.Current()))) continue;
        BRepAdaptor_Curve c(TopoDS::Edge(e.Current()));
        for (int k = 0; k <= 16; ++k) {
            const gp_Pnt p = c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * k / 16.0);
            if (axis.radial(p).Magnitude() > 1e-6) t.push_back(angleAbout(axis, p));
        }
    }
    if (t.size() < 2) return 0;
    std::sort(t.begin(), t.end());
    double gap = t.front() + 2 * kPi - t.back();
    for (size_t k = 1; k < t.size(); ++k) gap = std::max(gap, t[k] - t[k - 1]);
    return 2 * kPi - gap;
}

bool coaxialCylinder(const FaceGraph& g, int f, const Axis& axis, double tol) {
    if (g[f].type != GeomAbs_Cylinder) return false;
    const gp_Cylinder c = BRepAdaptor_Surface(g[f].face).Cylinder();
    return c.Axis().Direction().IsParallel(axis.dir, 1e-3) && axis.radial(c.Location()).Magnitude() < tol;
}

// Blades standing straight on the hub, without root fillets, or on a hub of several faces (a
// piece per channel, as exporters write it): the hub is the faces of revolution about the axis
// that span at least half a blade pitch and meet the blade walls; a blade is a connected set of
// the faces left (faces of revolution spanning a whole channel, the rim and the back, are not
// blade faces). In a blade, faces not of revolution tangent to the hub are root fillets; faces whose normals run round the axis are walls, and so are coaxial cylinders (the
// blade's end turned with the rim); the others are its shroud (tip), flat or following the casing.
void bladesOnHub(const FaceGraph& g, const Axis& axis, int m, const std::set<int>& holeSet, double scale, double tol,
                 ImpellerFeatures& out) {
    const double pitch = 2 * kPi / m, minArea = 1e-4 * scale * scale;
    const int n = g.size();
    std::vector<char> usable(n + 1, 0), rev(n + 1, 0), wide(n + 1, 0), round(n + 1, 0);
    for (int f = 1; f <= n; ++f) {
        usable[f] = !holeSet.count(f) && g[f].area >= minArea;  // slivers along exported intersections do not count
        if (!usable[f]) continue;
        const NormalTurn t = normalTurn(g, f, axis);
        rev[f] = t.known && t.largest <= kMeridianSine;
        round[f] = t.known && t.mean >= 0.5;
        wide[f] = rev[f] && angularSpan(g, f, axis) > 0.5 * pitch;
    }
    // A flat tip of a blade wrapped round more than half a pitch spans as much as a hub piece, but
    // only its blade's walls bound it: a hub piece meets the rim, a nose or the back as well.
    for (int f = 1; f <= n; ++f) {
        if (!wide[f]) continue;
        const auto& nbs = g.neighbours(f);
        if (!nbs.empty() && std::none_of(nbs.begin(), nbs.end(), [&](const Neighbour& nb) { return usable[nb.face] && rev[nb.face]; }))
            wide[f] = 0;
    }
    // The length of boundary each wide face shares with blade faces (not of revolution): the hub
    // carries the blades' roots; the back, the rim and a nose meet at most a blade's end.
    NCollection_IndexedDataMap<TopoDS_Shape, std::vector<int>, TopTools_ShapeMapHasher> edgeFaces;
    for (int f = 1; f <= n; ++f)
        for (TopExp_Explorer e(g[f].face, TopAbs_EDGE); e.More(); e.Next()) {
            const int i = edgeFaces.FindIndex(e.Current());
            if (i) edgeFaces(i).push_back(f);
            else edgeFaces.Add(e.Current(), {f});
        }
    std::vector<double> rootLength(n + 1, 0);
    for (int i = 1; i <= edgeFaces.Extent(); ++i) {
        const auto& fs = edgeFaces(i);
        const bool byBlade = std::any_of(fs.begin(), fs.end(), [&](int f) { return usable[f] && !rev[f]; });
        if (!byBlade || BRep_Tool::Degenerated(TopoDS::Edge(edgeFaces.FindKey(i)))) continue;
        const double len = GCPnts_AbscissaPoint::Length(BRepAdaptor_Curve(TopoDS::Edge(edgeFaces.FindKey(i))));
        for (int f : std::set<int>(fs.begin(), fs.end()))
            if (wide[f]) rootLength[f] += len;
    }
    const double longest = *std::max_element(rootLength.begin(), rootLength.end());
    std::set<int> hub;
    for (int f = 1; f <= n; ++f)
        if (wide[f] && longest > 0 && rootLength[f] >= kHubShare * longest) hub.insert(f);
    out.hubFaces.assign(hub.begin(), hub.end());
    out.hub = *std::max_element(hub.begin(), hub.end(), [&](int a, int b) { return rootLength[a] < rootLength[b]; });

    std::vector<char> seen(n + 1, 0);
    for (int start = 1; start <= n; ++start) {
        if (seen[start] || !usable[start] || wide[start]) continue;
        std::vector<int> comp, stack{start};
        seen[start] = 1;
        while (!stack.empty()) {
            const int f = stack.back();
            stack.pop_back();
            comp.push_back(f);
            for (const auto& nb : g.neighbours(f))
                if (!seen[nb.face] && usable[nb.face] && !wide[nb.face]) seen[nb.face] = 1, stack.push_back(nb.face);
        }
        if (std::all_of(comp.begin(), comp.end(), [&](int f) { return rev[f]; })) continue;  // no wall: not a blade
        Blade b;
        for (int f : comp) {
            const bool onHub = !rev[f] && std::any_of(g.neighbours(f).begin(), g.neighbours(f).end(), [&](const Neighbour& nb) {
                return nb.tangent && hub.count(nb.face);
            });
            if (onHub) b.fillets.push_back(f);
            else if (round[f] || coaxialCylinder(g, f, axis, tol)) b.walls.push_back(f);
            else b.shroudFaces.push_back(f);
        }
        if (b.shroudFaces.empty())
            throw inputError("not an impeller: the blade with wall " + std::to_string(b.walls.empty() ? comp.front() : b.walls.front()) +
                             " has no shroud (tip) face");
        std::sort(b.walls.begin(), b.walls.end());
        std::sort(b.fillets.begin(), b.fillets.end());
        std::sort(b.shroudFaces.begin(), b.shroudFaces.end());
        b.shroud = *std::max_element(b.shroudFaces.begin(), b.shroudFaces.end(),
                                     [&](int x, int y) { return g[x].area < g[y].area; });
        out.blades.push_back(b);
    }
    if (out.blades.empty()) throw inputError("not an impeller: no blade walls stand on the hub");
    // The other faces of revolution round a channel (the rim between the blades): turned.
    for (int f = 1; f <= n; ++f)
        if (wide[f] && !hub.count(f) && g[f].type != GeomAbs_Plane) out.turned.push_back(f);
}
}  // namespace

ImpellerFeatures recogniseImpeller(const TopoDS_Shape& shape) {
    if (shape.IsNull()) throw inputError("not an impeller: the shape is empty");
    const FaceGraph g(shape);
    ImpellerFeatures out;
    out.faceCount = g.size();
    if (g.size() == 0) throw inputError("not an impeller: the shape has no faces");

    // Size of the part, for the tolerances of the pattern checks.
    double scale = 0;
    for (int f = 1; f <= g.size(); ++f) scale = std::max(scale, gp_Vec(g[1].centroid, g[f].centroid).Magnitude());
    const double tol = std::max(1e-3 * scale, 1e-3);

    // 1. Planes and holes.
    std::vector<int> rest, holes;
    for (int f = 1; f <= g.size(); ++f) {
        if (g[f].type == GeomAbs_Plane) out.planes.push_back(f);
        else if (isHole(g, f)) holes.push_back(f);
        else rest.push_back(f);
    }

    // 2. The axis and the blade count from the part's rotational symmetry; the orbits of faces
    // under it (a blade face and its copies on the other blades) are the patterns.
    const RotationalSymmetry sym = findRotationalSymmetry(shape, g, std::max(5e-3 * scale, 1e-3), 1e-4 * scale * scale);
    if (sym.order < 3)
        throw inputError("not an impeller: no rotational pattern (no axis about which a turn of 360/N degrees, "
                         "N >= 3, takes the part onto itself, other than faces of revolution)");
    const int m = sym.order;
    Axis axis{sym.axis.Location(), sym.axis.Direction()};
    {
        // Faces without a copy a turn on: a blade missing or different. Slivers an exporter
        // leaves along intersections do not count.
        std::vector<int> differ;
        for (int f : sym.unmatched)
            if (g[f].area > 1e-4 * scale * scale) differ.push_back(f);
        if (!differ.empty()) {
            std::ostringstream s;
            s << "unequal blade groups: the part repeats " << m << " times about its axis, but face";
            s << (differ.size() > 1 ? "s " : " ");
            for (size_t k = 0; k < differ.size() && k < 12; ++k)
                s << (k ? ", " : "") << differ[k] << " (at " << std::lround(angleAbout(axis, g[differ[k]].centroid) * 180 / kPi)
                  << " deg)";
            if (differ.size() > 12) s << " and " << differ.size() - 12 << " more";
            s << " have no copy " << std::setprecision(4) << 360.0 / m
              << " degrees on (a blade is missing or differs from the others)";
            throw inputError(s.str());
        }
    }
    // Planes across the axis (the back, a nose) are faces of revolution; a plane along it may be a
    // blade's wall (straight radial blades), so it stays in its pattern.
    std::set<int> holeSet(holes.begin(), holes.end()), planeSet;
    for (int f : out.planes)
        if (BRepAdaptor_Surface(g[f].face).Plane().Axis().Direction().IsParallel(axis.dir, 1e-3)) planeSet.insert(f);
    std::vector<std::vector<int>> groups;
    for (const auto& orbit : sym.orbits) {
        std::vector<int> grp;
        for (int f : orbit)
            if (!holeSet.count(f) && !planeSet.count(f)) grp.push_back(f);
        if (!grp.empty()) groups.push_back(std::move(grp));
    }
    std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    // The symmetry's axis is exact when a face of revolution gave it; a bore or a single face of
    // revolution on it gives it exactly when the axes of inertia did.
    std::vector<int> revolved = holes;
    for (const auto& grp : groups)
        if (grp.size() == 1) revolved.push_back(grp.front());
    for (int f : revolved) {
        gp_Ax1 exact;
        if (!revolutionAxis(g, f, exact) || !exact.Direction().IsParallel(axis.dir, 1e-3)) continue;
        const gp_Lin line(exact);
        if (line.Distance(axis.point) > tol) continue;
        const gp_Dir d = exact.Direction().Dot(axis.dir) < 0 ? exact.Direction().Reversed() : exact.Direction();
        axis = Axis{ElCLib::Value(ElCLib::Parameter(line, axis.point), line), d};
        break;
    }
    std::vector<const std::vector<int>*> patterns;
    for (const auto& grp : groups)
        if (static_cast<int>(grp.size()) >= m) patterns.push_back(&grp);
    if (patterns.empty())
        throw inputError("not an impeller: no rotational pattern (no faces repeat about the axis)");
    out.bladeCount = m;

    // 3. The hub: the single face tangent to every member of some pattern (the root fillets).
    std::vector<int> singles;
    for (const auto& grp : groups)
        if (grp.size() == 1) singles.push_back(grp.front());
    auto tangentToAll = [&](int f, const std::vector<int>& grp) {
        return std::all_of(grp.begin(), grp.end(), [&](int o) { return g.tangent(f, o); });
    };
    int bestCount = 0;
    for (int s : singles) {
        int n = 0;
        for (const auto* p : patterns) n += tangentToAll(s, *p);
        if (n > bestCount) bestCount = n, out.hub = s;
    }
    // No single face tangent to fillets, or no walls and shroud round them: blades standing
    // straight on the hub, or a hub of pieces (bladesOnHub).
    bool onFillets = out.hub != 0;
    std::set<int> fillets, walls, shrouds;
    if (onFillets) {
        out.hubFaces = {out.hub};

        // 4. Fillets, walls and shroud faces.
        std::vector<const std::vector<int>*> others;
        for (const auto* p : patterns) {
            if (tangentToAll(out.hub, *p)) fillets.insert(p->begin(), p->end());
            else others.push_back(p);
        }
        auto everyMember = [&](const std::vector<int>& grp, const std::set<int>& set, bool tangentOnly) {
            return std::all_of(grp.begin(), grp.end(), [&](int f) {
                for (const auto& n : g.neighbours(f))
                    if (set.count(n.face) && (n.tangent || !tangentOnly)) return true;
                return false;
            });
        };
        std::vector<const std::vector<int>*> remaining;
        for (const auto* p : others) {
            if (everyMember(*p, fillets, true)) walls.insert(p->begin(), p->end());
            else remaining.push_back(p);
        }
        // Walls also run tangentially into one another (side walls into edge rounds).
        for (bool grew = true; grew;) {
            grew = false;
            for (auto it = remaining.begin(); it != remaining.end();) {
                const bool touchesHub = std::any_of((*it)->begin(), (*it)->end(), [&](int f) { return g.adjacent(f, out.hub); });
                if (!touchesHub && everyMember(**it, walls, true)) {
                    walls.insert((*it)->begin(), (*it)->end());
                    it = remaining.erase(it);
                    grew = true;
                } else {
                    ++it;
                }
            }
        }
        for (const auto* p : remaining)
            if (everyMember(*p, walls, false)) shrouds.insert(p->begin(), p->end());
        onFillets = !walls.empty() && !shrouds.empty();
    }
    if (onFillets) {

        // 5. Blades: connected sets of walls, fillets and shroud faces.
        std::set<int> bladeFaces = fillets;
        bladeFaces.insert(walls.begin(), walls.end());
        bladeFaces.insert(shrouds.begin(), shrouds.end());
        std::set<int> seen;
        for (int start : shrouds) {
            if (seen.count(start)) continue;
            Blade b;
            std::vector<int> stack{start};
            seen.insert(start);
            while (!stack.empty()) {
                const int f = stack.back();
                stack.pop_back();
                if (shrouds.count(f)) {
                    if (b.shroud) throw inputError("unequal blade groups: a blade has two shroud faces (" +
                                                   std::to_string(b.shroud) + " and " + std::to_string(f) + ")");
                    b.shroud = f;
                } else if (walls.count(f)) {
                    b.walls.push_back(f);
                } else {
                    b.fillets.push_back(f);
                }
                for (const auto& n : g.neighbours(f))
                    if (bladeFaces.count(n.face) && !seen.count(n.face)) seen.insert(n.face), stack.push_back(n.face);
            }
            std::sort(b.walls.begin(), b.walls.end());
            std::sort(b.fillets.begin(), b.fillets.end());
            b.angleDeg = angleAbout(axis, g[b.shroud].centroid) * 180 / kPi;
            out.blades.push_back(b);
        }
        for (auto& b : out.blades) b.shroudFaces = {b.shroud};
    } else {
        out.hub = 0;
        out.hubFaces.clear();
        bladesOnHub(g, axis, m, holeSet, scale, tol, out);
    }

    // Main blades have the larger shroud.
    auto shroudArea = [&](const Blade& b) {
        double a = 0;
        for (int f : b.shroudFaces) a += g[f].area;
        return a;
    };
    double largest = 0;
    for (const auto& b : out.blades) largest = std::max(largest, shroudArea(b));
    int mains = 0;
    for (auto& b : out.blades) {
        b.splitter = shroudArea(b) < largest * (1 - kSplitterShare);
        mains += !b.splitter;
    }
    out.splitterCount = static_cast<int>(out.blades.size()) - mains;
    if (mains != m || (out.splitterCount != 0 && out.splitterCount != m))
        throw inputError("unequal blade groups: " + std::to_string(mains) + " main and " +
                         std::to_string(out.splitterCount) + " splitter blades where the face pattern repeats " +
                         std::to_string(m) + " times");

    // Axis direction: from the hub towards the shroud faces.
    double lift = 0;
    for (const auto& b : out.blades) lift += axis.axial(g[b.shroud].centroid) - axis.axial(g[out.hub].centroid);
    if (lift < 0) axis.dir.Reverse();
    out.axisPoint = {axis.point.X(), axis.point.Y(), axis.point.Z()};
    out.axisDirection = {axis.dir.X(), axis.dir.Y(), axis.dir.Z()};

    // Walls: the two largest are the sides, pressure facing the turning direction (+θ).
    for (auto& b : out.blades) {
        b.angleDeg = angleAbout(axis, g[b.shroud].centroid) * 180 / kPi;
        std::vector<int> byArea = b.walls;
        std::sort(byArea.begin(), byArea.end(), [&](int x, int y) { return g[x].area > g[y].area; });
        if (byArea.size() < 2) throw inputError("not an impeller: a blade has fewer than two walls");
        for (int k = 0; k < 2; ++k) {
            const int f = byArea[k];
            const gp_Pnt p = g[f].centroid;
            const gp_Vec theta = gp_Vec(axis.dir).Crossed(axis.radial(p));
            (gp_Vec(g.normalNear(f, p)).Dot(theta) > 0 ? b.pressure : b.suction) = f;
        }
        if (!b.pressure || !b.suction)
            throw inputError("not an impeller: the side walls of the blade with shroud face " + std::to_string(b.shroud) +
                             " do not face opposite ways about the axis");
        // Other walls are edge rounds: leading nearer the axis than the sides' middle, trailing beyond.
        const double rSides = 0.5 * (axis.radial(g[b.pressure].centroid).Magnitude() +
                                     axis.radial(g[b.suction].centroid).Magnitude());
        double rMin = rSides, rMax = rSides;
        for (size_t k = 2; k < byArea.size(); ++k) {
            const double r = axis.radial(g[byArea[k]].centroid).Magnitude();
            if (r < rMin) rMin = r, b.leading = byArea[k];
            if (r > rMax) rMax = r, b.trailing = byArea[k];
        }
    }
    // Angular order, starting at a main blade.
    std::sort(out.blades.begin(), out.blades.end(), [](const Blade& a, const Blade& b) { return a.angleDeg < b.angleDeg; });
    auto firstMain = std::find_if(out.blades.begin(), out.blades.end(), [](const Blade& b) { return !b.splitter; });
    std::rotate(out.blades.begin(), firstMain, out.blades.end());

    // Classification of what is left: the bore on the axis, other holes, faces of revolution.
    for (int h : holes) {
        BRepAdaptor_Surface s(g[h].face);
        const gp_Cylinder c = s.Cylinder();
        const bool onAxis = c.Axis().Direction().IsParallel(axis.dir, 1e-6) &&
                            axis.radial(c.Location()).Magnitude() < tol;
        if (onAxis && (out.bore == 0 || g[h].area > g[out.bore].area)) {
            if (out.bore) out.holes.push_back(out.bore);
            out.bore = h;
        } else {
            out.holes.push_back(h);
        }
    }
    std::set<int> claimed(out.hubFaces.begin(), out.hubFaces.end());
    for (const auto& b : out.blades) {
        claimed.insert(b.walls.begin(), b.walls.end());
        claimed.insert(b.fillets.begin(), b.fillets.end());
        claimed.insert(b.shroudFaces.begin(), b.shroudFaces.end());
    }
    for (int s : singles)
        if (!claimed.count(s) && std::find(out.turned.begin(), out.turned.end(), s) == out.turned.end()) out.turned.push_back(s);
    out.planes.erase(std::remove_if(out.planes.begin(), out.planes.end(), [&](int f) { return claimed.count(f) > 0; }),
                     out.planes.end());

    // The closest pair of shroud faces: blade 0 and its nearest neighbour.
    const int n = static_cast<int>(out.blades.size());
    double best = 1e300;
    int nearest = 1 % n;
    // The neighbours first; a face whose bounding box is already farther needs no query.
    auto box = [&](int j) {
        Bnd_Box b;
        BRepBndLib::Add(g[out.blades[j].shroud].face, b, false);
        return b;
    };
    const Bnd_Box first = box(0);
    std::vector<int> order{1};
    if (n - 1 > 1) order.push_back(n - 1);
    for (int j = 2; j < n - 1; ++j) order.push_back(j);
    for (int j : order) {
        if (first.Distance(box(j)) >= best) continue;
        const double d = shapeDistance(g[out.blades[0].shroud].face, g[out.blades[j].shroud].face);
        if (d < best) best = d, nearest = j;
    }
    if (nearest != 1 && nearest != n - 1)
        throw geometryError("impeller: the shroud face nearest to blade 0's is not on an adjacent blade");
    out.closestPair[0] = nearest == 1 ? 0 : n - 1;
    out.closestPair[1] = nearest == 1 ? 1 : 0;
    out.closestShroudDistance = best;
    return out;
}

}  // namespace aeronc::impeller
