// The fast machinable ratio and roughing search against a straightforward reference: the
// full Clipper erosion of the whole pocket, the same cleaning, dilation and clip, and a plain
// search from the largest tool down that evaluates every tool. Pockets with fillets as
// tight as the tools (the case the fast erosion treats specially), islands, a corridor
// narrower than some tools, a pocket far from the origin.
#include <aeronc/core/Error.h>
#include <aeronc/toolselect/Selection.h>

#include <gtest/gtest.h>
#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace aeronc::toolselect;
using namespace ClipperLib;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kScale = 1e4;  // as the selector's
using Loop = std::vector<std::array<double, 2>>;

Path toPath(const Loop& l) {
    Path p;
    for (const auto& q : l) p.push_back({std::llround(q[0] * kScale), std::llround(q[1] * kScale)});
    return p;
}

double areaOf(const Paths& ps) {
    double a = 0;
    for (const Path& p : ps) a += Area(p);
    return a / (kScale * kScale);
}

Paths offset(const Paths& ps, double delta, double tol) {
    ClipperOffset off(2.0, tol * kScale);
    off.AddPaths(ps, jtRound, etClosedPolygon);
    Paths out;
    off.Execute(out, delta * kScale);
    return out;
}

// eta as the method defines it, every step done the plain way.
double referenceEta(const PocketGeometry& g, double r) {
    Clipper c;
    c.AddPath(toPath(g.outer), ptSubject, true);
    for (const Loop& isl : g.islands) c.AddPath(toPath(isl), ptClip, true);
    Paths region;
    c.Execute(ctDifference, region, pftNonZero, pftNonZero);
    const double tol = std::max(r * 2e-3, 2e-4);
    const Paths eroded = offset(region, -r, tol);
    if (eroded.empty()) return 0;
    Paths cleaned;
    CleanPolygons(eroded, cleaned, tol * kScale);
    const double step = 2 * std::acos(1 - tol / r);
    const Paths opened = offset(cleaned, r * std::sqrt(step / std::sin(step)), tol);
    Clipper k;
    k.AddPaths(opened, ptSubject, true);
    k.AddPaths(region, ptClip, true);
    Paths clipped;
    k.Execute(ctIntersection, clipped, pftNonZero, pftNonZero);
    return areaOf(clipped) / areaOf(region);
}

// From the largest diameter down, the first end mill reaching the depth with eta >= threshold.
const Tool* referenceRoughing(const PocketGeometry& g, const std::vector<Tool>& tools, double threshold) {
    std::vector<const Tool*> order;
    for (const Tool& t : tools)
        if (t.isEndMill() && t.usableLength() >= g.depth - 1e-6) order.push_back(&t);
    std::stable_sort(order.begin(), order.end(), [](const Tool* a, const Tool* b) { return a->diameter > b->diameter; });
    for (const Tool* t : order)
        if (referenceEta(g, t->radius()) >= threshold) return t;
    return nullptr;
}

Loop roundedRect(double x0, double y0, double w, double h, double r, int perCorner, bool clockwise = false) {
    Loop p;
    const double cx[4] = {x0 + w - r, x0 + r, x0 + r, x0 + w - r}, cy[4] = {y0 + h - r, y0 + h - r, y0 + r, y0 + r};
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < perCorner; ++k) {
            const double a = kPi / 2 * (c + k / double(perCorner - 1));
            p.push_back({cx[c] + r * std::cos(a), cy[c] + r * std::sin(a)});
        }
    if (clockwise) std::reverse(p.begin(), p.end());
    return p;
}

Loop ellipse(double cx, double cy, double a, double b, int n) {
    Loop p;
    for (int k = 0; k < n; ++k) {
        const double t = -2 * kPi * k / n;
        p.push_back({cx + a * std::cos(t), cy + b * std::sin(t)});
    }
    return p;
}

Loop star(double r0, double r1, int lobes, int perLobe) {
    Loop p;
    const int n = lobes * perLobe;
    for (int k = 0; k < n; ++k) {
        const double t = 2 * kPi * k / n, rr = r0 + (r1 - r0) * 0.5 * (1 + std::cos(lobes * t));
        p.push_back({rr * std::cos(t), rr * std::sin(t)});
    }
    return p;
}

PocketGeometry pocket(const std::string& name, Loop outer, std::vector<Loop> islands = {}) {
    PocketGeometry g;
    g.name = name;
    g.outer = std::move(outer);
    g.islands = std::move(islands);
    g.depth = 10;
    return g;
}

