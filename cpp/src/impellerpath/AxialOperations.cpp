// Turning, facing, drilling and boring of an impeller (see the header).
#include <aeronc/impellerpath/AxialOperations.h>

#include "ChannelGeometry.h"

#include <aeronc/core/Error.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepExtrema_DistShapeShape.hxx>
#include <Bnd_Box.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <gp_Ax2.hxx>
#include <gp_Pln.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>

namespace aeronc::impellerpath {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kGougeAim = 0.002;  // mm

// Radial and axial extent of a face about the axis, from points along its edges.
struct Extent {
    double rMin = 1e300, rMax = 0, zMin = 1e300, zMax = -1e300;
};
Extent extentOf(const TopoDS_Face& f, const Frame& fr) {
    Extent e;
    for (TopExp_Explorer ex(f, TopAbs_EDGE); ex.More(); ex.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(ex.Current());
        if (BRep_Tool::Degenerated(edge)) continue;
        BRepAdaptor_Curve c(edge);
        for (int i = 0; i <= 64; ++i) {
            const gp_Pnt p = c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * i / 64);
            const Vec3 v(p.X(), p.Y(), p.Z());
            e.rMin = std::min(e.rMin, fr.radius(v)), e.rMax = std::max(e.rMax, fr.radius(v));
            e.zMin = std::min(e.zMin, fr.axial(v)), e.zMax = std::max(e.zMax, fr.axial(v));
        }
    }
    return e;
}

// The outward normal of a plane face (a plane's natural normal is its axis, reversed for a
// left-handed placement; the face's orientation reverses it again).
Vec3 planeNormal(const TopoDS_Face& f) {
    const gp_Pln pl = BRepAdaptor_Surface(f).Plane();
    gp_Dir n = pl.Axis().Direction();
    if (!pl.Direct()) n.Reverse();
    if (f.Orientation() == TopAbs_REVERSED) n.Reverse();
    return Vec3(n.X(), n.Y(), n.Z());
}

// Whether a flat-bottomed tool (a cylinder of radius rho from `lift` above its tip up to its
// reach) touches the part: OCCT's distance between the cylinder and the part. Lifted by 0.01 mm,
// the bottom clears the plane it faces and the faces that only meet that plane at its edges; a
// blade standing above the plane meets the bottom and is caught.
bool flatToolTouches(const TopoDS_Shape& part, const Bnd_Box& partBox, const CutterShape& c, const Vec3& tip,
                     const Vec3& axis) {
    constexpr double lift = 0.01;
    const Vec3 base = tip + lift * axis;
    const TopoDS_Shape tool = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(base.x(), base.y(), base.z()),
                                                              gp_Dir(axis.x(), axis.y(), axis.z())),
                                                       c.tipRadius, c.reach - lift)
                                  .Shape();
    Bnd_Box box;
    BRepBndLib::Add(tool, box, false);
    if (box.IsOut(partBox)) return false;
    BRepExtrema_DistShapeShape d(tool, part);
    if (!d.IsDone()) throw geometryError("impeller facing: the distance between the face mill and the part failed");
    return d.Value() < 1e-7;
}

struct Measure {
    const Obstacles& part;
    CheckResult& result;
    // `at`: where the tool is measured from (the centre, or the tip of a tool cutting down the
    // bore, which then counts a sphere of its radius below the tip too: air in a through bore).
    Clearance measure(const CutterShape& c, const Vec3& at, const Vec3& axis) { return clearance(part, c, at, axis); }
    void record(const Clearance& k, const Vec3& centre) {
        ++result.positions;
        if (k.holder) ++result.holderCollisions;
        if (k.gouge > result.maxGouge) {
            result.maxGouge = k.gouge;
            result.worstAt[0] = centre.x(), result.worstAt[1] = centre.y(), result.worstAt[2] = centre.z();
        }
    }
};

// Rapid above a pass, feed through it, rapid back up: the approach and retract along the axis.
void appendPass(std::vector<Move>& out, const std::vector<Move>& pass, double lift) {
    if (pass.empty()) return;
    out.push_back(Move{pass.front().centre + lift * pass.front().axis, pass.front().axis, true});
    out.insert(out.end(), pass.begin(), pass.end());
    out.push_back(Move{pass.back().centre + lift * pass.back().axis, pass.back().axis, true});
}

}  // namespace

