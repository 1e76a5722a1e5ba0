#include <aeronc/compensation/BestFit.h>
#include <aeronc/compensation/ResidualField.h>

#include <Eigen/LU>
#include <Eigen/SVD>

#include <cmath>

namespace aeronc::compensation {

InverseDistanceField::InverseDistanceField(std::vector<Vec3> points, std::vector<Vec3> values, double power)
    : points_(std::move(points)), values_(std::move(values)), power_(power) {
    if (points_.empty() || points_.size() != values_.size())
        throw compensationError("inverse distance weighting needs one value per datum hole");
}

Vec3 InverseDistanceField::at(const Vec3& p) const {
    Vec3 sum = Vec3::Zero();
    double weights = 0.0;
    for (size_t i = 0; i < points_.size(); ++i) {
        const double d2 = (p - points_[i]).squaredNorm();
        if (d2 < 1e-24) return values_[i];  // on a datum hole: its own value
        const double w = power_ == 2.0 ? 1.0 / d2 : std::pow(d2, -0.5 * power_);
        sum += w * values_[i];
        weights += w;
    }
    return sum / weights;
}

namespace {

// r^2 log r, written with r^2 (no square root); 0 at r = 0.
double kernel(double r2) { return r2 > 0.0 ? 0.5 * r2 * std::log(r2) : 0.0; }

}  // namespace

ThinPlateSpline::ThinPlateSpline(const std::vector<Vec3>& points, const std::vector<Vec3>& values) {
    if (points.size() != values.size()) throw compensationError("a thin-plate spline needs one value per datum hole");
    requireThreeDimensionalFit(points, "the datum holes");
    const auto n = static_cast<Eigen::Index>(points.size());
    origin_ = Vec3::Zero();
    for (const auto& p : points) origin_ += p;
    origin_ /= static_cast<double>(n);
    Eigen::Matrix3Xd c(3, n);
    for (Eigen::Index i = 0; i < n; ++i) c.col(i) = points[static_cast<size_t>(i)] - origin_;
    Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(c, Eigen::ComputeFullU);
    double extent = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) extent = std::max(extent, c.col(i).norm());
    // Unit-sized plane coordinates keep the system well conditioned whatever the part's size.
    basis_ = svd.matrixU().leftCols<2>() / extent;
    nodes_.reserve(points.size());
    for (const auto& p : points) nodes_.push_back(planar(p));

    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n + 3, n + 3);
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n + 3, 3);
    for (Eigen::Index i = 0; i < n; ++i) {
        const auto& qi = nodes_[static_cast<size_t>(i)];
        for (Eigen::Index j = 0; j < i; ++j) a(i, j) = a(j, i) = kernel((qi - nodes_[static_cast<size_t>(j)]).squaredNorm());
        a(i, n) = a(n, i) = 1.0;
        a(i, n + 1) = a(n + 1, i) = qi.x();
        a(i, n + 2) = a(n + 2, i) = qi.y();
        rhs.row(i) = values[static_cast<size_t>(i)].transpose();
    }
    // Three points not on one line make the system regular unless two nodes coincide.
    for (size_t i = 0; i < nodes_.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if ((nodes_[i] - nodes_[j]).squaredNorm() < 1e-18)
                throw compensationError("thin-plate spline: two datum holes are at the same place (seen along the skin's normal)");
    const Eigen::MatrixXd w = Eigen::PartialPivLU<Eigen::MatrixXd>(a).solve(rhs);
    if (!w.allFinite()) throw compensationError("thin-plate spline: the datum holes give a singular system");
    for (Eigen::Index i = 0; i < n; ++i) weights_.push_back(w.row(i).transpose());
    halfWeights_ = 0.5 * w.topRows(n);
    nodeU_.resize(n);
    nodeV_.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) nodeU_[i] = nodes_[static_cast<size_t>(i)].x(), nodeV_[i] = nodes_[static_cast<size_t>(i)].y();
    constant_ = w.row(n).transpose();
    alongU_ = w.row(n + 1).transpose();
    alongV_ = w.row(n + 2).transpose();
}

Eigen::Vector2d ThinPlateSpline::planar(const Vec3& p) const { return basis_.transpose() * (p - origin_); }

Vec3 ThinPlateSpline::at(const Vec3& p) const {
    const Eigen::Vector2d q = planar(p);
    Vec3 v = constant_ + q.x() * alongU_ + q.y() * alongV_;
    for (size_t i = 0; i < nodes_.size(); ++i) v += kernel((q - nodes_[i]).squaredNorm()) * weights_[i];
    return v;
}

void ThinPlateSpline::addAt(const std::vector<Vec3>& points, std::vector<Vec3>& out) const {
    constexpr Eigen::Index kBlock = 256;
    const Eigen::Index n = nodeU_.size();
    Eigen::ArrayXXd k(n, kBlock);
    for (size_t start = 0; start < points.size(); start += kBlock) {
        const auto count = static_cast<Eigen::Index>(std::min<size_t>(kBlock, points.size() - start));
        Eigen::Matrix2Xd q(2, count);
        for (Eigen::Index j = 0; j < count; ++j) q.col(j) = planar(points[start + static_cast<size_t>(j)]);
        for (Eigen::Index j = 0; j < count; ++j)
            k.col(j) = (nodeU_ - q(0, j)).square() + (nodeV_ - q(1, j)).square();
        // r^2 log r = 0.5 r^2 log r^2 (the 0.5 is in halfWeights_); at a node (r = 0) the
        // product is 0 x finite = 0.
        auto block = k.leftCols(count);
        block *= block.max(1e-300).log();
        // Three dot products per point over contiguous columns: a general matrix product with
        // three rows spends more on packing than on arithmetic.
        for (Eigen::Index j = 0; j < count; ++j) {
            const auto i = start + static_cast<size_t>(j);
            const auto kj = block.col(j).matrix();
            out[i] += Vec3(halfWeights_.col(0).dot(kj), halfWeights_.col(1).dot(kj), halfWeights_.col(2).dot(kj)) +
                      constant_ + q(0, j) * alongU_ + q(1, j) * alongV_;
        }
    }
}

}  // namespace aeronc::compensation
