// Rotational symmetry by sample points: the candidate axes are those of the faces of revolution
// (largest total area first) and the solid's axes of inertia through its centroid; the order is
// the largest N whose turn takes the samples of the faces that are not of revolution about the
// axis back onto the boundary; the orbits link each face to the faces most of its turned samples
// land on.
#include "RotationalSymmetry.h"

#include "FaceProperties.h"

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <Poly_Triangulation.hxx>
#include <TopLoc_Location.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GProp_GProps.hxx>
#include <GProp_PrincipalProps.hxx>
#include <Geom_Surface.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <gp_Lin.hxx>
#include <gp_Trsf.hxx>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <atomic>
#include <memory>
#include <thread>
#include <unordered_map>

namespace aeronc::impeller {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxOrder = 64;
constexpr double kOrderShare = 0.9;   // share of turned samples that must land on the part
constexpr double kOrbitShare = 0.25;  // share of a face's turned samples that links it to a face

// The distance from p to the surface near uv, by damped Gauss-Newton steps from uv (no global
// search: a point far from the guess is far from the face anyway). uv becomes the foot point.
double localDistance(const GeomAdaptor_Surface& s, gp_Pnt2d& uv, const gp_Pnt& p) {
    double u = uv.X(), v = uv.Y();
    const double ulo = std::min(s.FirstUParameter(), s.LastUParameter()), uhi = std::max(s.FirstUParameter(), s.LastUParameter());
    const double vlo = std::min(s.FirstVParameter(), s.LastVParameter()), vhi = std::max(s.FirstVParameter(), s.LastVParameter());
    double d = s.Value(u, v).Distance(p);
    for (int it = 0; it < 16 && d > 0; ++it) {
        gp_Pnt q;
        gp_Vec du, dv;
        s.D1(u, v, q, du, dv);
        const gp_Vec r(q, p);
        const double a = du.Dot(du), b = du.Dot(dv), c = dv.Dot(dv), ru = du.Dot(r), rv = dv.Dot(r);
        const double det = a * c - b * b;
        if (det <= 1e-30 * (a * c + 1e-300)) break;
        double su = (c * ru - b * rv) / det, sv = (a * rv - b * ru) / det;
        // Damped: a step that does not bring the foot point nearer is halved (B-spline surfaces
        // of uneven parametrisation throw the plain step far off).
        bool better = false;
        for (int half = 0; half < 12 && !better; ++half, su *= 0.5, sv *= 0.5) {
            const double un = std::clamp(u + su, ulo, uhi), vn = std::clamp(v + sv, vlo, vhi);
            const double dn = s.Value(un, vn).Distance(p);
            if (dn < d) u = un, v = vn, d = dn, better = true;
        }
        if (!better) break;
    }
    uv.SetCoord(u, v);
    return d;
}

struct Sample {
    gp_Pnt p;
    gp_Pnt2d uv;
    int face;  // 1-based
};

// The samples of the part's faces on a grid over each face's parameter range, kept where the
// grid point is inside the face; about `spacing` apart on a face of even parametrisation.
class SampleCloud {
public:
    SampleCloud(const FaceGraph& g, double spacing) : g_(g), spacing_(spacing), cell_(2 * spacing) {
        surfaces_.resize(g.size() + 1);
        perFace_.resize(g.size() + 1);
        std::vector<std::vector<Sample>> found(g.size() + 1);
        for (int f = 1; f <= g.size(); ++f) surfaces_[f] = GeomAdaptor_Surface(BRep_Tool::Surface(g[f].face));
        // Faces are sampled independently: two threads take the next face in turn.
        std::atomic<int> next{1};
        auto work = [&] {
            for (int f; (f = next++) <= g.size();) found[f] = sampleFace(f);
        };
        std::thread second(work);
        work();
        second.join();
        // A face the grid found (almost) nothing inside, though it has area (a piece of a
        // periodic surface across its seam, where the classifier and the parameter bounds do not
        // agree): its mesh nodes instead. Meshing writes to edges that faces share: one at a time.
        for (int f = 1; f <= g.size(); ++f)
            if (found[f].size() < 0.125 * g[f].area / (spacing * spacing)) {
                auto nodes = meshSamples(f);
                if (nodes.size() > found[f].size()) found[f] = std::move(nodes);
            }
        for (int f = 1; f <= g.size(); ++f)
            for (const Sample& x : found[f]) {
                perFace_[f].push_back(static_cast<int>(samples_.size()));
                samples_.push_back(x);
            }
        for (int i = 0; i < static_cast<int>(samples_.size()); ++i) grid_[key(samples_[i].p)].push_back(i);
    }

    const std::vector<Sample>& samples() const { return samples_; }
    const std::vector<int>& of(int face) const { return perFace_[face]; }

