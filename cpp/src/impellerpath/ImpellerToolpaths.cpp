// Impeller toolpaths: channel roughing, blade flank finishing and hub finishing (see the header).
#include <aeronc/impellerpath/ImpellerToolpaths.h>

#include "ChannelGeometry.h"
#include "StockEnvelope.h"

#include <aeronc/core/Error.h>

#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <BRepTopAdaptor_FClass2d.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <atomic>
#include <exception>
#include <thread>
#include <cmath>
#include <map>
#include <memory>

namespace aeronc::impellerpath {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kGougeAim = 0.002;  // mm: finishing positions are stepped back to at most this

double lerp(double a, double b, double t) { return a + (b - a) * t; }

// Axis turned by `deg` about `about` (unit).
Vec3 tilted(const Vec3& axis, const Vec3& about, double deg) {
    return (Eigen::AngleAxisd(deg * kPi / 180, about) * axis).normalized();
}

// Cutting positions of one pass, checked; the holder cleared by tilting towards the channel's
// middle (about the local radial direction, both ways, in growing steps).
struct Checker {
    const Channel& ch;
    const CutterShape& cutter;
    const PathOptions& opt;
    CheckResult& result;
    double stock = 0;  // distance to keep beyond the cutter (roughing's allowance)

    // A position closer to the part than the cutter and the stock allow (OCCT's approximations,
    // a twisted ruling, a slanted wall) is stepped back from the nearest point of the part.
    Move place(Vec3 centre, Vec3 axis) {
        const double aim = stock > 0 ? 0.0 : kGougeAim;
        Clearance c = clearance(ch.obstacles(), cutter, centre, axis, stock);
        for (int i = 0; i < 6 && c.gouge > aim && c.away.norm() > 0; ++i) {
            centre += (c.gouge - aim + 1e-4) * c.away;
            c = clearance(ch.obstacles(), cutter, centre, axis, stock);
        }
        c.gouge -= stock;  // what is reported is the cut into the part itself
        if (c.holder) {
            const Vec3 radial = (centre - ch.frame().at(0, 0, ch.frame().axial(centre))).normalized();
            const Vec3 tangential = ch.frame().z().cross(radial).normalized();
            bool cleared = false;
            for (double deg = 2; deg <= opt.maxTiltDeg + 1e-9 && !cleared; deg += 2)
                for (const Vec3& about : {radial, Vec3(-radial), tangential, Vec3(-tangential)}) {
                    const Vec3 a = tilted(axis, about, deg);
                    Clearance t = clearance(ch.obstacles(), cutter, centre, a, stock);
                    t.gouge -= stock;
                    if (!t.holder && t.gouge <= std::max(c.gouge, 0.0) + 1e-6) {
                        axis = a, c = t, cleared = true;
                        ++result.tilted;
                        break;
                    }
                }
        }
        record(c, centre);
        return Move{centre, axis, false};
    }
    // A position that is not moved, measured as the program's re-check measures it.
    void tally(const Move& m) { record(clearance(ch.obstacles(), cutter, m.centre, m.axis), m.centre); }
    void record(const Clearance& c, const Vec3& centre) {
        ++result.positions;
        if (c.holder) ++result.holderCollisions;
        if (c.gouge > result.maxGouge) {
            result.maxGouge = c.gouge;
            result.worstAt[0] = centre.x(), result.worstAt[1] = centre.y(), result.worstAt[2] = centre.z();
        }
    }
};

// Links between passes. A pass is entered and left along the tool axis at feed, from and to the
// point where the whole tool is `clearance` outside the blank (the envelope of the part and of
// any stock left); from there rapids run along the axis up to the clearance plane, and across
// it to the next pass. Every link is checked: the feed stretches against the part (the tool
// swept along its axis), the rapids against the blank.
struct Links {
    const StockEnvelope& stock;
    double plane;      // axial height of the ball centre on the clearance plane
    double clearance;  // mm the tool keeps outside the blank on rapids

