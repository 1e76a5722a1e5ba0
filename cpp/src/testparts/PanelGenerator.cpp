// Integral-panel test-part generator.
//
// Layout (mm). The panel is the box [0, L] x [0, W] x [0, thickness] with
//   pw = pitch - ribThickness                 (pocket size, square)
//   L  = 2 * border + pocketsX * pitch - ribThickness
//   W  = 2 * border + pocketsY * pitch - ribThickness
// Pocket (i, j) covers [x0, x0 + pw] x [y0, y0 + pw] with x0 = border + i * pitch,
// y0 = border + j * pitch, so neighbouring pockets are separated by ribs of ribThickness and
// the grid is surrounded by a frame of width border.
//
// Feature pattern (deterministic, documented here and relied on by the tests):
//   * Floor feature of cell (i, j): k = (i + 3 * j) mod 5
//       0 plain pocket, 1 island, 2 rectangular opening, 3 lightening hole, 4 joggle.
//     Each enabled option keeps its cells; a disabled one turns them into plain pockets.
//     The default 3 x 2 grid is  row 0: plain, island, opening;  row 1: hole, joggle, plain.
//   * Bottom (-Z) pocket under every cell of kind 0 or 1 by the formula, whether or not
//     islands are on (never under openings, holes or joggles, so the web stays whole and at
//     least webZ - bottomDepth thick).
//   * Lowered ribs: in rows with j even, the rib between pockets (i, i + 1) for even i.
//     The pairs are disjoint, so each pocket has at most one rib-top parent.
//   * Bolt holes in the frame, not in the flange strip: the two corners on the y = W side
//     and every point where a rib meets the frame on the y = W, x = L and x = 0 edges, in the
//     order top-left corner, top-edge junctions (left to right), top-right corner, right-edge
//     junctions (top to bottom), left-edge junctions (bottom to top). Hole number n has kind
//     n mod 3: 0 plain, 1 counterbored, 2 countersunk.
//   * Flange: the frame strip y in [0, border / 2] lowered by 6 mm over the whole length.
//
// Feature sizes: island 0.30 pw x 0.25 pw (corner radius 3, top 2 mm under the panel top,
// floor fillet round its foot); opening 0.40 pw x 0.30 pw (corner radius 3); lightening hole
// diameter lighteningDiameter, by default min(20, 0.4 pw), at most pw - cornerRadius and
// clear of the floor fillet; joggle the middle third of the pocket along x, full width in y,
// 1.5 mm deep; -Z pocket inset 4 mm from the pocket outline; rib notch 3 mm into each pocket
// and 0.5 pw - max(cornerRadius, floorFillet) wide; bolt holes 6.6, counterbore 11 x 6 deep,
// countersink 12 at 90 degrees, placed for the largest clearance to edges and pockets.
//
// Truth (notes in quotes). Setup 0 is +Z, setup 1 is -Z (levels along -Z are -z).
//   "pocket"        closed_pocket, level webZ, islands 1 in island cells, parent -1 or its
//                   "lowered rib" element.
//   "lowered rib"   closed_pocket, level thickness - lowerRibBy, the region above the lowered
//                   rib joining both pockets; children: the two pockets; islands: those of
//                   the two pockets (island tops stand above the rib top).
//   "joggle"        closed_pocket, level webZ - 1.5, parent: its pocket.
//   "opening"       opening, through, level 0, parent: its pocket.
//   "lightening hole"  hole, through, level 0, diameter, parent: its pocket.
//   "bottom pocket" closed_pocket, setup 1, level -bottomDepth, parent -1.
//   "flange"        open_pocket, level thickness - 6, parent -1.
//   "bolt hole"     hole, through, level 0, diameter 6.6, parent -1; under a counterbore its
//                   parent is the "counterbore" and counterboreDiameter is 11.
//   "counterbore"   hole, level thickness - 6, diameter 11, parent -1, one child.
//   "countersunk bolt hole"  hole, through, level 0, diameter 6.6, countersinkDiameter 12.
// Points lie 0.5 mm above the floor along the setup direction (through elements: 0.5 mm
// above z = 0), clear of islands, holes and fillets.
//
// All cutting tools are built once as prototypes (filleted boxes, locally fused with their
// floor features), placed by location and cut from the plate in a single Boolean operation.
#include <aeronc/testparts/PanelGenerator.h>