    // The face p lies on (within tol), nearest sample's face first; 0 when none. thorough: also
    // OCCT's global projection where the local one stalls (slow: for the orbits, not the order).
    int faceAt(const gp_Pnt& p, double tol, bool thorough = false) const {
        std::vector<std::pair<double, int>> near;  // distance to the sample, sample
        const long long cx = cellOf(p.X()), cy = cellOf(p.Y()), cz = cellOf(p.Z());
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz) {
                    auto it = grid_.find(pack(cx + dx, cy + dy, cz + dz));
                    if (it == grid_.end()) continue;
                    for (int i : it->second) {
                        const double d = samples_[i].p.Distance(p);
                        if (d <= cell_ + tol) near.push_back({d, i});
                    }
                }
        std::sort(near.begin(), near.end());
        std::vector<int> tried;
        for (const auto& [d, i] : near) {
            const int f = samples_[i].face;
            if (std::find(tried.begin(), tried.end(), f) != tried.end()) continue;
            tried.push_back(f);
            if (d <= tol) return f;
            if (tried.size() > 3) break;
            gp_Pnt2d uv = samples_[i].uv;
            // Near a sample of the face, the foot point is on the face; farther, on its surface
            // beyond the face perhaps.
            if (localDistance(surfaces_[f], uv, p) <= tol && (d < 0.5 * spacing_ || onFace(f, uv))) return f;
            // The local search can stall on a B-spline of uneven parametrisation: OCCT's global
            // projection, for the two nearest faces only.
            if (thorough && tried.size() <= 2) {
                GeomAPI_ProjectPointOnSurf proj(p, BRep_Tool::Surface(g_[f].face));
                if (proj.NbPoints() > 0 && proj.LowerDistance() <= tol) {
                    double pu, pv;
                    proj.LowerDistanceParameters(pu, pv);
                    if (onFace(f, gp_Pnt2d(pu, pv))) return f;
                }
            }
        }
        return 0;
    }

    // Whether p lies on the face's own surface (trimming aside).
    bool onSurface(int f, const gp_Pnt& p, const gp_Pnt2d& guess, double tol) const {
        gp_Pnt2d uv = guess;
        return localDistance(surfaces_[f], uv, p) <= tol;
    }

private:
    // A grid over the face's parameter range, its steps about `spacing_` long on the surface
    // (measured along the middle iso-curves), kept where inside the face.
    std::vector<Sample> sampleFace(int f) const {
        const TopoDS_Face& face = g_[f].face;
        const GeomAdaptor_Surface& s = surfaces_[f];
        double u0, u1, v0, v1;
        BRepTools::UVBounds(face, u0, u1, v0, v1);
        double lu = 0, lv = 0;
        for (int k = 0; k < 8; ++k) {
            const double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
            lu += s.Value(u0 + (u1 - u0) * k / 8, vm).Distance(s.Value(u0 + (u1 - u0) * (k + 1) / 8, vm));
            lv += s.Value(um, v0 + (v1 - v0) * k / 8).Distance(s.Value(um, v0 + (v1 - v0) * (k + 1) / 8));
        }
        int nu = std::clamp(static_cast<int>(lu / spacing_) + 1, 2, 32);
        int nv = std::clamp(static_cast<int>(lv / spacing_) + 1, 2, 32);
        // A face that is its parameter rectangle (fillets, rolled walls) needs no classifier.
        std::unique_ptr<BRepTopAdaptor_FClass2d> inside;
        if (!isParameterRectangle(face)) inside = std::make_unique<BRepTopAdaptor_FClass2d>(face, 1e-7);
        // A face that covers a small part of its parameter range (a piece of a hub split by the
        // blades across the seam) gets a finer grid until it has about its share of samples.
        const double wanted = 0.5 * std::max(g_[f].area, 0.0) / (spacing_ * spacing_);
        std::vector<Sample> out;
        for (int pass = 0; pass < 3; ++pass) {
            out.clear();
            for (int i = 0; i < nu; ++i)
                for (int j = 0; j < nv; ++j) {
                    const gp_Pnt2d uv(u0 + (u1 - u0) * (i + 0.5) / nu, v0 + (v1 - v0) * (j + 0.5) / nv);
                    if (!inside || inside->Perform(uv) == TopAbs_IN) out.push_back({s.Value(uv.X(), uv.Y()), uv, f});
                }
            if (!inside || out.size() >= wanted) break;
            nu *= 2, nv *= 2;
        }
        return out;
    }