    // Up the tool axis from m until the tool is clear of the blank.
    Move outside(const Move& m, const CutterShape& c) const {
        double t = 0;
        while (t < 500 && stock.clearance(c, m.centre + t * m.axis, m.axis) < clearance) t += 0.5;
        return Move{m.centre + t * m.axis, m.axis, false};
    }
    Move onPlane(const Move& m, const Frame& fr) const {
        const double up = plane - fr.axial(m.centre);
        return Move{m.centre + std::max(up, 0.0) / std::max(0.2, m.axis.dot(fr.z())) * m.axis, m.axis, true};
    }
    // Feed along the tool axis between a cutting position and a point above it. Moving along its
    // own axis, the tool sweeps what the tool at the cutting position covers with its shank longer
    // by the distance (and no narrower than the flutes' top): one measure of that longer tool.
    void checkFeed(const Move& cutting, const Move& above, Checker& check) const {
        CutterShape longer = check.cutter;
        longer.reach += (above.centre - cutting.centre).norm();
        // Flutes wider than the shank sweep up through where the shank was.
        longer.shankRadius = std::max(longer.shankRadius, longer.radiusAt(longer.fluteLength - longer.tipRadius));
        const Clearance k = impellerpath::clearance(check.ch.obstacles(), longer, cutting.centre, cutting.axis);
        ++check.result.links;
        check.result.linkCollisions += k.gouge > kGougeAim || k.holder;
    }
    // A rapid from a to b: the tool outside the blank all along.
    void checkRapid(const Move& a, const Move& b, Checker& check) const {
        ++check.result.links;
        check.result.linkCollisions += rapidClearance(stock, check.cutter, a, b) < 0;
    }
    void append(std::vector<Move>& out, const std::vector<Move>& pass, Checker& check) const {
        if (pass.empty()) return;
        const Frame& fr = check.ch.frame();
        const Move in = outside(pass.front(), check.cutter), out_ = outside(pass.back(), check.cutter);
        const Move inTop = onPlane(in, fr), outTop = onPlane(out_, fr);
        Move inRapid = in;
        inRapid.rapid = true;
        checkRapid(inTop, inRapid, check);
        checkFeed(pass.front(), in, check);
        checkFeed(pass.back(), out_, check);
        checkRapid(out_, outTop, check);
        check.tally(out_);
        out.push_back(inTop);
        out.push_back(inRapid);
        out.insert(out.end(), pass.begin(), pass.end());
        out.push_back(out_);
        out.push_back(outTop);
    }
};

std::vector<double> stations(double a, double b, int n) {
    std::vector<double> s;
    for (int i = 0; i < n; ++i) s.push_back(lerp(a, b, (i + 0.5) / n));
    return s;
}

// The interpolated ruling direction across the channel at fraction u from wall A to wall B.
Vec3 blendedAxis(const Channel& ch, double r, double z, double thetaA, double thetaB, double u) {
    Vec3 ra, na, rb, nb;
    ch.wallFrame(false, ch.frame().at(r, thetaA, z), ra, na);
    ch.wallFrame(true, ch.frame().at(r, thetaB, z), rb, nb);
    return ((1 - u) * ra + u * rb).normalized();
}

// The distance along the arc at radius r from a wall to where a point is `keep` from it.
double arcMargin(const Channel& ch, bool b, double r, double theta, double z, double keep) {
    Vec3 ruling, normal;
    const Vec3 p = ch.frame().at(r, theta, z);
    ch.wallFrame(b, p, ruling, normal);
    const Vec3 tangential = ch.frame().z().cross(p - ch.frame().at(0, 0, z)).normalized();
    return keep / std::max(0.2, std::abs(normal.dot(tangential)));
}

void roughChannel(const Channel& ch, const CutterShape& cut, const PathOptions& opt, const Links& links,
                  CheckResult& res, std::vector<Move>& out) {
    Checker check{ch, cut, opt, res, opt.roughAllowance};
    const double R = cut.tipRadius, keep = R + opt.roughAllowance;
    const double r0 = ch.rMin() + keep, r1 = ch.rMax() - keep;
    const auto rs = stations(r0, r1, opt.stations);
    // The lowest centre at each station: `keep` from the hub along its normal (the hub slopes,
    // so that is more than `keep` along the axis).
    std::vector<double> floor;
    for (double r : rs) {
        const double theta = 0.5 * (ch.guessTheta(false, r) + ch.guessTheta(true, r));
        const Vec3 onHub = ch.frame().at(r, theta, ch.hubZ(r));
        floor.push_back(ch.hubZ(r) + keep / std::max(0.3, ch.hubNormal(onHub).dot(ch.frame().z())));
    }
    // Layers from the shroud down, by depth below it.
    double deepest = 0;
    for (size_t i = 0; i < rs.size(); ++i) deepest = std::max(deepest, ch.shroudZ(rs[i]) - floor[i]);
    const int layers = std::max(1, static_cast<int>(std::ceil(deepest / opt.stepDown)));
    for (int k = 1; k <= layers; ++k) {
        // Lanes across the channel at this layer: as many as the narrowest station needs.
        std::vector<double> zs, ta, tb;
        double gA = ch.guessTheta(false, rs.front()), gB = ch.guessTheta(true, rs.front());
        int lanes = 1;
        for (size_t i = 0; i < rs.size(); ++i) {
            const double r = rs[i];
            const double z = std::max(ch.shroudZ(r) - std::min(k * opt.stepDown, deepest), floor[i]);
            gA = ch.wallTheta(false, r, z, gA);
            gB = ch.wallTheta(true, r, z, gB);
            zs.push_back(z), ta.push_back(gA), tb.push_back(gB);
            const double width = r * (gB - gA) - 2 * keep;
            lanes = std::max(lanes, 1 + static_cast<int>(std::ceil(std::max(width, 0.0) / (opt.stepOver * 2 * R))));
        }
        for (int l = 0; l < lanes; ++l) {
            const double u = lanes == 1 ? 0.5 : static_cast<double>(l) / (lanes - 1);
            std::vector<Move> pass;
            for (size_t i = 0; i < rs.size(); ++i) {
                const size_t j = l % 2 ? rs.size() - 1 - i : i;  // zig-zag
                const double r = rs[j];
                // Clear of both walls by the ball and the allowance, normal to each wall (a
                // wrapped wall meets the arc at a slant, so the arc needs more than that).
                const double lo = ta[j] + arcMargin(ch, false, r, ta[j], zs[j], keep) / r;
                const double hi = tb[j] - arcMargin(ch, true, r, tb[j], zs[j], keep) / r;
                if (hi < lo) continue;  // the channel is narrower than the ball here
                const double theta = lerp(lo, hi, u);
                const Vec3 c = ch.frame().at(r, theta, zs[j]);
                pass.push_back(check.place(c, blendedAxis(ch, r, zs[j], ta[j], tb[j], (theta - ta[j]) / (tb[j] - ta[j]))));
            }
            links.append(out, pass, check);
        }
    }
}

void finishWall(const Channel& ch, bool b, const CutterShape& cut, const PathOptions& opt, const Links& links,
                CheckResult& res, std::vector<Move>& out) {
    Checker check{ch, cut, opt, res};
    const Wall& w = ch.wall(b);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(w.face, u0, u1, v0, v1);
    // The ruling parameter: the one whose iso-lines run up the wall.
    Vec3 ruling, normal;
    double pu, pv;
    ch.wallFrame(b, w.samples[w.samples.size() / 2], ruling, normal, &pu, &pv);
    gp_Pnt q;
    gp_Vec du, dv;
    w.surface->D1(pu, pv, q, du, dv);
    const bool alongV = std::abs(dv.Normalized().Dot(gp_Vec(ch.frame().z().x(), ch.frame().z().y(), ch.frame().z().z()))) >
                        std::abs(du.Normalized().Dot(gp_Vec(ch.frame().z().x(), ch.frame().z().y(), ch.frame().z().z())));
    const double a0 = alongV ? u0 : v0, a1 = alongV ? u1 : v1;
    const double sina = std::sin(cut.taperDeg * kPi / 180), cosa = std::cos(cut.taperDeg * kPi / 180);
    std::vector<Move> pass;
    const int n = opt.stations;
    for (int i = 0; i < n; ++i) {
        const double a = lerp(a0, a1, 0.06 + 0.88 * i / (n - 1));
        gp_Pnt2d foot;
        BRepTopAdaptor_FClass2d cls(w.face, 1e-7);
        bool found = false;
        // Lowest point of this ruling on the face.
        const double b0 = alongV ? v0 : u0, b1 = alongV ? v1 : u1;
        double lowest = 1e300;
        for (int k = 0; k <= 200; ++k) {
            const double t = lerp(b0, b1, k / 200.0);
            const gp_Pnt2d uv = alongV ? gp_Pnt2d(a, t) : gp_Pnt2d(t, a);
            if (cls.Perform(uv) != TopAbs_IN) continue;
            const gp_Pnt p = w.surface->Value(uv.X(), uv.Y());
            const double z = ch.frame().axial(Vec3(p.X(), p.Y(), p.Z()));
            if (z < lowest) lowest = z, foot = uv, found = true;
        }
        if (!found) continue;
        const gp_Pnt p = w.surface->Value(foot.X(), foot.Y());
        const Vec3 P(p.X(), p.Y(), p.Z());
        ch.wallFrame(b, P, ruling, normal);
        // The cone's generator on the wall side then runs along the ruling: flank contact.
        const Vec3 axis = (cosa * ruling + sina * normal).normalized();
        const double r = ch.frame().radius(P);
        // Keep the ball at the wall's foot, clear of the hub by its radius.
        const Vec3 c = P + cut.tipRadius * normal;
        if (ch.frame().axial(c) - ch.hubZ(r) < cut.tipRadius - 1e-6) continue;
        pass.push_back(check.place(c, axis));
    }
    links.append(out, pass, check);
}

void finishHub(const Channel& ch, const CutterShape& cut, double filletRadius, const PathOptions& opt,
               const Links& links, CheckResult& res, std::vector<Move>& out) {
    Checker check{ch, cut, opt, res};
    const double R = cut.tipRadius, keep = R + filletRadius;
    const auto rs = stations(ch.rMin() + keep, ch.rMax() - keep, opt.stations);
    // Lanes across the hub between the fillets, the step at most finishStep at the narrowest.
    std::vector<double> ta, tb, zh;
    double gA = ch.guessTheta(false, rs.front()), gB = ch.guessTheta(true, rs.front());
    double widest = 0;
    for (double r : rs) {
        const double z = ch.hubZ(r) + R;
        gA = ch.wallTheta(false, r, z, gA), gB = ch.wallTheta(true, r, z, gB);
        ta.push_back(gA), tb.push_back(gB), zh.push_back(z);
        widest = std::max(widest, r * (gB - gA) - 2 * keep);
    }
    const int lanes = std::max(2, 1 + static_cast<int>(std::ceil(widest / opt.finishStep)));
    for (int l = 0; l < lanes; ++l) {
        const double u = static_cast<double>(l) / (lanes - 1);
        std::vector<Move> pass;
        for (size_t i = 0; i < rs.size(); ++i) {
            const size_t j = l % 2 ? rs.size() - 1 - i : i;
            const double r = rs[j];
            const double lo = ta[j] + arcMargin(ch, false, r, ta[j], zh[j], keep) / r;
            const double hi = tb[j] - arcMargin(ch, true, r, tb[j], zh[j], keep) / r;
            if (hi < lo) continue;
            const double theta = lerp(lo, hi, u);
            const Vec3 onHub = ch.frame().at(r, theta, ch.hubZ(r));
            const Vec3 n = ch.hubNormal(onHub);
            pass.push_back(check.place(onHub + R * n, blendedAxis(ch, r, zh[j], ta[j], tb[j], (theta - ta[j]) / (tb[j] - ta[j]))));
        }
        links.append(out, pass, check);
    }
}

// Along the root fillet of one wall: at each station the rolling ball of the fillet (the point
// the fillet radius from both the wall and the hub, found by Newton steps on the two distances),
// then the cutter's ball moved from it towards the corner until it touches the fillet.
void finishFillet(const Channel& ch, bool b, const CutterShape& cut, double filletRadius, const PathOptions& opt,
                  const Links& links, CheckResult& res, std::vector<Move>& out) {
    Checker check{ch, cut, opt, res};
    const Wall& w = ch.wall(b);
    const double R = cut.tipRadius, target = std::max(R, filletRadius);
    const double tilt = 10 * kPi / 180;
    std::vector<Move> pass;
    const auto rs = stations(w.rMin + target + 1, w.rMax - target - 1, opt.stations);
    for (size_t i = 0; i < rs.size(); ++i) {
        const double r = rs[b ? rs.size() - 1 - i : i];  // climb milling either side: A outwards, B inwards
        const double z0 = ch.hubZ(r) + target;
        Vec3 x = ch.frame().at(r, ch.wallTheta(b, r, z0, ch.guessTheta(b, r)), z0), nW, nH;
        ch.wallDistance(b, x, nW);
        x += target * nW;
        bool converged = false;
        for (int it = 0; it < 30 && !converged; ++it) {
            const double ew = target - ch.wallDistance(b, x, nW), eh = target - ch.hubDistance(x, nH);
            const double c = nW.dot(nH);
            if (1 - c * c < 1e-6) break;  // wall and hub parallel: no corner here
            x += (ew - c * eh) / (1 - c * c) * nW + (eh - c * ew) / (1 - c * c) * nH;
            converged = std::abs(ew) < 1e-7 && std::abs(eh) < 1e-7;
        }
        if (!converged) continue;
        const Vec3 centre = x - (target - R) * (nW + nH).normalized();
        Vec3 ruling, normal;
        ch.wallFrame(b, centre, ruling, normal);
        pass.push_back(check.place(centre, (std::cos(tilt) * ruling + std::sin(tilt) * normal).normalized()));
    }
    links.append(out, pass, check);
}

void merge(CheckResult& into, const CheckResult& r) {
    into.positions += r.positions;
    into.holderCollisions += r.holderCollisions;
    into.tilted += r.tilted;
    into.links += r.links;
    into.linkCollisions += r.linkCollisions;
    if (r.maxGouge > into.maxGouge) {
        into.maxGouge = r.maxGouge;
        std::copy(r.worstAt, r.worstAt + 3, into.worstAt);
    }
}

Move turnedMove(const Frame& fr, const Move& m, double angle) {
    return Move{fr.turned(m.centre, angle), fr.turnedVector(m.axis, angle), m.rapid};
}

}  // namespace

