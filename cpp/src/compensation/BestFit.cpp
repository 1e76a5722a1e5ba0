#include <aeronc/compensation/BestFit.h>

#include <Eigen/SVD>

#include <sstream>

namespace aeronc::compensation {

namespace {

Eigen::Matrix3Xd columns(const std::vector<Vec3>& points) {
    Eigen::Matrix3Xd m(3, points.size());
    for (size_t i = 0; i < points.size(); ++i) m.col(static_cast<Eigen::Index>(i)) = points[i];
    return m;
}

SimilarityTransform fit(const std::vector<Vec3>& from, const std::vector<Vec3>& to, bool scaling) {
    if (from.size() != to.size()) throw compensationError("best fit: as many measured as nominal points are needed");
    requireThreeDimensionalFit(from, "the datum holes");
    const Mat4 t = Eigen::umeyama(columns(from), columns(to), scaling);
    SimilarityTransform s;
    const Mat3 sr = t.topLeftCorner<3, 3>();
    s.scale = scaling ? std::cbrt(sr.determinant()) : 1.0;
    s.rotation = sr / s.scale;
    s.translation = t.topRightCorner<3, 1>();
    return s;
}

}  // namespace

Mat4 SimilarityTransform::matrix() const {
    Mat4 m = Mat4::Identity();
    m.topLeftCorner<3, 3>() = scale * rotation;
    m.topRightCorner<3, 1>() = translation;
    return m;
}

void requireThreeDimensionalFit(const std::vector<Vec3>& points, const std::string& what) {
    if (points.size() < 3) {
        std::ostringstream os;
        os << "a 3-D fit needs at least three datum holes not on one line; " << what << " are " << points.size();
        throw compensationError(os.str());
    }
    Vec3 centre = Vec3::Zero();
    for (const auto& p : points) centre += p;
    centre /= static_cast<double>(points.size());
    Eigen::Matrix3Xd c = columns(points).colwise() - centre;
    Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(c, Eigen::ComputeFullU);
    const Vec3 along = svd.matrixU().col(0);
    double extent = 0.0, off = 0.0;
    for (Eigen::Index i = 0; i < c.cols(); ++i) {
        const double t = c.col(i).dot(along);
        extent = std::max(extent, std::abs(t));
        off = std::max(off, (c.col(i) - t * along).norm());
    }
    if (!(off > 1e-3 * 2.0 * extent)) {
        std::ostringstream os;
        os << "collinear datum holes: " << what << " lie on one line (within " << off
           << " mm), so a 3-D fit cannot fix the rotation about it; add a datum hole off that line or use the "
              "seed's method";
        throw compensationError(os.str());
    }
}

SimilarityTransform fitRigid(const std::vector<Vec3>& from, const std::vector<Vec3>& to) { return fit(from, to, false); }

SimilarityTransform fitSimilarity(const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
    return fit(from, to, true);
}

}  // namespace aeronc::compensation