    std::vector<Sample> meshSamples(int f) const {
        std::vector<Sample> out;
        const TopoDS_Face& face = g_[f].face;
        BRepMesh_IncrementalMesh(face, 0.25 * spacing_, false, 0.5, false);
        TopLoc_Location loc;
        const Handle(Poly_Triangulation) t = BRep_Tool::Triangulation(face, loc);
        if (t.IsNull() || !t->HasUVNodes()) return out;
        const int step = std::max(1, static_cast<int>(t->NbNodes() * spacing_ * spacing_ / std::max(g_[f].area, 1e-12)));
        for (int i = 1; i <= t->NbNodes(); i += step)
            out.push_back({t->Node(i).Transformed(loc.Transformation()), t->UVNode(i), f});
        return out;
    }

    bool onFace(int f, const gp_Pnt2d& uv) const {
        auto it = classifiers_.find(f);
        if (it == classifiers_.end())
            it = classifiers_.emplace(f, std::make_unique<BRepTopAdaptor_FClass2d>(g_[f].face, 1e-7)).first;
        return it->second->Perform(uv) != TopAbs_OUT;
    }
    long long cellOf(double x) const { return static_cast<long long>(std::floor(x / cell_)); }
    static long long pack(long long x, long long y, long long z) {
        return ((x & 0x1FFFFF) << 42) | ((y & 0x1FFFFF) << 21) | (z & 0x1FFFFF);
    }
    long long key(const gp_Pnt& p) const { return pack(cellOf(p.X()), cellOf(p.Y()), cellOf(p.Z())); }

    const FaceGraph& g_;
    double spacing_, cell_;
    std::vector<Sample> samples_;
    std::vector<std::vector<int>> perFace_;
    std::vector<GeomAdaptor_Surface> surfaces_;
    std::unordered_map<long long, std::vector<int>> grid_;
    mutable std::map<int, std::unique_ptr<BRepTopAdaptor_FClass2d>> classifiers_;
};

gp_Trsf turn(const gp_Ax1& axis, double angle) {
    gp_Trsf t;
    t.SetRotation(axis, angle);
    return t;
}

// Candidate axes: the axes of the faces of revolution, by the total area of the faces on each.
std::vector<gp_Ax1> candidateAxes(const FaceGraph& g, double tol) {
    std::vector<std::pair<double, gp_Ax1>> byArea;
    for (int f = 1; f <= g.size(); ++f) {
        BRepAdaptor_Surface s(g[f].face);
        gp_Ax1 ax;
        switch (s.GetType()) {
            case GeomAbs_Cylinder: ax = s.Cylinder().Axis(); break;
            case GeomAbs_Cone: ax = s.Cone().Axis(); break;
            case GeomAbs_Torus: ax = s.Torus().Axis(); break;
            case GeomAbs_SurfaceOfRevolution: ax = s.AxeOfRevolution(); break;
            default: continue;
        }
        auto same = std::find_if(byArea.begin(), byArea.end(), [&](const auto& c) {
            return c.second.Direction().IsParallel(ax.Direction(), 1e-6) && gp_Lin(c.second).Distance(ax.Location()) < tol;
        });
        if (same == byArea.end()) byArea.push_back({g[f].area, ax});
        else same->first += g[f].area;
    }
    std::stable_sort(byArea.begin(), byArea.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<gp_Ax1> out;
    for (size_t i = 0; i < byArea.size() && i < 4; ++i) out.push_back(byArea[i].second);
    return out;
}

// The solid's axes of inertia through its centroid: an axis of symmetry is one of them.
std::vector<gp_Ax1> inertiaAxes(const TopoDS_Shape& shape) {
    std::vector<gp_Ax1> out;
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props);
    if (props.Mass() > 0) {
        const GProp_PrincipalProps pp = props.PrincipalProperties();
        for (const gp_Vec& v : {pp.FirstAxisOfInertia(), pp.SecondAxisOfInertia(), pp.ThirdAxisOfInertia()})
            out.push_back(gp_Ax1(props.CentreOfMass(), gp_Dir(v)));
    }
    return out;
}

// Whether the face is of revolution about the axis: its samples, turned by an angle no pattern
// has, stay on its surface.
bool ofRevolution(const SampleCloud& cloud, int f, const gp_Ax1& axis, double tol) {
    const auto& ids = cloud.of(f);
    if (ids.empty()) return false;
    const gp_Trsf t = turn(axis, 0.1234);
    for (size_t k = 0; k < ids.size(); k += std::max<size_t>(1, ids.size() / 5)) {
        const Sample& s = cloud.samples()[ids[k]];
        if (!cloud.onSurface(f, s.p.Transformed(t), s.uv, tol)) return false;
    }
    return true;
}