double CutterShape::radiusAt(double h) const {
    return tipRadius + std::max(h, 0.0) * std::sin(taperDeg * kPi / 180);
}

ImpellerProgram impellerToolpaths(const TopoDS_Shape& part, const impeller::ImpellerFeatures& f,
                                  const impeller::ImpellerDimensions& d, const CutterShape& rougher,
                                  const CutterShape& finisher, const PathOptions& opt) {
    return impellerToolpaths(part, f, d, RouteCutters{rougher, finisher, std::nullopt}, opt);
}

ImpellerProgram impellerToolpaths(const TopoDS_Shape& part, const impeller::ImpellerFeatures& f,
                                  const impeller::ImpellerDimensions& d, const RouteCutters& cutters,
                                  const PathOptions& opt) {
    const CutterShape& rougher = cutters.rougher;
    const CutterShape& finisher = cutters.finisher;
    if (f.blades.size() < 2) throw inputError("impeller toolpaths: the part has fewer than two blades");
    std::vector<const CutterShape*> all{&rougher, &finisher};
    if (cutters.filletBall) all.push_back(&*cutters.filletBall);
    for (const auto* c : all)
        if (!(c->tipRadius > 0) || !(c->fluteLength > c->tipRadius) || !(c->reach >= c->fluteLength) ||
            !(c->shankRadius >= c->tipRadius) || c->taperDeg < 0 || c->taperDeg >= 15 || !(c->feed > 0) || !(c->rpm > 0))
            throw inputError("impeller toolpaths: cutter " + c->id + " has impossible dimensions or cutting data");
    if (2 * rougher.tipRadius + 2 * opt.roughAllowance > d.minChannelWidth)
        throw inputError("impeller toolpaths: the roughing ball " + rougher.id + " with the allowance is wider than the "
                         "narrowest channel (" + std::to_string(d.minChannelWidth) + " mm)");
    if (cutters.filletBall && !(d.filletRadius > 0))
        throw inputError("impeller toolpaths: fillet finishing asked for a part without root fillets");
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    const int n = static_cast<int>(f.blades.size());
    const int kinds = f.splitterCount > 0 ? 2 : 1;  // channel kinds repeating about the axis
    const double pitch = 2 * kPi / f.bladeCount;
    const int channels = opt.channels > 0 ? std::min(opt.channels, n) : n;

    ImpellerProgram prog;
    Operation rough{"rough_channels", rougher, {}}, blades{"finish_blades", finisher, {}}, hub{"finish_hub", finisher, {}};
    Operation fillets{"finish_fillets", cutters.filletBall.value_or(finisher), {}};
    // Base moves by kind; kind `kinds` is the inducer (with splitters only), once per main blade.
    const int bases = kinds + (kinds == 2 ? 1 : 0);
    std::vector<std::vector<Move>> baseRough(bases), baseBlades(bases), baseHub(bases), baseFillets(bases);
    const Frame frame(f);
    // Each operation of each channel kind is independent: two threads take the next in turn,
    // roughing (the most positions) first. Each measures with a channel of its own (the distance
    // queries keep state); results are merged in a fixed order, so they do not depend on timing.
    struct Task {
        int kind, op;
        CheckResult check;
        std::exception_ptr error;
    };
    std::vector<Task> tasks;
    for (int op = 0; op < 4; ++op)
        for (int k = 0; k < bases; ++k) {
            if (op == 2 && k == kinds) continue;  // the inducer's walls are the main blades', finished whole
            if (op == 3 && (!cutters.filletBall || k == kinds)) continue;
            tasks.push_back({k, op, {}, nullptr});
        }
    // The blank is meshed here, before the threads share the part.
    const StockEnvelope stock(impeller::outerProfile(part, f, opt.blankAllowance), frame);
    auto linksFor = [&](const CutterShape& c) { return Links{stock, stock.top() + c.tipRadius + opt.safeDistance, opt.rapidClearance}; };
    const Links roughLinks = linksFor(rougher), finishLinks = linksFor(finisher);
    const Links filletLinks = linksFor(fillets.cutter);
    std::atomic<size_t> next{0};
    auto work = [&] {
        for (size_t i; (i = next++) < tasks.size();) {
            Task& t = tasks[i];
            try {
                const Channel ch = t.kind == kinds ? Channel(faces, f, 0, 2) : Channel(faces, f, t.kind);
                if (t.op == 0) roughChannel(ch, rougher, opt, roughLinks, t.check, baseRough[t.kind]);
                if (t.op == 1) finishHub(ch, finisher, d.filletRadius, opt, finishLinks, t.check, baseHub[t.kind]);
                if (t.op == 2) {
                    finishWall(ch, false, finisher, opt, finishLinks, t.check, baseBlades[t.kind]);
                    finishWall(ch, true, finisher, opt, finishLinks, t.check, baseBlades[t.kind]);
                }
                if (t.op == 3) {
                    finishFillet(ch, false, fillets.cutter, d.filletRadius, opt, filletLinks, t.check, baseFillets[t.kind]);
                    finishFillet(ch, true, fillets.cutter, d.filletRadius, opt, filletLinks, t.check, baseFillets[t.kind]);
                }
            } catch (...) {
                t.error = std::current_exception();
            }
        }
    };
    std::thread second(work);
    work();
    second.join();
    for (const Task& t : tasks) {
        if (t.error) std::rethrow_exception(t.error);
        merge(prog.check, t.check);
    }
    // The channels in angular order: channel c is its kind's base turned by its pattern step;
    // the inducer ahead of a main blade's channel follows it.
    for (int c = 0; c < channels; ++c) {
        const int kind = c % kinds;
        const double angle = (c / kinds) * pitch;
        for (auto [base, op] : {std::pair{&baseRough, &rough}, {&baseBlades, &blades}, {&baseHub, &hub}, {&baseFillets, &fillets}}) {
            for (const auto& m : (*base)[kind]) op->moves.push_back(turnedMove(frame, m, angle));
            if (kind == 0 && bases > kinds)
                for (const auto& m : (*base)[kinds]) op->moves.push_back(turnedMove(frame, m, angle));
        }
    }
    prog.operations = {rough, blades, hub};
    if (cutters.filletBall) prog.operations.push_back(fillets);
    return prog;
}