CutterShape flatCutter(const std::string& id, int number, double diameter, double fluteLength, double reach,
                       double rpm, double feed) {
    CutterShape c;
    c.id = id, c.number = number, c.tipRadius = 0.5 * diameter, c.flat = true;
    c.fluteLength = std::max(fluteLength, c.tipRadius + 1);
    c.reach = std::max(reach, c.fluteLength);
    c.shankRadius = c.tipRadius;
    c.rpm = rpm, c.feed = feed;
    return c;
}

AxialProgram axialToolpaths(const TopoDS_Shape& part, const impeller::ImpellerFeatures& f,
                            const impeller::ImpellerDimensions& d, const AxialCutters& cutters,
                            const AxialOptions& opt) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    std::vector<TopoDS_Face> all;
    for (int i = 1; i <= faces.Extent(); ++i) all.push_back(TopoDS::Face(faces(i)));
    const Obstacles obstacles(all, {});
    const Frame fr(f);
    const Vec3 x = fr.at(1, 0, 0) - fr.at(0, 0, 0), z = fr.z();
    AxialProgram prog;
    Measure m{obstacles, prog.check};
    auto face = [&](int id) { return TopoDS::Face(faces(id)); };

    // Turning, in the meridian plane at angle 0: each outer cylinder along its length, each plane
    // across it from outside in, the insert's shank pointing away from the face.
    {
        const CutterShape& c = cutters.turningInsert;
        Operation op{"turn", c, {}};
        const double R = c.tipRadius;
        for (int id : f.turned) {
            if (BRepAdaptor_Surface(face(id)).GetType() != GeomAbs_Cylinder) {
                prog.notes.push_back("turn: face " + std::to_string(id) + " is not a cylinder; not turned");
                continue;
            }
            const Extent e = extentOf(face(id), fr);
            std::vector<Move> pass;
            const int n = std::max(1, static_cast<int>(std::ceil((e.zMax - e.zMin) / opt.turnStep)));
            for (int i = 0; i <= n; ++i) {
                const Vec3 centre = fr.at(e.rMax + R, 0, e.zMax - (e.zMax - e.zMin) * i / n);
                const Clearance k = m.measure(c, centre, x);
                m.record(k, centre);
                pass.push_back(Move{centre, x, false});
            }
            appendPass(op.moves, pass, opt.safeDistance);
        }
        for (int id : f.planes) {
            const Vec3 n = planeNormal(face(id));
            if (std::abs(std::abs(n.dot(z)) - 1) > 1e-6) continue;  // not square to the axis
            const Extent e = extentOf(face(id), fr);
            const double side = n.dot(z) > 0 ? 1 : -1;
            std::vector<Move> pass;
            const int steps = std::max(1, static_cast<int>(std::ceil((e.rMax + R + 1 - e.rMin) / opt.turnStep)));
            for (int i = 0; i <= steps; ++i) {
                const double r = e.rMax + R + 1 - (e.rMax + R + 1 - e.rMin) * i / steps;
                const Vec3 centre = fr.at(r, 0, e.zMax + side * R);
                const Vec3 axis = side * z;
                const Clearance k = m.measure(c, centre, axis);
                if (k.gouge > kGougeAim || k.holder) {  // the insert cannot reach further in
                    prog.notes.push_back("turn: plane " + std::to_string(id) + " faced down to radius " +
                                         std::to_string(r) + " mm only (the insert would touch the part)");
                    break;
                }
                m.record(k, centre);
                pass.push_back(Move{centre, axis, false});
            }
            appendPass(op.moves, pass, opt.safeDistance);
        }
        if (!op.moves.empty()) prog.operations.push_back(op);
    }

    // Facing: straight passes of the face mill over each plane, its bottom on the plane.
    if (cutters.faceMill) {
        const CutterShape& c = *cutters.faceMill;
        Operation op{"face", c, {}};
        Bnd_Box partBox;
        BRepBndLib::AddOptimal(part, partBox, false, false);
        for (int id : f.planes) {
            const Vec3 n = planeNormal(face(id));
            if (std::abs(std::abs(n.dot(z)) - 1) > 1e-6) continue;
            const Extent e = extentOf(face(id), fr);
            const double rho = c.tipRadius;
            // Passes across the plane, 0.7 of the diameter apart, from outside to outside.
            const double span = e.rMax + rho + 1;
            const int lanes = std::max(1, static_cast<int>(std::ceil(2 * e.rMax / (1.4 * rho))));
            std::vector<std::vector<Move>> passes;
            bool reachable = true;
            for (int l = 0; l < lanes && reachable; ++l) {
                const double y = lanes == 1 ? 0 : -e.rMax + 2 * e.rMax * l / (lanes - 1);
                std::vector<Move> pass;
                const int steps = std::max(1, static_cast<int>(std::ceil(2 * span / std::max(opt.turnStep, 0.1 * rho))));
                for (int i = 0; i <= steps && reachable; ++i) {
                    const double xs = (l % 2 ? 1 : -1) * (span - 2 * span * i / steps);
                    const Vec3 tip = fr.at(0, 0, e.zMax) + xs * x + y * z.cross(x);
                    reachable = !flatToolTouches(part, partBox, c, tip, n);
                    pass.push_back(Move{tip + rho * n, n, false});
                }
                passes.push_back(pass);
            }
            if (!reachable) {
                prog.notes.push_back("face: " + c.id + " cannot face plane " + std::to_string(id) +
                                     " without touching the part; the lathe faces it (turn)");
                continue;
            }
            for (const auto& p : passes) {
                for (const auto& mv : p) {
                    // Clear of the part by the test above; the spheres along its axis measure the
                    // rest as for every other step (and are what the re-check measures).
                    Clearance k = m.measure(c, mv.centre, mv.axis);
                    m.record(k, mv.centre);
                }
                appendPass(op.moves, p, opt.safeDistance);
            }
        }
        if (!op.moves.empty()) prog.operations.push_back(op);
    }

    // Drilling and boring the bore, from its end towards the blades; as far as the flutes reach
    // (the shank, as wide as the cut, would rub the finished wall), the rest from the back face
    // in a second setup, the tool axis reversed.
    if (f.bore && (cutters.drill || cutters.boringMill)) {
        const Extent e = extentOf(face(f.bore), fr);
        const double radius = 0.5 * d.boreDiameter;
        auto cut = [&](const CutterShape& c, double offset, double pitch, const std::string& name) {
            Operation top{name, c, {}}, back{name + "_back", c, {}};
            const double rho = c.tipRadius, depth = c.fluteLength - 0.5;  // flutes inside the bore, the shank out
            CutterShape fromTip = c;  // the same tool with its lengths counted from its tip
            fromTip.fluteLength += rho, fromTip.reach += rho;
            if (!(depth > 0)) throw inputError("impeller " + name + ": " + c.id + " has no flute length");
            const double through = e.zMax - e.zMin + 2;  // the tip leaves the bore by 1 mm each end
            for (int side : {1, -1}) {
                const double start = side > 0 ? e.zMax + 1 : e.zMin - 1;
                // From the back, only what the first side left, with 1 mm of overlap.
                const double length = side > 0 ? std::min(through, depth) : std::min(through - depth + 1, depth);
                if (side < 0 && depth >= through) break;
                if (side < 0 && 2 * depth - 1 < through)
                    prog.notes.push_back(name + ": " + c.id + "'s flutes reach " + std::to_string(2 * depth - 1) +
                                         " mm of the " + std::to_string(through) + " mm through the bore from both ends");
                const Vec3 axis = side * z;
                const int perTurn = offset > 0 ? 24 : 1;
                const int n = offset > 0 ? static_cast<int>(std::ceil(length / pitch)) * perTurn + perTurn
                                         : std::max(1, static_cast<int>(std::ceil(length / 2.0)));
                std::vector<Move> pass;
                for (int i = 0; i <= n; ++i) {
                    const double a = 2 * kPi * i / perTurn;
                    const double advance = offset > 0 ? std::min(pitch * i / perTurn, length) : length * i / n;
                    const Vec3 tip = fr.at(offset, a, start - side * advance);
                    // Measured from its tip: the sphere of its radius there holds the flat bottom
                    // (and reaches beyond it, into the bore's air).
                    m.record(m.measure(fromTip, tip, axis), tip + rho * axis);
                    pass.push_back(Move{tip + rho * axis, axis, false});
                }
                appendPass((side > 0 ? top : back).moves, pass, opt.safeDistance);
            }
            prog.operations.push_back(top);
            if (!back.moves.empty()) prog.operations.push_back(back);
        };
        if (cutters.drill) {
            if (cutters.drill->tipRadius > radius - opt.drillAllowance + 1e-9)
                throw inputError("impeller drill: " + cutters.drill->id + " is wider than the bore less the allowance");
            cut(*cutters.drill, 0, 0, "drill");
        }
        if (cutters.boringMill) {
            const double offset = radius - cutters.boringMill->tipRadius;
            if (!(offset > 0)) throw inputError("impeller bore: " + cutters.boringMill->id + " is as wide as the bore");
            cut(*cutters.boringMill, offset, opt.helixPitch, "bore");
        }
    }
    return prog;
}

}  // namespace aeronc::impellerpath
