// Forward kinematics and the transforms of the kinematic chain (see Kinematics.h).
#include <aeronc/kinematics/Kinematics.h>

namespace aeronc::kinematics {

namespace {

Mat3 rotation(const Vec3& axis, double degrees) {
    return Eigen::AngleAxisd(toRadians(degrees), axis).toRotationMatrix();
}

}  // namespace

Kinematics::Kinematics(MachineModel model, const MachineSetup& setup) : model_(std::move(model)) {
    if (model_.rotary.size() != 2) throw inputError("machine " + model_.name + ": needs two rotary axes");
    const Vec3 partZero = setup.partZero ? *setup.partZero : model_.partZero;
    for (int i = 0; i < 2; ++i) {
        const RotaryAxis& a = model_.rotary[i];
        if (a.carrier == Carrier::Table) {
            // From the table reference to the program zero.
            points_[i] = a.point - partZero;
            tableAxes_.push_back(i);
        } else {
            // From the gauge point to the tip: the tip sits toolLength below the gauge point.
            points_[i] = a.point + setup.toolLength * model_.toolDirection;
            headAxes_.push_back(i);
        }
    }
}

Vec3 Kinematics::applyTable(const Vec3& p, const std::array<double, 2>& rotary) const {
    // Posts call this for every move, mostly at the angles of the move before: keep the rotations.
    if (rotary != cachedAngles_) {
        for (int i = 0; i < 2; ++i) cachedRotation_[i] = rotation(model_.rotary[i].direction, rotary[i]);
        cachedAngles_ = rotary;
    }
    Vec3 x = p;
    for (auto it = tableAxes_.rbegin(); it != tableAxes_.rend(); ++it) {
        const int i = *it;
        x = points_[i] + cachedRotation_[i] * (x - points_[i]);
    }
    return x;
}

Mat3 Kinematics::tableRotation(const std::array<double, 2>& rotary) const {
    Mat3 r = Mat3::Identity();
    for (int i : tableAxes_) r = r * rotation(model_.rotary[i].direction, rotary[i]);
    return r;
}

Mat3 Kinematics::headRotation(const std::array<double, 2>& rotary) const {
    Mat3 r = Mat3::Identity();
    for (int i : headAxes_) r = r * rotation(model_.rotary[i].direction, rotary[i]);
    return r;
}

Vec3 Kinematics::headOffset(const std::array<double, 2>& rotary) const {
    Vec3 x = Vec3::Zero();
    for (auto it = headAxes_.rbegin(); it != headAxes_.rend(); ++it) {
        const int i = *it;
        x = points_[i] + rotation(model_.rotary[i].direction, rotary[i]) * (x - points_[i]);
    }
    return x;
}

ToolPose Kinematics::forward(const Joints& j) const {
    const Vec3 tipMachine = j.linear + headOffset(j.rotary);
    // Invert the table transform: innermost axis last, each about its own point.
    Vec3 x = tipMachine;
    for (int i : tableAxes_)
        x = points_[i] + rotation(model_.rotary[i].direction, -j.rotary[i]) * (x - points_[i]);
    const Mat3 rt = tableRotation(j.rotary);
    ToolPose pose;
    pose.tip = x;
    pose.axis = (rt.transpose() * headRotation(j.rotary) * model_.toolDirection).normalized();
    return pose;
}

Vec3 Kinematics::linearFor(const Vec3& tip, const std::array<double, 2>& rotary) const {
    return applyTable(tip, rotary) - headOffset(rotary);
}

}  // namespace aeronc::kinematics