CheckResult checkProgram(const TopoDS_Shape& part, const impeller::ImpellerFeatures& f,
                         const std::vector<std::pair<CutterShape, std::vector<Move>>>& operations) {
    TopTools_IndexedMapOfShape faces;
    TopExp::MapShapes(part, TopAbs_FACE, faces);
    std::vector<TopoDS_Face> obstacles;
    for (const auto& b : f.blades) {
        for (int w : b.walls) obstacles.push_back(TopoDS::Face(faces(w)));
        for (int w : b.fillets) obstacles.push_back(TopoDS::Face(faces(w)));
        obstacles.push_back(TopoDS::Face(faces(b.shroud)));
    }
    const Handle(Geom_Surface) hub = BRep_Tool::Surface(TopoDS::Face(faces(f.hub)));
    // The cutting positions in program order, measured on two threads, each half with distance
    // queries of its own (they keep state); the halves merge in order, as one thread would.
    std::vector<std::pair<const CutterShape*, const Move*>> cuts;
    for (const auto& [cutter, moves] : operations)
        for (const auto& m : moves)
            if (!m.rapid) cuts.push_back({&cutter, &m});
    CheckResult half[2];
    std::exception_ptr error[2];
    auto work = [&](int part) {
        try {
            const Obstacles o(obstacles, hub);
            CheckResult& r = half[part];
            const size_t from = part == 0 ? 0 : cuts.size() / 2, to = part == 0 ? cuts.size() / 2 : cuts.size();
            for (size_t i = from; i < to; ++i) {
                const Move& m = *cuts[i].second;
                const Clearance c = clearance(o, *cuts[i].first, m.centre, m.axis);
                ++r.positions;
                if (c.holder) ++r.holderCollisions;
                if (c.gouge > r.maxGouge) {
                    r.maxGouge = c.gouge;
                    r.worstAt[0] = m.centre.x(), r.worstAt[1] = m.centre.y(), r.worstAt[2] = m.centre.z();
                }
            }
        } catch (...) {
            error[part] = std::current_exception();
        }
    };
    std::thread second(work, 1);
    work(0);
    second.join();
    CheckResult r;
    for (int i = 0; i < 2; ++i) {
        if (error[i]) std::rethrow_exception(error[i]);
        merge(r, half[i]);
    }
    return r;
}