#include <aeronc/core/Error.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRep_Tool.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <ShapeUpgrade_UnifySameDomain.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Solid.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopLoc_Location.hxx>
#include <gp_Ax2.hxx>
#include <gp_Ax1.hxx>
#include <gp_Pnt.hxx>
#include <gp_Trsf.hxx>
#include <gp_Vec.hxx>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace aeronc::testparts {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Fixed feature sizes (mm).
constexpr double kBoltDiameter = 6.6;
constexpr double kCounterboreDiameter = 11;
constexpr double kCounterboreDepth = 6;
constexpr double kCountersinkDiameter = 12;  // 90 degree included angle
constexpr double kFlangeDrop = 6;
constexpr double kJoggleDepth = 1.5;
constexpr double kIslandDrop = 2;            // island top below the panel top
constexpr double kIslandCornerRadius = 3;
constexpr double kOpeningCornerRadius = 3;
constexpr double kLighteningDiameter = 20;
constexpr double kBottomMargin = 4;          // -Z pocket inset from the cell's pocket outline
constexpr double kAbove = 0.5;               // truth points: this far above the floor
constexpr double kToolOver = 1;              // tools stick out of the panel by this much

enum CellKind { Plain = 0, Island = 1, Opening = 2, Lightening = 3, Joggle = 4 };

// A spec the generator cannot build.
[[noreturn]] void fail(const std::string& what) { throw inputError("makePanel: " + what); }
// An OCCT operation that did not give the expected shape.
[[noreturn]] void broken(const std::string& what) { throw geometryError("makePanel: " + what); }

TopoDS_Shape box(double x0, double y0, double z0, double x1, double y1, double z1) {
    return BRepPrimAPI_MakeBox(gp_Pnt(x0, y0, z0), gp_Pnt(x1, y1, z1)).Shape();
}

bool isVertical(const TopoDS_Edge& e) {
    TopoDS_Vertex a, b;
    TopExp::Vertices(e, a, b);
    if (a.IsNull() || b.IsNull()) return false;
    gp_Pnt p = BRep_Tool::Pnt(a), q = BRep_Tool::Pnt(b);
    return std::abs(p.X() - q.X()) < 1e-9 && std::abs(p.Y() - q.Y()) < 1e-9;
}

// Box with its four vertical edges rounded with radius r (r <= 0: sharp).
TopoDS_Shape roundedBox(double x0, double y0, double z0, double x1, double y1, double z1,
                        double r) {
    TopoDS_Shape b = box(x0, y0, z0, x1, y1, z1);
    if (r <= 1e-9) return b;
    BRepFilletAPI_MakeFillet mk(b);
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(b, TopAbs_EDGE, edges);
    for (int i = 1; i <= edges.Extent(); ++i) {
        const TopoDS_Edge& e = TopoDS::Edge(edges(i));
        if (isVertical(e)) mk.Add(r, e);
    }
    mk.Build();
    if (!mk.IsDone()) broken("corner fillet failed");
    return mk.Shape();
}

// Fillets all edges of the planar face of `s` that faces -Z at height z.
TopoDS_Shape filletBottom(const TopoDS_Shape& s, double z, double r) {
    BRepFilletAPI_MakeFillet mk(s);
    int added = 0;
    for (TopExp_Explorer fx(s, TopAbs_FACE); fx.More(); fx.Next()) {
        const TopoDS_Face& f = TopoDS::Face(fx.Current());
        BRepAdaptor_Surface surf(f);
        if (surf.GetType() != GeomAbs_Plane) continue;
        gp_Dir n = surf.Plane().Axis().Direction();
        if (f.Orientation() == TopAbs_REVERSED) n.Reverse();
        if (n.Z() > -0.999 || std::abs(surf.Plane().Location().Z() - z) > 1e-7) continue;
        for (TopExp_Explorer ex(f, TopAbs_EDGE); ex.More(); ex.Next()) {
            mk.Add(r, TopoDS::Edge(ex.Current()));
            ++added;
        }
    }
    if (added == 0) broken("floor fillet: no floor face");
    mk.Build();
    if (!mk.IsDone()) broken("floor fillet failed");
    return mk.Shape();
}

// The only solid of a Boolean result (which comes as a compound).
TopoDS_Shape singleSolid(const TopoDS_Shape& s, const char* what) {
    TopoDS_Shape solid;
    int n = 0;
    for (TopExp_Explorer ex(s, TopAbs_SOLID); ex.More(); ex.Next(), ++n) solid = ex.Current();
    if (n != 1) broken(std::string(what) + " gave " + std::to_string(n) + " solids");
    return solid;
}

TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b, bool unify = false) {
    BRepAlgoAPI_Fuse op(a, b);
    if (!op.IsDone() || op.HasErrors()) broken("local fuse failed");
    TopoDS_Shape r = singleSolid(op.Shape(), "local fuse");
    if (unify) {
        ShapeUpgrade_UnifySameDomain u(r, true, true, false);
        u.Build();
        r = singleSolid(u.Shape(), "unify");
    }
    return r;
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) {
    BRepAlgoAPI_Cut op(a, b);
    if (!op.IsDone() || op.HasErrors()) broken("local cut failed");
    return singleSolid(op.Shape(), "local cut");
}

// Solid of revolution about the Z axis of the closed profile (r, z) given in order; the
// first and last points must lie on the axis (r = 0).
TopoDS_Shape revolveProfile(const std::vector<std::pair<double, double>>& rz) {
    BRepBuilderAPI_MakePolygon poly;
    for (const auto& [r, z] : rz) poly.Add(gp_Pnt(r, 0, z));
    poly.Close();
    TopoDS_Face face = BRepBuilderAPI_MakeFace(poly.Wire(), true).Face();
    BRepPrimAPI_MakeRevol rev(face, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2 * kPi);
    rev.Build();
    if (!rev.IsDone()) broken("revolution failed");
    return rev.Shape();
}

TopoDS_Shape placed(const TopoDS_Shape& s, double dx, double dy) {
    gp_Trsf t;
    t.SetTranslation(gp_Vec(dx, dy, 0));
    return s.Moved(TopLoc_Location(t));
}

// Distance from (px, py) to the rounded rectangle [x0, x1] x [y0, y1] with corner radius r
// (negative inside).
double roundedRectDistance(double px, double py, double x0, double y0, double x1, double y1,
                           double r) {
    double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
    double hx = 0.5 * (x1 - x0) - r, hy = 0.5 * (y1 - y0) - r;
    double qx = std::abs(px - cx) - hx, qy = std::abs(py - cy) - hy;
    double ox = std::max(qx, 0.0), oy = std::max(qy, 0.0);
    return std::sqrt(ox * ox + oy * oy) + std::min(std::max(qx, qy), 0.0) - r;
}

TruthElement element(const std::string& type, int setup, Vec3 p, double level,
                     const std::string& note) {
    TruthElement e;
    e.type = type;
    e.setup = setup;
    e.point = p;
    e.level = level;
    e.note = note;
    return e;
}

}  // namespace

