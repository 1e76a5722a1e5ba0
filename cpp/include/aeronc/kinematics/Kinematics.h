#pragma once
// Forward and inverse kinematics of a machine model for one setup (part zero, tool length).
//
// Machine coordinates: X Y Z are the position of the tool tip as the linear axes carry it,
// i.e. the tip with every head axis at zero (tool length compensated by the controller),
// measured from the program zero with every axis at zero. For a table-table machine this
// is the usual "machine coordinates of the tool tip"; for a head machine it is the tip of
// the unswivelled head.
//
//   table transform  T(theta): workpiece -> machine; axes applied innermost first
//   head transform   H(theta): tool-local -> ram; innermost first, tip-at-home at the origin
//   tip   in machine = linear + H(0)          = T(tip in workpiece)
//   axis  in machine = R_H * toolDirection    = R_T * (axis in workpiece)
#include <aeronc/kinematics/MachineModel.h>

#include <vector>

namespace aeronc::kinematics {

struct MachineSetup {
    std::optional<Vec3> partZero;  // overrides the machine file's
    double toolLength = 0.0;       // gauge point to tip, mm (head axes only)
};

// One solution of the orientation problem. `free` marks an axis left undetermined by the
// orientation (the pole: the tool axis lies on that rotary axis); its angle is the one
// the caller asked to keep.
struct RotarySolution {
    std::array<double, 2> angles{0.0, 0.0};  // degrees, in (-180, 180] before winding
    std::array<bool, 2> free{false, false};
};

// Not for use from several threads at once: it keeps the last table rotations it computed.
class Kinematics {
public:
    explicit Kinematics(MachineModel model, const MachineSetup& setup = {});

    const MachineModel& model() const { return model_; }

    // Forward kinematics: machine axes -> tool pose in the workpiece frame.
    ToolPose forward(const Joints& j) const;

    // Inverse kinematics of the orientation: both solutions (A+ and A-) for the tool axis,
    // none when no rotation of the two axes reaches it. At the pole the free axis takes
    // `keep` (degrees) and the two solutions coincide into one.
    std::vector<RotarySolution> orientations(const Vec3& axis, const std::array<double, 2>& keep) const;

    // Inverse kinematics of the position: linear axes that put the tip at `tip` (workpiece
    // frame) with the rotary axes at `rotary` (degrees).
    Vec3 linearFor(const Vec3& tip, const std::array<double, 2>& rotary) const;

    // Rotation of the workpiece frame into the machine frame for these rotary angles.
    Mat3 tableRotation(const std::array<double, 2>& rotary) const;

private:
    Vec3 applyTable(const Vec3& p, const std::array<double, 2>& rotary) const;
    Vec3 headOffset(const std::array<double, 2>& rotary) const;  // H(0)
    Mat3 headRotation(const std::array<double, 2>& rotary) const;

    MachineModel model_;
    std::array<Vec3, 2> points_;  // effective axis points for this setup
    std::vector<int> tableAxes_;  // indices, outer first
    std::vector<int> headAxes_;   // indices, outer first
    mutable std::array<double, 2> cachedAngles_{std::nan(""), std::nan("")};
    mutable std::array<Mat3, 2> cachedRotation_;
};

// Pole tolerance: |sin| of the angle between the tool axis and a rotary axis below which the
// rotary axis is taken as undetermined. Small enough that keeping the previous angle there
// moves the tool axis by less than 1e-10 rad.
constexpr double kPoleTolerance = 1e-10;

}  // namespace aeronc::kinematics