CheckResult checkRapids(const impeller::BlankProfile& blank, const impeller::ImpellerFeatures& f,
                        const std::vector<std::pair<CutterShape, std::vector<Move>>>& operations, double clearance) {
    const StockEnvelope stock(blank, Frame(f));
    CheckResult r;
    for (const auto& [cutter, moves] : operations)
        for (size_t i = 0; i < moves.size(); ++i) {
            if (!moves[i].rapid) continue;
            // The first move after a tool change starts from the tool change position: only its end counts.
            const Move& from = i > 0 ? moves[i - 1] : moves[i];
            ++r.links;
            r.linkCollisions += rapidClearance(stock, cutter, from, moves[i]) < clearance;
        }
    return r;
}

kinematics::ClProgram toClProgram(const ImpellerProgram& p, const std::string& name) {
    using namespace kinematics;
    ClProgram cl;
    cl.name = name;
    auto add = [&](ClRecord r) {
        r.op = static_cast<int>(cl.operations.size()) - 1;
        cl.records.push_back(r);
    };
    for (const auto& op : p.operations) {
        cl.operations.push_back({op.name});
        ClRecord label;
        label.kind = ClKind::Operation;
        label.text = op.name;
        add(label);
        ClRecord tool;
        tool.kind = ClKind::LoadTool;
        tool.tool = ClTool{op.cutter.number, op.cutter.id, 2 * op.cutter.tipRadius,
                           op.cutter.flat ? 0.0 : op.cutter.tipRadius, 0.0};
        add(tool);
        ClRecord spindle;
        spindle.kind = ClKind::Spindle;
        spindle.rpm = op.cutter.rpm;
        spindle.spindleDir = 1;
        add(spindle);
        ClRecord coolant;
        coolant.kind = ClKind::Coolant;
        coolant.text = "flood";
        add(coolant);
        for (const auto& m : op.moves) {
            ClRecord r;
            r.kind = ClKind::Move;
            r.motion = m.rapid ? Motion::Rapid : Motion::Linear;
            r.axis = m.axis.normalized();
            r.tip = m.centre - op.cutter.tipRadius * r.axis;
            r.feed = m.rapid ? 0.0 : op.cutter.feed;
            add(r);
        }
    }
    return cl;
}

std::vector<std::pair<CutterShape, std::vector<Move>>> movesOf(const kinematics::ClProgram& cl,
                                                               const std::vector<CutterShape>& cutters) {
    using namespace kinematics;
    std::vector<std::pair<CutterShape, std::vector<Move>>> out;
    const CutterShape* current = nullptr;
    int op = -2;
    for (const auto& r : cl.records) {
        if (r.kind == ClKind::LoadTool) {
            current = nullptr;
            for (const auto& c : cutters)
                if (c.number == r.tool.number) current = &c;
            if (!current) throw inputError("impeller program: tool " + std::to_string(r.tool.number) + " is not one of its cutters");
        }
        if (r.kind != ClKind::Move) continue;
        if (!current) throw inputError("impeller program: a move before any tool is loaded (" + cl.where(r) + ")");
        if (r.op != op || out.empty() || out.back().first.number != current->number) {
            out.push_back({*current, {}});
            op = r.op;
        }
        const Vec3 axis = r.axis.normalized();
        out.back().second.push_back(Move{r.tip + current->tipRadius * axis, axis, r.motion == Motion::Rapid});
    }
    return out;
}

}  // namespace aeronc::impellerpath
