#pragma once
// From what the camera measures to the part frame (drilling paper section 1.2.2):
//     camera -> tool mount -> machine -> assembly -> part.
// Each link is a 4x4 rigid transform:
//   mountFromCamera      calibrated: where the camera sits on the tool mount (the camera is a
//                        tool with its own offset along the spindle)
//   machineFromMount     where the machine put the tool mount to take the picture: the gauge
//                        point and the head's orientation for that datum hole
//   assemblyFromMachine  calibrated when the assembly frame is set up (laser tracker)
//   partFromAssembly     from the model: the part's placement in the assembly, inverted
// The camera frame's z axis runs along the camera spindle towards the part, so a datum hole
// seen at (U, V) with the camera at height h above it is the point (U, V, h).
#include <aeronc/compensation/Types.h>

#include <string>

namespace aeronc::compensation {

struct TransformChain {
    Mat4 mountFromCamera = Mat4::Identity();
    Mat4 machineFromMount = Mat4::Identity();
    Mat4 assemblyFromMachine = Mat4::Identity();
    Mat4 partFromAssembly = Mat4::Identity();

    Mat4 partFromCamera() const { return partFromAssembly * assemblyFromMachine * machineFromMount * mountFromCamera; }
    Vec3 toPart(const Vec3& camera) const;  // (U, V, h) -> part frame
    Vec3 toCamera(const Vec3& part) const;  // part frame -> (U, V, h)
};

// Throws unless m is a rigid transform: a rotation (orthonormal within 1e-6, determinant +1),
// a finite translation and the last row 0 0 0 1. `name` names the transform in the message.
void requireRigid(const Mat4& m, const std::string& name);
void requireRigid(const TransformChain& chain);

// The inverse of a rigid transform (exact, without a general matrix inverse).
Mat4 rigidInverse(const Mat4& m);

// A frame at `origin` whose z axis is `axis` and whose x axis is `xDirection` made
// perpendicular to it (the tool mount at a camera position: origin the gauge point, z the
// spindle axis pointing away from the part, x fixed by the head's angles).
Mat4 frameAt(const Vec3& origin, const Vec3& axis, const Vec3& xDirection);

}  // namespace aeronc::compensation
