#include <aeronc/verify/SweptSegment.h>

#include <algorithm>
#include <cmath>

namespace aeronc::verify {

namespace {
constexpr double plungeLength = 1e-9;  // a projection this short is a plunge
}

SweptSegment::SweptSegment(double x0, double y0, double w0, double x1, double y1, double w1)
    : x0_(x0), y0_(y0), w0_(w0), x1_(x1), y1_(y1), w1_(w1) {
    const double dx = x1 - x0, dy = y1 - y0;
    length_ = std::hypot(dx, dy);
    if (length_ > plungeLength) {
        ux_ = dx / length_, uy_ = dy / length_;
        slope_ = (w1 - w0) / length_;
    } else {
        length_ = 0;
    }
}

namespace {
inline double norm2d(double a, double b) { return std::sqrt(a * a + b * b); }
}  // namespace

double SweptSegment::distance(double x, double y) const {
    const double px = x - x0_, py = y - y0_;
    if (length_ == 0) return norm2d(px, py);
    const double along = std::clamp(px * ux_ + py * uy_, 0.0, length_);
    return norm2d(px - along * ux_, py - along * uy_);
}

// The lowest point over (x, y) of the capsule the ball's centre sweeps: the lower meeting of the
// vertical line with the cylinder about the centre's path, if it falls between the ends, else
// with the sphere at either end.
double SweptSegment::ballEnvelope(double R, double x, double y) const {
    double best = HUGE_VAL;
    auto sphere = [&](double cx, double cy, double cw) {
        const double d2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
        if (d2 <= R * R) best = std::min(best, cw + R - std::sqrt(R * R - d2));
    };
    sphere(x0_, y0_, w0_);
    sphere(x1_, y1_, w1_);
    const double dw = w1_ - w0_, len3 = std::sqrt(length_ * length_ + dw * dw);
    const double ux = ux_ * length_ / len3, uy = uy_ * length_ / len3, uw = dw / len3;
    const double a = x - x0_, b = y - y0_, k = a * ux + b * uy;
    // |D|^2 - (D.u)^2 = R^2 for D = (a, b, o), o the height above the start's centre.
    const double A = 1 - uw * uw, B = -2 * uw * k, C = a * a + b * b - k * k - R * R;
    const double disc = B * B - 4 * A * C;
    if (disc < 0) return best;
    const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
    const double r1 = q / A, r2 = q != 0 ? C / q : r1;
    const double o = std::min(r1, r2);
    const double t = (k + o * uw) / len3;  // where along the path the foot lies
    if (t >= 0 && t <= 1) best = std::min(best, w0_ + R + o);
    return best;
}

double SweptSegment::envelope(const Cutter& cutter, double x, double y) const {
    const double R = cutter.radius;
    const double px = x - x0_, py = y - y0_;
    if (length_ == 0) {
        const double d = norm2d(px, py);
        return d <= R ? std::min(w0_, w1_) + cutter.height(d) : HUGE_VAL;
    }
    const double a = px * ux_ + py * uy_;         // along the projection
    const double p = std::abs(px * uy_ - py * ux_);  // across it
    if (p > R) return HUGE_VAL;
    const double half = std::sqrt(R * R - p * p);
    double lo = std::max(0.0, a - half), hi = std::min(length_, a + half);
    if (lo > hi) return HUGE_VAL;
    auto dist = [&](double s) { return norm2d(s - a, p); };
    double s;
    if (slope_ == 0) {
        s = std::clamp(a, lo, hi);
    } else if (cutter.cornerRadius == R && std::abs(slope_) < 1e4) {
        return ballEnvelope(R, x, y);
    } else {
        // Along the segment the envelope is w0 + slope s + height(d(s)): convex in s (height is
        // convex and non-decreasing in d, d convex in s), so its slope changes sign once: Newton
        // on the slope, kept inside a shrinking bracket, bisecting when a step leaves it.
        auto derivatives = [&](double t, double& g, double& gp) {
            const double d = dist(t), r = std::min(d, R);
            if (d <= 0) {
                g = slope_, gp = cutter.curvature(0);
                return;
            }
            const double c = (t - a) / d, sl = cutter.slope(r);
            g = slope_ + sl * c;
            gp = cutter.curvature(r) * c * c + sl * p * p / (d * d * d);
        };
        double g, gp;
        derivatives(lo, g, gp);
        if (g >= 0) {
            s = lo;
        } else {
            derivatives(hi, g, gp);
            if (g <= 0) {
                s = hi;
            } else {
                s = std::clamp(a, lo, hi);
                for (int k = 0; k < 60 && hi - lo > 1e-9; ++k) {
                    derivatives(s, g, gp);
                    if (g == 0) break;
                    (g < 0 ? lo : hi) = s;
                    const double next = gp > 0 ? s - g / gp : lo - 1;
                    if (!(next > lo && next < hi)) {
                        s = 0.5 * (lo + hi);
                        continue;
                    }
                    const bool converged = std::abs(next - s) < 1e-10;
                    s = next;
                    if (converged) break;
                }
            }
        }
    }
    return w0_ + slope_ * s + cutter.height(std::min(dist(s), R));
}

bool SweptSegment::rowSpan(double y, double reach, double& xa, double& xb) const {
    xa = HUGE_VAL, xb = -HUGE_VAL;
    auto disc = [&](double cx, double cy) {
        const double dy = y - cy;
        if (std::abs(dy) > reach) return;
        const double w = std::sqrt(reach * reach - dy * dy);
        xa = std::min(xa, cx - w), xb = std::max(xb, cx + w);
    };
    disc(x0_, y0_);
    disc(x1_, y1_);
    if (length_ > 0) {
        // The band swept by the disc: |across| <= reach and 0 <= along <= length, both linear in x.
        double lo = -HUGE_VAL, hi = HUGE_VAL;
        auto constrain = [&](double slope, double offset, double from, double to) {
            if (std::abs(slope) < 1e-12) {
                if (offset < from || offset > to) lo = HUGE_VAL;
                return;
            }
            const double t1 = (from - offset) / slope, t2 = (to - offset) / slope;
            lo = std::max(lo, std::min(t1, t2)), hi = std::min(hi, std::max(t1, t2));
        };
        const double dy = y - y0_;
        constrain(-uy_, dy * ux_, -reach, reach);  // across = -(x - x0) uy + dy ux
        constrain(ux_, dy * uy_, 0, length_);     // along = (x - x0) ux + dy uy
        if (lo <= hi) xa = std::min(xa, x0_ + lo), xb = std::max(xb, x0_ + hi);
    }
    return xa <= xb;
}

}  // namespace aeronc::verify
