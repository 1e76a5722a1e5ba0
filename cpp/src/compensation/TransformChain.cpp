#include <aeronc/compensation/TransformChain.h>

#include <sstream>

namespace aeronc::compensation {

Vec3 TransformChain::toPart(const Vec3& camera) const { return (partFromCamera() * camera.homogeneous()).head<3>(); }

Vec3 TransformChain::toCamera(const Vec3& part) const {
    return (rigidInverse(partFromCamera()) * part.homogeneous()).head<3>();
}

void requireRigid(const Mat4& m, const std::string& name) {
    if (!m.allFinite()) throw compensationError(name + " has a value that is not a finite number");
    const Eigen::RowVector4d last = m.row(3);
    if ((last - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-12)
        throw compensationError(name + ": the last row of a 4x4 transform must be 0 0 0 1");
    const Mat3 r = m.topLeftCorner<3, 3>();
    const double off = (r.transpose() * r - Mat3::Identity()).cwiseAbs().maxCoeff();
    if (off > 1e-6 || r.determinant() < 0.0) {
        std::ostringstream os;
        os << name << " is not a rigid transform (its 3x3 part must be a rotation: R^T R differs from the identity by "
           << off << ", determinant " << r.determinant() << ")";
        throw compensationError(os.str());
    }
}

void requireRigid(const TransformChain& chain) {
    requireRigid(chain.mountFromCamera, "camera -> tool mount");
    requireRigid(chain.machineFromMount, "tool mount -> machine");
    requireRigid(chain.assemblyFromMachine, "machine -> assembly");
    requireRigid(chain.partFromAssembly, "assembly -> part");
}

Mat4 rigidInverse(const Mat4& m) {
    Mat4 inv = Mat4::Identity();
    const Mat3 rt = m.topLeftCorner<3, 3>().transpose();
    inv.topLeftCorner<3, 3>() = rt;
    inv.topRightCorner<3, 1>() = -rt * m.topRightCorner<3, 1>();
    return inv;
}

Mat4 frameAt(const Vec3& origin, const Vec3& axis, const Vec3& xDirection) {
    if (!finite(origin) || !finite(axis) || !finite(xDirection) || axis.norm() < 1e-12)
        throw compensationError("a frame needs a finite origin and a non-zero axis");
    const Vec3 z = axis.normalized();
    Vec3 x = xDirection - xDirection.dot(z) * z;
    if (x.norm() < 1e-9) throw compensationError("a frame's x direction must not lie along its axis");
    x.normalize();
    Mat4 m = Mat4::Identity();
    m.block<3, 1>(0, 0) = x;
    m.block<3, 1>(0, 1) = z.cross(x);
    m.block<3, 1>(0, 2) = z;
    m.block<3, 1>(0, 3) = origin;
    return m;
}

}  // namespace aeronc::compensation