std::vector<PocketGeometry> pockets() {
    std::vector<PocketGeometry> v;
    for (double fillet : {4.0, 8.0}) {  // fillets equal to tool radii: the borderline case
        std::vector<Loop> isl;
        for (int i = 0; i < 5; ++i) isl.push_back(ellipse(20 + 30 * i, 50, 6, 12, 24));
        v.push_back(pocket("fillet " + std::to_string(fillet), roundedRect(0, 0, 160, 100, fillet, 50), isl));
    }
    v.push_back(pocket("islands with fillets", roundedRect(0, 0, 80, 50, 5, 17),
                       {roundedRect(20, 15, 15, 20, 3, 9, true), roundedRect(50, 10, 12, 30, 4, 12, true)}));
    // A ring corridor 4.5 mm wide round an island: a narrow passage for the larger tools.
    v.push_back(pocket("ring corridor", roundedRect(0, 0, 60, 40, 6, 20), {roundedRect(10, 4.5, 40, 31, 3, 10, true)}));
    v.push_back(pocket("dumbbell", {{0, 0}, {40, 0}, {40, 16}, {70, 16}, {70, 0}, {110, 0},
                                    {110, 40}, {70, 40}, {70, 24}, {40, 24}, {40, 40}, {0, 40}}));
    v.push_back(pocket("star", star(20, 35, 7, 40), {ellipse(0, 0, 5, 5, 32)}));
    {
        std::vector<Loop> isl;
        for (int i = 0; i < 5; ++i) isl.push_back(ellipse(150000 + 20 + 30 * i, 50, 6, 12, 24));
        v.push_back(pocket("far from the origin", roundedRect(150000, 0, 160, 100, 8, 50), isl));
    }
    return v;
}

std::vector<Tool> tools() {
    std::vector<Tool> t;
    for (double d : {1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0, 32.0})
        for (double cr : {0.0, 1.0}) {
            Tool x;
            x.id = "D" + std::to_string(d) + "r" + std::to_string(cr);
            x.type = cr > 0 ? "bull" : "flat";
            x.material = "carbide";
            x.diameter = d, x.cornerRadius = std::min(cr, d / 2), x.flutes = 3;
            x.fluteLength = 3 * d + 10, x.reach = 4 * d + 10;
            t.push_back(x);
        }
    return t;
}

}  // namespace

TEST(ToolSelectionReference, EtaMatchesThePlainComputation) {
    for (const PocketGeometry& g : pockets())
        for (double r : {1.0, 2.0, 3.0, 4.0, 4.5, 5.0, 6.0, 7.9, 8.0, 8.1, 10.0, 12.0, 16.0}) {
            SCOPED_TRACE(g.name + ", r = " + std::to_string(r));
            const MachinableRatio m = machinableRatio(g, r);
            const double ref = referenceEta(g, r);
            EXPECT_NEAR(m.eta, ref, 1e-5);
            EXPECT_NEAR(m.machinableArea, ref * m.area, 1e-5 * m.area);
        }
}

TEST(ToolSelectionReference, RoughingMatchesTheFullSearch) {
    const std::vector<Tool> ts = tools();
    for (const PocketGeometry& g : pockets())
        for (double threshold : {0.8, 0.9, 0.95, 0.98, 0.995}) {
            SCOPED_TRACE(g.name + ", eta >= " + std::to_string(threshold));
            const Tool* ref = referenceRoughing(g, ts, threshold);
            MachinableRatio m;
            const Tool* t = nullptr;
            try {
                t = roughingTool(g, ts, threshold, &m);
            } catch (const aeronc::Error&) {
            }
            ASSERT_EQ(t == nullptr, ref == nullptr);
            if (!t) continue;
            EXPECT_EQ(t->id, ref->id);
            EXPECT_NEAR(m.eta, referenceEta(g, ref->radius()), 1e-5);
            // The ratio handed back is the one machinableRatio gives for that tool.
            const MachinableRatio direct = machinableRatio(g, t->radius());
            EXPECT_EQ(m.eta, direct.eta);
            EXPECT_EQ(m.narrowPassages, direct.narrowPassages);
        }
}

TEST(ToolSelectionReference, NarrowCorridorShowsUp) {
    const PocketGeometry g = pockets()[3];  // ring corridor, 4.5 mm wide
    ASSERT_EQ(g.name, "ring corridor");
    EXPECT_EQ(machinableRatio(g, 2).narrowPassages, 0);  // a 4 mm tool passes
    const MachinableRatio m = machinableRatio(g, 3);      // a 6 mm tool does not
    EXPECT_GE(m.narrowPassages, 1);
    EXPECT_NEAR(m.eta, referenceEta(g, 3), 1e-5);
}
