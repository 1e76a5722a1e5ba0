// Inverse kinematics of the tool orientation: two rotations about known axes that take one
// direction onto another (the Paden-Kahan subproblem 2), for any placement of the two rotary
// axes on the table or the head.
#include <aeronc/kinematics/Kinematics.h>

namespace aeronc::kinematics {

namespace {

// Angle (rad) of the rotation about unit w that takes x onto y, when both have the same
// component along w. Sets `free` when x lies on w: every angle does.
double rotationAbout(const Vec3& w, const Vec3& x, const Vec3& y, bool& free) {
    const Vec3 xp = x - w * w.dot(x), yp = y - w * w.dot(y);
    free = xp.norm() < kPoleTolerance || yp.norm() < kPoleTolerance;
    if (free) return 0.0;
    return std::atan2(w.dot(xp.cross(yp)), xp.dot(yp));
}

Mat3 rot(const Vec3& w, double rad) { return Eigen::AngleAxisd(rad, w).toRotationMatrix(); }

double wrap180(double deg) {
    double a = std::remainder(deg, 360.0);  // [-180, 180]
    if (a <= -180.0) a += 360.0;
    return a;
}

}  // namespace

std::vector<RotarySolution> Kinematics::orientations(const Vec3& axisIn, const std::array<double, 2>& keep) const {
    const Vec3 u = axisIn.normalized();
    const Vec3& t0 = model_.toolDirection;
    // Write the orientation equation as  exp(w1 th1) exp(w2 th2) p = q, with the joint of
    // each theta and the sign between them.
    int j1, j2;
    double s1 = 1.0;  // joint(j1) = s1 * th1
    Vec3 p, q;
    if (headAxes_.empty()) {  // R_outer R_inner u = t0
        j1 = tableAxes_[0], j2 = tableAxes_[1], p = u, q = t0;
    } else if (tableAxes_.empty()) {  // R_outer R_inner t0 = u
        j1 = headAxes_[0], j2 = headAxes_[1], p = t0, q = u;
    } else {  // R_table^-1 R_head t0 = u
        j1 = tableAxes_[0], j2 = headAxes_[0], p = t0, q = u, s1 = -1.0;
    }
    const Vec3& w1 = model_.rotary[j1].direction;
    const Vec3& w2 = model_.rotary[j2].direction;
    const double keep1 = toRadians(keep[j1]) * s1, keep2 = toRadians(keep[j2]);

    std::array<std::array<double, 2>, 2> thetas;  // (th1, th2) in rad
    int count = 0;
    std::array<bool, 2> freeFlag{false, false};
    const bool free2 = w2.cross(p).norm() < kPoleTolerance;
    const bool free1 = w1.cross(q).norm() < kPoleTolerance;
    const double reach = 1e-9;  // tolerance of the reachability tests (unit vectors)
    if (free1 || free2) {
        double th1 = keep1, th2 = keep2;
        bool f = false;
        if (free2 && !free1) {
            if (std::abs(w1.dot(p) - w1.dot(q)) > reach) return {};
            th1 = rotationAbout(w1, p, q, f);
        } else if (free1 && !free2) {
            const Vec3 z = rot(w1, -th1) * q;
            if (std::abs(w2.dot(p) - w2.dot(z)) > reach) return {};
            th2 = rotationAbout(w2, p, z, f);
        } else if ((p - q).norm() > reach && (rot(w1, th1) * rot(w2, th2) * p - q).norm() > reach) {
            return {};
        }
        freeFlag[0] = free1, freeFlag[1] = free2;
        thetas[count++] = {th1, th2};
    } else {
        const double c = w1.dot(w2);
        const double den = c * c - 1.0;  // non-zero: the axes are not parallel
        const double alpha = (c * w2.dot(p) - w1.dot(q)) / den;
        const double beta = (c * w1.dot(q) - w2.dot(p)) / den;
        const Vec3 w12 = w1.cross(w2);
        const double g2 = (p.squaredNorm() - alpha * alpha - beta * beta - 2 * alpha * beta * c) / w12.squaredNorm();
        if (g2 < -reach) return {};
        const double g = std::sqrt(std::max(0.0, g2));
        const int n = g > 1e-12 ? 2 : 1;
        for (int k = 0; k < n; ++k) {
            const Vec3 z = alpha * w1 + beta * w2 + (k == 0 ? g : -g) * w12;
            bool fa = false, fb = false;
            const double th2 = rotationAbout(w2, p, z, fb);
            const double th1 = rotationAbout(w1, z, q, fa);
            thetas[count++] = {th1, th2};
        }
    }
    std::vector<RotarySolution> out;
    out.reserve(count);
    for (int k = 0; k < count; ++k) {
        const auto& th = thetas[k];
        RotarySolution s;
        s.angles[j1] = wrap180(toDegrees(s1 * th[0]));
        s.angles[j2] = wrap180(toDegrees(th[1]));
        s.free[j1] = freeFlag[0];
        s.free[j2] = freeFlag[1];
        if (s.free[j1]) s.angles[j1] = keep[j1];  // keep exactly, winding included
        if (s.free[j2]) s.angles[j2] = keep[j2];
        out.push_back(s);
    }
    return out;
}

}  // namespace aeronc::kinematics
