// camera -> tool mount -> machine -> assembly -> part, and back.
#include "../ErrorOf.h"

#include <aeronc/compensation/TransformChain.h>

#include <gtest/gtest.h>

#include <random>

using namespace aeronc::compensation;
using aeronc::test::inputErrorOf;

namespace {

Mat4 randomRigid(std::mt19937& rng, double reach) {
    std::uniform_real_distribution<double> u(-1, 1);
    Mat4 m = Mat4::Identity();
    m.topLeftCorner<3, 3>() = Eigen::AngleAxisd(3.0 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()).toRotationMatrix();
    m.topRightCorner<3, 1>() = reach * Vec3(u(rng), u(rng), u(rng));
    return m;
}

}  // namespace

TEST(TransformChain, RoundTripsThroughEveryFrame) {
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 500; ++i) {
        TransformChain c{randomRigid(rng, 200), randomRigid(rng, 2000), randomRigid(rng, 5000), randomRigid(rng, 3000)};
        const Vec3 camera(5 * u(rng), 5 * u(rng), 60 + u(rng));
        const Vec3 part = c.toPart(camera);
        EXPECT_LT((c.toCamera(part) - camera).norm(), 1e-9);
        // Link by link, the same point.
        const Vec3 mount = (c.mountFromCamera * camera.homogeneous()).head<3>();
        const Vec3 machine = (c.machineFromMount * mount.homogeneous()).head<3>();
        const Vec3 assembly = (c.assemblyFromMachine * machine.homogeneous()).head<3>();
        EXPECT_LT(((c.partFromAssembly * assembly.homogeneous()).head<3>() - part).norm(), 1e-9);
        const Mat4 identity = rigidInverse(c.partFromCamera()) * c.partFromCamera();
        const Mat3 rotation = identity.topLeftCorner<3, 3>();
        const Vec3 translation = identity.topRightCorner<3, 1>();
        EXPECT_LT((rotation - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-12);
        EXPECT_LT(translation.norm(), 1e-9);  // mm, transforms reaching 10 m
    }
}

TEST(TransformChain, CameraLooksAlongItsZAxisAtTheHole) {
    // Tool mount 150 mm above a hole at (100, 50, 0) on a skin tilted 30 degrees about x; the
    // camera 90 mm below the gauge point on the spindle, its z axis towards the part, 60 mm
    // above the hole: the hole is seen at (0, 0, 60).
    const Vec3 hole(100, 50, 0), n(0, -0.5, std::sqrt(3.0) / 2);
    TransformChain c;
    c.machineFromMount = frameAt(hole + 150.0 * n, n, Vec3::UnitX());
    c.mountFromCamera << 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, -90, 0, 0, 0, 1;
    EXPECT_LT((c.toCamera(hole) - Vec3(0, 0, 60)).norm(), 1e-12);
    EXPECT_LT((c.toPart(Vec3(0, 0, 60)) - hole).norm(), 1e-12);
    // A hole 0.1 mm off along the mount's x axis is seen at U = 0.1.
    EXPECT_LT((c.toCamera(hole + Vec3(0.1, 0, 0)) - Vec3(0.1, 0, 60)).norm(), 1e-12);
}

TEST(TransformChain, NonRigidTransformsAreRefused) {
    Mat4 scaled = Mat4::Identity();
    scaled(0, 0) = 1.01;
    EXPECT_NE(inputErrorOf([&] { requireRigid(scaled, "camera -> tool mount"); }).find("not a rigid transform"),
              std::string::npos);
    Mat4 mirror = Mat4::Identity();
    mirror(2, 2) = -1;
    EXPECT_NE(inputErrorOf([&] { requireRigid(mirror, "m"); }).find("determinant"), std::string::npos);
    Mat4 row = Mat4::Identity();
    row(3, 0) = 0.5;
    EXPECT_NE(inputErrorOf([&] { requireRigid(row, "m"); }).find("last row"), std::string::npos);
    Mat4 nan = Mat4::Identity();
    nan(1, 3) = NAN;
    EXPECT_NE(inputErrorOf([&] { requireRigid(nan, "machine -> assembly"); }).find("machine -> assembly"), std::string::npos);
    EXPECT_THROW(frameAt(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitZ()), aeronc::Error);
}
