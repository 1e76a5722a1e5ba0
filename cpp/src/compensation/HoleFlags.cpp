#include <aeronc/compensation/HoleFlags.h>

#include "NearestGrid.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace aeronc::compensation {

std::string flagKindName(FlagKind kind) {
    switch (kind) {
        case FlagKind::DatumLeftOut: return "datum left out";
        case FlagKind::DatumLeftOutByHand: return "datum left out by hand";
        case FlagKind::DatumPutBack: return "datum put back";
        case FlagKind::DatumOutOfLineUsed: return "datum out of line, used";
        case FlagKind::AgainstNeighbours: return "against neighbours";
        case FlagKind::BeyondTolerance: return "beyond tolerance";
    }
    return "?";
}

std::vector<double> neighbourDepartures(const std::vector<Vec3>& positions, const std::vector<Vec3>& corrections,
                                        int neighbours) {
    if (positions.size() != corrections.size())
        throw compensationError("neighbour check: one correction per hole is needed");
    std::vector<double> out(positions.size(), 0.0);
    if (positions.size() < 3 || neighbours < 2) return out;
    const NearestGrid grid(positions);
    std::vector<std::pair<double, int>> near;
    for (size_t i = 0; i < positions.size(); ++i) {
        grid.nearest(static_cast<int>(i), neighbours, near);
        if (near.size() < 2) continue;
        // The neighbours' own directions: their plane, or their line when they lie on one.
        Vec3 mean = Vec3::Zero();
        for (const auto& [d2, k] : near) mean += positions[static_cast<size_t>(k)] - positions[i];
        mean /= static_cast<double>(near.size());
        Mat3 spread = Mat3::Zero();
        for (const auto& [d2, k] : near) {
            const Vec3 d = positions[static_cast<size_t>(k)] - positions[i] - mean;
            spread += d * d.transpose();
        }
        Eigen::SelfAdjointEigenSolver<Mat3> eig;
        eig.computeDirect(spread);
        const Vec3 along = eig.eigenvectors().col(2), across = eig.eigenvectors().col(1);
        const bool flat = eig.eigenvalues()(1) > 1e-6 * eig.eigenvalues()(2);
        // Least squares c = a + b u (+ c v) over the neighbours, in offsets from hole i: a is the
        // trend at the hole.
        const int unknowns = flat ? 3 : 2;
        Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
        Eigen::Matrix3d rhs = Eigen::Matrix3d::Zero();  // a column per coordinate of the correction
        for (const auto& [d2, k] : near) {
            const Vec3 d = positions[static_cast<size_t>(k)] - positions[i];
            const Eigen::Vector3d row(1.0, d.dot(along), flat ? d.dot(across) : 0.0);
            normal += row * row.transpose();
            rhs += row * corrections[static_cast<size_t>(k)].transpose();
        }
        if (!flat) normal(2, 2) = 1.0;  // no v: its coefficient pinned to zero
        if (static_cast<int>(near.size()) < unknowns) continue;
        const Eigen::LDLT<Eigen::Matrix3d> solve(normal);
        if (solve.info() != Eigen::Success) continue;
        const Eigen::Matrix3d coefficients = solve.solve(rhs);
        const Vec3 trend = coefficients.row(0).transpose();
        if (trend.allFinite()) out[i] = (corrections[i] - trend).norm();
    }
    return out;
}

}  // namespace aeronc::compensation