// The largest N in 3..kMaxOrder whose turn lands kOrderShare of the samples on the part.
int orderAbout(const SampleCloud& cloud, const std::vector<int>& samples, const gp_Ax1& axis, double tol) {
    if (samples.empty()) return 0;
    for (int n = kMaxOrder; n >= 3; --n) {
        const gp_Trsf t = turn(axis, 2 * kPi / n);
        const int allowed = static_cast<int>((1 - kOrderShare) * samples.size());
        int misses = 0, tried = 0;
        for (int i : samples) {
            if (!cloud.faceAt(cloud.samples()[i].p.Transformed(t), tol)) ++misses;
            // A wrong N misses most samples: settle it on the first 30 (a right one misses few),
            // and as soon as 7 of those have missed (the later ones would not change that).
            if (misses > allowed || (++tried <= 30 && misses > 6)) {
                misses = allowed + 1;
                break;
            }
        }
        if (misses <= allowed) return n;
    }
    return 0;
}

int findRoot(std::vector<int>& parent, int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

}  // namespace

RotationalSymmetry findRotationalSymmetry(const TopoDS_Shape& shape, const FaceGraph& g, double tol, double sliverArea) {
    RotationalSymmetry out;
    if (g.size() == 0) return out;
    double total = 0;
    for (int f = 1; f <= g.size(); ++f) total += std::max(g[f].area, 0.0);
    // About 1200 samples over the boundary.
    const SampleCloud cloud(g, std::max(std::sqrt(total / 1200), tol));

    // The axis with the largest order; on each, only the faces not of revolution about it tell.
    auto tryAxes = [&](const std::vector<gp_Ax1>& axes) {
        for (const gp_Ax1& axis : axes) {
            std::vector<int> samples;
            for (int f = 1; f <= g.size(); ++f)
                if (!ofRevolution(cloud, f, axis, tol))
                    samples.insert(samples.end(), cloud.of(f).begin(), cloud.of(f).end());
            // A fixed spread of at most 400 of them, in an order that mixes the faces.
            std::vector<int> picked;
            const size_t step = std::max<size_t>(1, samples.size() / 400);
            for (size_t k = 0; k < samples.size(); k += step) picked.push_back(samples[(k * 7919) % samples.size()]);
            const int n = orderAbout(cloud, picked, axis, tol);
            if (n > out.order) out.order = n, out.axis = axis;
        }
    };
    tryAxes(candidateAxes(g, tol));
    // No face of revolution on the axis (a part without bore or hub of revolution): the axes of
    // inertia, which cost a volume integration.
    if (out.order < 3) tryAxes(inertiaAxes(shape));
    if (out.order < 3) return out;

    // Orbits: each face linked to the faces that a good share of its turned samples land on.
    auto orbitsFor = [&](int order, std::vector<std::vector<int>>& orbits, std::vector<int>& unmatched) {
        orbits.clear();
        unmatched.clear();
        std::vector<int> parent(g.size() + 1);
        std::iota(parent.begin(), parent.end(), 0);
        const gp_Trsf t = turn(out.axis, 2 * kPi / order);
        for (int f = 1; f <= g.size(); ++f) {
            const auto& ids = cloud.of(f);
            if (ids.empty()) continue;  // too small to sample: an orbit of its own
            std::map<int, int> landed;
            int count = 0, misses = 0;
            for (size_t k = 0; k < ids.size(); k += std::max<size_t>(1, ids.size() / 12)) {
                const int to = cloud.faceAt(cloud.samples()[ids[k]].p.Transformed(t), tol, true);
                ++count;
                if (to) ++landed[to];
                else ++misses;
            }
            if (misses > count / 2) unmatched.push_back(f);
            for (const auto& [to, n] : landed)
                if (n >= kOrbitShare * count) parent[findRoot(parent, f)] = findRoot(parent, to);
        }
        std::map<int, std::vector<int>> byRoot;
        for (int f = 1; f <= g.size(); ++f) byRoot[findRoot(parent, f)].push_back(f);
        for (auto& [root, faces] : byRoot) orbits.push_back(std::move(faces));
    };
    auto significant = [&](const std::vector<int>& faces) {
        return std::count_if(faces.begin(), faces.end(), [&](int f) { return g[f].area > sliverArea; });
    };
    orbitsFor(out.order, out.orbits, out.unmatched);
    // Most samples landing is not all: main blades turned onto splitters that are their outer
    // part pass the order's test. A divisor of N (3 of 6) under which every face has its copy is
    // the part's order; if none, N stands and its unmatched faces say where the blades differ.
    if (significant(out.unmatched))
        for (int k = 2; out.order / k >= 3; ++k) {
            if (out.order % k) continue;
            std::vector<std::vector<int>> orbits;
            std::vector<int> unmatched;
            orbitsFor(out.order / k, orbits, unmatched);
            if (!significant(unmatched)) {
                out.order /= k;
                out.orbits = std::move(orbits);
                out.unmatched = std::move(unmatched);
                break;
            }
        }
    return out;
}

}  // namespace aeronc::impeller
