// Rule-based impeller recognition (impeller paper §1):
//   1. planes and holes (concave cylinders) are classified directly;
//   2. the other faces are grouped by equal area; a group whose members are copies of one
//      another about one axis is a pattern, and the axis is fitted to the largest group's
//      centroids. Every blade face repeats once per blade, so the smallest pattern is m, the
//      blade count; a group of 2m holds faces that main and splitter blades share (congruent
//      trailing edges). A group of any other size, or not evenly spaced, means unequal blades;
//   3. the hub is the single face tangent to the root fillets: every member of some pattern;
//   4. the blade walls are the patterns tangent to the fillets, the shroud faces the patterns
//      that meet the walls;
//   5. each blade is a connected set of walls, fillets and one shroud; main and splitter blades
//      differ by shroud area, and the closest pair of shroud faces is an adjacent pair.
#include <aeronc/impeller/ImpellerFeatures.h>

#include "FaceGraph.h"

#include <aeronc/core/Error.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <BRepTools.hxx>
#include <TopExp_Explorer.hxx>
#include <ElCLib.hxx>
#include <gp_Cylinder.hxx>
#include <gp_Lin.hxx>
#include <gp_Vec.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace aeronc::impeller {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kAreaTolerance = 2e-3;     // relative: copies differ by OCCT's approximations only
constexpr double kAngleTolerance = 0.01;    // rad, spacing of pattern members

struct Axis {
    gp_Pnt point;
    gp_Dir dir;
    double axial(const gp_Pnt& p) const { return gp_Vec(point, p).Dot(gp_Vec(dir)); }
    gp_Vec radial(const gp_Pnt& p) const {
        gp_Vec v(point, p);
        return v - gp_Vec(dir) * v.Dot(gp_Vec(dir));
    }
};

std::string joinSizes(const std::set<int>& sizes) {
    std::ostringstream s;
    int k = 0;
    for (int n : sizes) s << (k++ ? ", " : "") << n;
    return s.str();
}

// A concave cylinder: its outward normal points towards its own axis.
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
    return r.Magnitude() > 1e-9 && n.Dot(r) < 0;
}

// Splits `faces` (sorted by key) where two neighbours' keys differ by more than tol.
template <class Key>
std::vector<std::vector<int>> splitSorted(std::vector<int> faces, Key key, double tol) {
    std::sort(faces.begin(), faces.end(), [&](int a, int b) { return key(a) < key(b); });
    std::vector<std::vector<int>> out;
    for (int f : faces) {
        if (out.empty() || key(f) - key(out.back().back()) > tol) out.push_back({});
        out.back().push_back(f);
    }
    return out;
}

// Groups of faces of the same surface type and equal area, largest first. Copies of a face
// differ in area by OCCT's approximations (a fillet up to 0.1 %), while distinct faces of a blade
// can come as close (edge rounds of equal height); so a group is also split by the distance of
// its faces' centroids from the centroid of the whole boundary, which lies on the axis of any
// rotational pattern and is the same for every copy.
std::vector<std::vector<int>> groupByArea(const FaceGraph& g, const std::vector<int>& faces, double distTol) {
    gp_XYZ c(0, 0, 0);
    double total = 0;
    for (int f = 1; f <= g.size(); ++f) c += g[f].centroid.XYZ() * g[f].area, total += g[f].area;
    const gp_Pnt centre(total > 0 ? c / total : c);
    std::vector<std::vector<int>> groups;
    for (const auto& byType : splitSorted(faces, [&](int f) { return static_cast<double>(g[f].type); }, 0.5)) {
        double largest = 0;
        for (int f : byType) largest = std::max(largest, g[f].area);
        auto logArea = [&](int f) { return std::log(std::max(g[f].area, 1e-12)); };
        for (const auto& byArea : splitSorted(byType, logArea, kAreaTolerance))
            for (auto& grp : splitSorted(byArea, [&](int f) { return g[f].centroid.Distance(centre); }, distTol))
                groups.push_back(std::move(grp));
    }
    std::stable_sort(groups.begin(), groups.end(), [](const auto& a, const auto& b) { return a.size() > b.size(); });
    return groups;
}