Panel makePanel(const PanelSpec& s) {
    const int nx = s.pocketsX, ny = s.pocketsY;
    const double T = s.thickness, Z = s.webZ, R = s.cornerRadius, ff = s.floorFillet;
    const double pw = s.pitch - s.ribThickness;
    if (nx < 1 || ny < 1) fail("need at least one pocket");
    if (s.ribThickness <= 0 || s.border <= 0) fail("rib thickness and border must be positive");
    if (R < 0 || pw < 2 * R + 0.05) fail("pockets too small for the corner radius");
    if (Z <= 0 || Z >= T) fail("webZ must lie inside the thickness");
    if (ff < 0 || (ff > 0 && (ff >= R || ff >= T - Z))) fail("floor fillet must be < cornerRadius");
    if (s.bottomPockets && (s.bottomDepth <= 0 || Z - s.bottomDepth < 1))
        fail("bottom pockets must leave a web of at least 1 mm");
    if (s.joggles && Z - kJoggleDepth < 1) fail("web too thin for joggles");
    if (s.flange && T - kFlangeDrop <= 0) fail("panel too thin for the flange");
    if (s.lowerRibs && (s.lowerRibBy <= 0 || T - s.lowerRibBy <= Z + ff))
        fail("lowerRibBy must keep the rib above the floor");
    if (s.islands && T - kIslandDrop <= Z + 1) fail("panel too thin for islands");
    if (s.boltHoles && T <= kCounterboreDepth + 1) fail("panel too thin for counterbores");

    const double L = 2 * s.border + nx * s.pitch - s.ribThickness;
    const double W = 2 * s.border + ny * s.pitch - s.ribThickness;
    const double top = T + kToolOver;

    auto kindOf = [&](int i, int j) {
        int k = (i + 3 * j) % 5;
        if ((k == Island && !s.islands) || (k == Opening && !s.openings) ||
            (k == Lightening && !s.lighteningHoles) || (k == Joggle && !s.joggles))
            k = Plain;
        return k;
    };
    auto hasBottom = [&](int i, int j) {
        int k = (i + 3 * j) % 5;
        return s.bottomPockets && (k == Plain || k == Island);
    };

    // ---- Prototype tools, local coordinates: the pocket occupies [0, pw]^2. ----
    const double c = 0.5 * pw;
    const TopoDS_Shape baseTool = roundedBox(0, 0, Z, pw, pw, top, R);
    const TopoDS_Shape plainTool = ff > 0 ? filletBottom(baseTool, Z, ff) : baseTool;

    const double iw = 0.30 * pw, ih = 0.25 * pw;
    const double ir = std::min(kIslandCornerRadius, 0.25 * std::min(iw, ih));
    const double ow = 0.40 * pw, oh = 0.30 * pw;
    const double orad = kOpeningCornerRadius;
    if (s.openings && 2 * orad + 1 >= std::min(ow, oh)) fail("pockets too small for openings");
    const double holeD = s.lighteningDiameter > 0 ? s.lighteningDiameter : std::min(kLighteningDiameter, 0.4 * pw);
    if (s.lighteningHoles && s.lighteningDiameter < 0) fail("the lightening hole diameter must not be negative");
    // The floor ring round the hole keeps room for a truth point beside the floor fillet.
    if (s.lighteningHoles && (holeD > pw - R + 1e-9 || holeD > pw - 2 * ff - 1))
        fail("lightening hole too wide for the pocket");

    TopoDS_Shape tools[5];
    tools[Plain] = plainTool;
    if (s.islands) {
        TopoDS_Shape isl = roundedBox(c - iw / 2, c - ih / 2, Z - 1, c + iw / 2, c + ih / 2,
                                      T - kIslandDrop, ir);
        // The floor fillet also runs round the island's foot.
        tools[Island] = cut(baseTool, isl);
        if (ff > 0) tools[Island] = filletBottom(tools[Island], Z, ff);
    }
    if (s.openings) {
        TopoDS_Shape win = roundedBox(c - ow / 2, c - oh / 2, -kToolOver, c + ow / 2,
                                      c + oh / 2, Z + 1, orad);
        tools[Opening] = fuse(plainTool, win);
    }
    if (s.lighteningHoles) {
        TopoDS_Shape cyl =
            BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(c, c, -kToolOver), gp_Dir(0, 0, 1)),
                                     holeD / 2, Z + 1 + kToolOver)
                .Shape();
        tools[Lightening] = fuse(plainTool, cyl);
    }
    if (s.joggles) {
        // Middle third along x, full pocket width in y: its sides lie in the pocket walls.
        TopoDS_Shape jog = box(pw / 3, 0, Z - kJoggleDepth, 2 * pw / 3, pw, Z + ff + 1);
        tools[Joggle] = fuse(plainTool, jog, true);
    }
    const double bw = pw - 2 * kBottomMargin;
    const double br = std::min(R, 0.5 * bw - 1);
    TopoDS_Shape bottomTool;
    if (s.bottomPockets)
        bottomTool = roundedBox(kBottomMargin, kBottomMargin, -kToolOver, pw - kBottomMargin,
                                pw - kBottomMargin, s.bottomDepth, std::max(br, 0.0));

    // Rib lowering box, local to the rib centre (xr, yc).
    const double notchHalf = 0.5 * (0.5 * pw - std::max(R, ff));
    const double notchReach = std::min(3.0, 0.25 * pw);
    TopoDS_Shape ribTool;
    if (s.lowerRibs)
        ribTool = box(-s.ribThickness / 2 - notchReach, -notchHalf, T - s.lowerRibBy,
                      s.ribThickness / 2 + notchReach, notchHalf, T + 2 * kToolOver);

    const double rb = kBoltDiameter / 2;
    const double cbTop = T - kCounterboreDepth;
    const double rs = kCountersinkDiameter / 2;
    const double cskBottom = T - (rs - rb);  // 90 degrees: depth = radius difference
    TopoDS_Shape boltTools[3];
    if (s.boltHoles) {
        boltTools[0] = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, 0, -kToolOver), gp_Dir(0, 0, 1)),
                                                rb, T + 2 * kToolOver)
                           .Shape();
        boltTools[1] = revolveProfile({{0, -kToolOver},
                                       {rb, -kToolOver},
                                       {rb, cbTop},
                                       {kCounterboreDiameter / 2, cbTop},
                                       {kCounterboreDiameter / 2, top},
                                       {0, top}});
        boltTools[2] = revolveProfile({{0, -kToolOver},
                                       {rb, -kToolOver},
                                       {rb, cskBottom},
                                       {rs + kToolOver, top},
                                       {0, top}});
    }

    // ---- Place tools and record the truth. ----
    Panel panel;
    auto& truth = panel.truth;
    auto add = [&](TruthElement e) {
        e.id = static_cast<int>(truth.size());
        truth.push_back(e);
        return e.id;
    };

    TopTools_ListOfShape toolList;
    std::vector<int> pocketId(static_cast<size_t>(nx) * ny, -1);
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const double x0 = s.border + i * s.pitch, y0 = s.border + j * s.pitch;
            const int k = kindOf(i, j);
            toolList.Append(placed(tools[k], x0, y0));

            double px = x0 + std::max(pw / 6, ff + 1.0);
            // A wide lightening hole leaves a ring of floor: take its middle, clear of the fillet.
            if (k == Lightening && c - (px - x0) < 0.5 * holeD + 0.5)
                px = x0 + 0.5 * (ff + c - 0.5 * holeD);
            TruthElement p = element("closed_pocket", 0, {px, y0 + c, Z + kAbove}, Z, "pocket");
            p.islands = (k == Island) ? 1 : 0;
            const int pid = add(p);
            pocketId[static_cast<size_t>(j) * nx + i] = pid;

            const Vec3 through{x0 + c, y0 + c, kAbove};
            if (k == Opening) {
                TruthElement e = element("opening", 0, through, 0, "opening");
                e.through = true;
                e.parent = pid;
                add(e);
            } else if (k == Lightening) {
                TruthElement e = element("hole", 0, through, 0, "lightening hole");
                e.through = true;
                e.diameter = holeD;
                e.parent = pid;
                add(e);
            } else if (k == Joggle) {
                TruthElement e = element("closed_pocket", 0,
                                         {x0 + c, y0 + c, Z - kJoggleDepth + kAbove},
                                         Z - kJoggleDepth, "joggle");
                e.parent = pid;
                add(e);
            }
            if (hasBottom(i, j)) {
                toolList.Append(placed(bottomTool, x0, y0));
                add(element("closed_pocket", 1, {x0 + c, y0 + c, s.bottomDepth - kAbove},
                            -s.bottomDepth, "bottom pocket"));
            }
        }
    }

    if (s.lowerRibs) {
        for (int j = 0; j < ny; j += 2) {
            for (int i = 0; i + 1 < nx; i += 2) {
                const double xr = s.border + i * s.pitch + pw + s.ribThickness / 2;
                const double yc = s.border + j * s.pitch + c;
                toolList.Append(placed(ribTool, xr, yc));
                TruthElement e = element("closed_pocket", 0,
                                         {xr, yc, T - s.lowerRibBy + kAbove}, T - s.lowerRibBy,
                                         "lowered rib");
                const int a = pocketId[static_cast<size_t>(j) * nx + i];
                const int b = pocketId[static_cast<size_t>(j) * nx + i + 1];
                e.islands = truth[a].islands + truth[b].islands;
                const int id = add(e);
                truth[a].parent = id;
                truth[b].parent = id;
            }
        }
    }

    const double flangeWidth = 0.5 * s.border;
    if (s.flange) {
        toolList.Append(box(-kToolOver, -kToolOver, T - kFlangeDrop, L + kToolOver, flangeWidth,
                            top));
        add(element("open_pocket", 0, {L / 2, flangeWidth / 2, T - kFlangeDrop + kAbove},
                    T - kFlangeDrop, "flange"));
    }

    if (s.boltHoles) {
        // Largest radius of any bolt-hole kind at the top; keep it clear of edges and pockets.
        const double rmax = std::max(kCountersinkDiameter, kCounterboreDiameter) / 2;
        const double keepY = s.flange ? flangeWidth : 0.0;
        auto clearance = [&](double hx, double hy) {
            double d = std::min({hx, L - hx, hy - keepY, W - hy});
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) {
                    const double x0 = s.border + i * s.pitch, y0 = s.border + j * s.pitch;
                    if (std::abs(hx - x0 - c) > pw + 2 * rmax ||
                        std::abs(hy - y0 - c) > pw + 2 * rmax)
                        continue;
                    d = std::min(d, roundedRectDistance(hx, hy, x0, y0, x0 + pw, y0 + pw, R));
                }
            return d - rmax;
        };
        // Offsets from the outer edge, chosen for the largest clearance.
        auto bestOffset = [&](auto positionAt) {
            double best = -1e9, bestE = 0;
            for (double e = 0.5 * rmax; e <= s.border + R; e += 0.05) {
                auto [hx, hy] = positionAt(e);
                double cl = clearance(hx, hy);
                if (cl > best + 1e-9) best = cl, bestE = e;
            }
            return std::make_pair(bestE, best);
        };
        const double minClear = 0.5;
        std::vector<std::pair<double, double>> holes;
        auto ribX = [&](int i) { return s.border + i * s.pitch + pw + s.ribThickness / 2; };
        auto ribY = [&](int j) { return s.border + j * s.pitch + pw + s.ribThickness / 2; };
        auto [ec, clc] = bestOffset([&](double e) { return std::make_pair(e, W - e); });
        auto [ej, clj] = bestOffset([&](double e) {
            return std::make_pair(nx > 1 ? ribX(0) : L / 2, W - e);
        });
        if (clc >= minClear) holes.push_back({ec, W - ec});
        if (clj >= minClear)
            for (int i = 0; i + 1 < nx; ++i) holes.push_back({ribX(i), W - ej});
        if (clc >= minClear) holes.push_back({L - ec, W - ec});
        auto [es, cls] = bestOffset([&](double e) {
            return std::make_pair(e, ny > 1 ? ribY(0) : W / 2);
        });
        if (cls >= minClear) {
            for (int j = ny - 2; j >= 0; --j) holes.push_back({L - es, ribY(j)});
            for (int j = 0; j + 1 < ny; ++j) holes.push_back({es, ribY(j)});
        }
        for (size_t n = 0; n < holes.size(); ++n) {
            const auto [hx, hy] = holes[n];
            const int kind = static_cast<int>(n % 3);
            toolList.Append(placed(boltTools[kind], hx, hy));
            if (kind == 1) {
                const double ra = 0.5 * (rb + kCounterboreDiameter / 2);
                TruthElement cb = element("hole", 0, {hx + ra, hy, cbTop + kAbove}, cbTop,
                                          "counterbore");
                cb.diameter = kCounterboreDiameter;
                const int cid = add(cb);
                TruthElement h = element("hole", 0, {hx, hy, kAbove}, 0, "bolt hole");
                h.diameter = kBoltDiameter;
                h.through = true;
                h.counterboreDiameter = kCounterboreDiameter;
                h.parent = cid;
                add(h);
            } else {
                TruthElement h = element("hole", 0, {hx, hy, kAbove}, 0,
                                         kind == 2 ? "countersunk bolt hole" : "bolt hole");
                h.diameter = kBoltDiameter;
                h.through = true;
                if (kind == 2) h.countersinkDiameter = kCountersinkDiameter;
                add(h);
            }
        }
    }

    // ---- One Boolean: the plate minus all tools. ----
    TopTools_ListOfShape args;
    args.Append(box(0, 0, 0, L, W, T));
    BRepAlgoAPI_Cut op;
    op.SetArguments(args);
    op.SetTools(toolList);
    op.SetRunParallel(true);
    op.SetNonDestructive(true);  // the placed tools share their prototypes' sub-shapes
    op.SetToFillHistory(false);
    op.Build();
    if (!op.IsDone() || op.HasErrors()) broken("panel cut failed");
    panel.shape = singleSolid(op.Shape(), "panel cut");
    return panel;
}

std::string truthToJson(const Panel& panel) {
    using nlohmann::json;
    json elems = json::array();
    for (const auto& e : panel.truth) {
        json children = json::array();
        for (const auto& o : panel.truth)
            if (o.parent == e.id) children.push_back(o.id);
        elems.push_back({{"id", e.id},
                         {"type", e.type},
                         {"setup", e.setup},
                         {"point", {e.point[0], e.point[1], e.point[2]}},
                         {"level", e.level},
                         {"parent", e.parent},
                         {"children", children},
                         {"islands", e.islands},
                         {"diameter", e.diameter},
                         {"through", e.through},
                         {"counterboreDiameter", e.counterboreDiameter},
                         {"countersinkDiameter", e.countersinkDiameter},
                         {"note", e.note}});
    }
    json setups = json::array({{{"id", 0}, {"name", "+Z"}, {"direction", {0, 0, 1}}},
                               {{"id", 1}, {"name", "-Z"}, {"direction", {0, 0, -1}}}});
    json doc = {{"units", "mm"}, {"setups", setups}, {"elements", elems}};
    return doc.dump(1);
}

}  // namespace aeronc::testparts
