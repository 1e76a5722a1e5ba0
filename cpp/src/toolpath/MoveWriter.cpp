#include "MoveWriter.h"

#include <cmath>

namespace aeronc::toolpath {

void MoveWriter::add(Move::Kind kind, double u, double v, double h) {
    const double d = std::sqrt((u - u_) * (u - u_) + (v - v_) * (v - v_) + (h - h_) * (h - h_));
    if (started_ && d < 1e-9) return;
    if (started_) (kind == Move::Kind::Rapid ? path_.rapidLength : path_.cutLength) += d;
    path_.moves.push_back({kind, u, v, h});
    started_ = true;
    u_ = u, v_ = v, h_ = h;
}

void MoveWriter::drill(double u, double v, double bottom, double r, double q, double dwell) {
    if (started_) path_.rapidLength += std::abs(h_ - r);  // down to the R plane
    const double depth = r - bottom;
    path_.cutLength += depth;
    path_.rapidLength += depth;  // the final retract
    if (q > 0)                   // G83: out to R and back in after each peck but the last
        for (double reached = q; reached < depth - 1e-9; reached += q) path_.rapidLength += 2 * reached;
    Move m{Move::Kind::Drill, u, v, bottom};
    m.r = r, m.q = q, m.dwell = dwell;
    path_.moves.push_back(m);
    started_ = true;
    u_ = u, v_ = v, h_ = r;
}

void MoveWriter::rapidOver(const Point& p, double clearance, double h) {
    if (started_ && std::hypot(p[0] - u_, p[1] - v_) < 1e-9 && h <= h_) {
        rapid(p[0], p[1], h);
        return;
    }
    if (started_ && h_ < clearance) rapid(u_, v_, clearance);
    rapid(p[0], p[1], started_ ? std::max(h_, clearance) : clearance);
    rapid(p[0], p[1], h);
}

void MoveWriter::retract(double h) {
    if (started_ && h_ < h) rapid(u_, v_, h);
}

}  // namespace aeronc::toolpath
