#pragma once
// What is left after the best fit, interpolated from the datum holes to any point: inverse
// distance weighting or a thin-plate spline. Both pass exactly through the datum values.
#include <aeronc/compensation/Types.h>

#include <vector>

namespace aeronc::compensation {

// Shepard's weighting: sum(w_i r_i) / sum(w_i), w_i = 1 / d_i^power.
class InverseDistanceField {
public:
    InverseDistanceField(std::vector<Vec3> points, std::vector<Vec3> values, double power = 2.0);
    Vec3 at(const Vec3& p) const;

private:
    std::vector<Vec3> points_, values_;
    double power_;
};

// A thin-plate spline (kernel r^2 log r plus an affine part) in the best-fit plane of the datum
// holes: a skin is a surface, and its holes seen along the plane's normal spread over two
// dimensions. Needs three datum holes not on one line.
class ThinPlateSpline {
public:
    ThinPlateSpline(const std::vector<Vec3>& points, const std::vector<Vec3>& values);
    Vec3 at(const Vec3& p) const;
    // at() for many points at once (the kernel evaluated in vectorised blocks); adds to `out`.
    void addAt(const std::vector<Vec3>& points, std::vector<Vec3>& out) const;

private:
    Eigen::Vector2d planar(const Vec3& p) const;

    Vec3 origin_;
    Eigen::Matrix<double, 3, 2> basis_;  // columns: the plane's two directions, scaled
    std::vector<Eigen::Vector2d> nodes_;
    Eigen::ArrayXd nodeU_, nodeV_;
    std::vector<Vec3> weights_;  // kernel weight per datum hole
    Eigen::MatrixX3d halfWeights_;  // half the kernel weights, a column per coordinate
    Vec3 constant_, alongU_, alongV_;  // the affine part
};

}  // namespace aeronc::compensation
