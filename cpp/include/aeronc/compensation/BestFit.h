#pragma once
// Best-fit rigid and similarity transforms between the nominal and the measured datum holes
// (Umeyama's least-squares method, Eigen::umeyama).
#include <aeronc/compensation/Types.h>

#include <vector>

namespace aeronc::compensation {

// x -> scale * rotation * x + translation
struct SimilarityTransform {
    Mat3 rotation = Mat3::Identity();
    double scale = 1.0;
    Vec3 translation = Vec3::Zero();

    Vec3 apply(const Vec3& x) const { return scale * (rotation * x) + translation; }
    Mat4 matrix() const;
};

// Both throw unless there are at least three points and they are not on one line (a rotation
// about that line would be undetermined): "collinear" means every point lies within
// 1e-3 x (the points' extent) of their best-fit line.
SimilarityTransform fitRigid(const std::vector<Vec3>& from, const std::vector<Vec3>& to);
SimilarityTransform fitSimilarity(const std::vector<Vec3>& from, const std::vector<Vec3>& to);

// Throws the fits' error for points that do not fix a 3-D transform; `what` names them.
void requireThreeDimensionalFit(const std::vector<Vec3>& points, const std::string& what);

}  // namespace aeronc::compensation
