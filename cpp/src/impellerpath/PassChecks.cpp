// The checks made while the passes are made (see PassChecks.h).
#include "PassChecks.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace aeronc::impellerpath {

namespace {

// Axis turned by `deg` about `about` (unit).
Vec3 tilted(const Vec3& axis, const Vec3& about, double deg) {
    return (Eigen::AngleAxisd(deg * kPi / 180, about) * axis).normalized();
}

}  // namespace

Move Checker::place(Vec3 centre, Vec3 axis) {
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
    lastSafe_ = !c.holder && c.gouge <= kGougeLeaveOut;
    if (!leavingOut_ || lastSafe_) record(c, centre);
    return Move{centre, axis, false};
}

void Checker::add(std::vector<Move>& pass, Vec3 centre, Vec3 axis, const Links& links, std::vector<Move>& out) {
    leavingOut_ = true;
    const Move m = place(centre, axis);
    leavingOut_ = false;
    if (lastSafe_) {
        pass.push_back(m);
        return;
    }
    ++result.leftOut;
    links.append(out, pass, *this);
    pass.clear();
}

void Checker::tally(const Move& m) { record(clearance(ch.obstacles(), cutter, m.centre, m.axis), m.centre); }

void Checker::record(const Clearance& c, const Vec3& centre) {
    ++result.positions;
    if (c.holder) ++result.holderCollisions;
    result.minHolderGap = std::min(result.minHolderGap, c.holderGap);
    if (c.gouge > result.maxGouge) {
        result.maxGouge = c.gouge;
        result.worstAt[0] = centre.x(), result.worstAt[1] = centre.y(), result.worstAt[2] = centre.z();
    }
}

Move Links::outside(const Move& m, const CutterShape& c) const {
    double t = 0;
    while (t < 500 && stock.clearance(c, m.centre + t * m.axis, m.axis) < clearance) t += 0.5;
    return Move{m.centre + t * m.axis, m.axis, false};
}

Move Links::onPlane(const Move& m, const Frame& fr) const {
    const double up = plane - fr.axial(m.centre);
    return Move{m.centre + std::max(up, 0.0) / std::max(0.2, m.axis.dot(fr.z())) * m.axis, m.axis, true};
}

bool Links::feedTouches(const Move& cutting, const Move& above, const Checker& check) const {
    CutterShape longer = check.cutter;
    longer.reach += (above.centre - cutting.centre).norm();
    // Flutes wider than the shank sweep up through where the shank was.
    longer.shankRadius = std::max(longer.shankRadius, longer.radiusAt(longer.fluteLength - longer.tipRadius));
    const Clearance k = impellerpath::clearance(check.ch.obstacles(), longer, cutting.centre, cutting.axis);
    return k.gouge > kGougeAim || k.holder;
}

void Links::checkFeed(const Move& cutting, const Move& above, Checker& check) const {
    ++check.result.links;
    check.result.linkCollisions += feedTouches(cutting, above, check);
}

void Links::checkRapid(const Move& a, const Move& b, Checker& check) const {
    ++check.result.links;
    check.result.linkCollisions += rapidClearance(stock, check.cutter, a, b) < 0;
}

void Links::append(std::vector<Move>& out, const std::vector<Move>& whole, Checker& check) const {
    // A pass cannot start or end where the tool, moving out along its axis, would touch the part
    // (a tilted tool deep in a narrow channel): such end positions are left out.
    size_t first = 0, last = whole.size();
    while (first < last && feedTouches(whole[first], outside(whole[first], check.cutter), check)) ++first, ++check.result.leftOut;
    while (last > first && feedTouches(whole[last - 1], outside(whole[last - 1], check.cutter), check))
        --last, ++check.result.leftOut;
    const std::vector<Move> pass(whole.begin() + first, whole.begin() + last);
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

void placeTurned(const std::vector<Move>& linked, double angle, Checker& check, const Links& links,
                 std::vector<Move>& out) {
    const Frame& fr = check.ch.frame();
    for (size_t i = 0; i < linked.size();) {
        if (linked[i].rapid) {
            ++i;
            continue;
        }
        size_t end = i;
        while (end < linked.size() && !linked[end].rapid) ++end;
        // [i, end): the pass's cutting positions, then its exit (rebuilt by append).
        std::vector<Move> pass;
        for (size_t k = i; k + 1 < end; ++k)
            check.add(pass, fr.turned(linked[k].centre, angle), fr.turnedVector(linked[k].axis, angle), links, out);
        links.append(out, pass, check);
        i = end;
    }
}

void merge(CheckResult& into, const CheckResult& r) {
    into.positions += r.positions;
    into.holderCollisions += r.holderCollisions;
    into.tilted += r.tilted;
    into.links += r.links;
    into.linkCollisions += r.linkCollisions;
    into.minHolderGap = std::min(into.minHolderGap, r.minHolderGap);
    into.leftOut += r.leftOut;
    if (r.maxGouge > into.maxGouge) {
        into.maxGouge = r.maxGouge;
        std::copy(r.worstAt, r.worstAt + 3, into.worstAt);
    }
}

}  // namespace aeronc::impellerpath