// The axis through the centroids of a group, when they lie on one circle (the circle through
// three of them far apart).
bool fitAxis(const FaceGraph& g, const std::vector<int>& group, double tol, Axis& out) {
    const gp_Pnt p0 = g[group[0]].centroid;
    gp_Pnt p1 = p0, p2 = p0;
    for (int f : group)
        if (g[f].centroid.Distance(p0) > p1.Distance(p0)) p1 = g[f].centroid;
    double bestArea = 0;
    for (int f : group) {
        const double a = gp_Vec(p0, p1).Crossed(gp_Vec(p0, g[f].centroid)).Magnitude();
        if (a > bestArea) bestArea = a, p2 = g[f].centroid;
    }
    if (p1.Distance(p0) < tol || bestArea < tol * p1.Distance(p0)) return false;
    // Circumcentre of p0, p1, p2.
    const gp_Vec a(p0, p1), b(p0, p2), n = a.Crossed(b);
    const gp_Vec toCentre = (n.Crossed(a) * b.SquareMagnitude() + b.Crossed(n) * a.SquareMagnitude()) /
                            (2 * n.SquareMagnitude());
    out = Axis{p0.Translated(toCentre), gp_Dir(n)};
    const double r0 = toCentre.Magnitude();
    for (int f : group) {
        if (std::abs(out.axial(g[f].centroid)) > tol) return false;
        if (std::abs(out.radial(g[f].centroid).Magnitude() - r0) > tol) return false;
    }
    return true;
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

// Whether the group's centroids are on the axis circle, evenly spaced.
bool evenlySpaced(const FaceGraph& g, const Axis& a, const std::vector<int>& group, double tol) {
    const double r0 = a.radial(g[group[0]].centroid).Magnitude();
    const double z0 = a.axial(g[group[0]].centroid);
    if (r0 < tol) return false;
    std::vector<double> angles;
    for (int f : group) {
        if (std::abs(a.radial(g[f].centroid).Magnitude() - r0) > tol || std::abs(a.axial(g[f].centroid) - z0) > tol)
            return false;
        angles.push_back(angleAbout(a, g[f].centroid));
    }
    std::sort(angles.begin(), angles.end());
    const double step = 2 * kPi / group.size();
    for (size_t i = 0; i < angles.size(); ++i) {
        const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + 2 * kPi;
        if (std::abs(next - angles[i] - step) > kAngleTolerance) return false;
    }
    return true;
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

    // 2. Groups of equal area, the axis and the blade count.
    const auto groups = groupByArea(g, rest, 0.02 * scale);
    if (groups.empty() || groups.front().size() < 3)
        throw inputError("not an impeller: no rotational pattern (no face area occurs three or more times)");
    Axis axis;
    bool found = false;
    for (const auto& grp : groups) {  // the largest groups (a blade face on every blade)
        if (grp.size() < groups.front().size()) break;
        if ((found = fitAxis(g, grp, tol, axis))) break;
    }
    if (!found)
        throw inputError("not an impeller: no rotational pattern (the " + std::to_string(groups.front().size()) +
                         " faces of equal area that occur most often are not copies of one another about an axis)");
    // The centroids give the axis to OCCT's approximation; a bore or a single face of revolution
    // on it gives it exactly.
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
    std::set<int> sizes, unevenSizes;
    for (const auto& grp : groups) {
        if (grp.size() < 2) continue;
        sizes.insert(static_cast<int>(grp.size()));
        if (grp.size() >= 3 && evenlySpaced(g, axis, grp, tol)) patterns.push_back(&grp);
        else unevenSizes.insert(static_cast<int>(grp.size()));
    }
    if (patterns.empty())
        throw inputError("not an impeller: no rotational pattern (no faces of equal area evenly spaced about the axis)");
    int m = static_cast<int>(patterns.front()->size());
    for (const auto* p : patterns) m = std::min(m, static_cast<int>(p->size()));
    bool equal = unevenSizes.empty();
    for (int n : sizes) equal = equal && n % m == 0;
    if (!equal)
        throw inputError("unequal blade groups: faces of equal area occur " + joinSizes(sizes) +
                         " times; with " + std::to_string(m) +
                         " blades every blade face must occur a multiple of " + std::to_string(m) +
                         " times, evenly spaced about the axis (a blade is missing or differs from the others)");
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
    if (out.hub == 0)
        throw inputError("missing hub: no single face is tangent to a group of " + std::to_string(m) +
                         " root fillets (an impeller has a hub of revolution with its blades standing on it, "
                         "joined by root fillets)");

    // 4. Fillets, walls and shroud faces.
    std::set<int> fillets, walls, shrouds;
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
    if (walls.empty()) throw inputError("not an impeller: no blade walls run into the root fillets");
    if (shrouds.empty()) throw inputError("not an impeller: the blades have no shroud (tip) faces");

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
    // Main blades have the larger shroud.
    double largest = 0;
    for (const auto& b : out.blades) largest = std::max(largest, g[b.shroud].area);
    int mains = 0;
    for (auto& b : out.blades) {
        b.splitter = g[b.shroud].area < largest * (1 - kAreaTolerance);
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
    for (int s : singles)
        if (s != out.hub) out.turned.push_back(s);

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
