// Best-fit transforms and residual fields on known data.
#include "../ErrorOf.h"
#include "Fixtures.h"

#include <aeronc/compensation/BestFit.h>
#include <aeronc/compensation/ResidualField.h>

#include <gtest/gtest.h>

#include <random>

using namespace aeronc::compensation;
using namespace aeronc::compensation::test;
using aeronc::test::inputErrorOf;

namespace {

std::vector<Vec3> randomPoints(int n, unsigned seed, double zSpread = 30.0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-400, 400), w(-zSpread, zSpread);
    std::vector<Vec3> out;
    for (int i = 0; i < n; ++i) out.emplace_back(u(rng), u(rng), w(rng));
    return out;
}

}  // namespace

TEST(BestFit, KnownRigidAndSimilarityTransformsAreRecovered) {
    const auto from = randomPoints(12, 3);
    const Mat3 r = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const Vec3 t(10, -4, 2);
    std::vector<Vec3> rigid, similar;
    for (const auto& p : from) rigid.push_back(r * p + t), similar.push_back(1.002 * (r * p) + t);
    const auto a = fitRigid(from, rigid);
    EXPECT_LT((a.rotation - r).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((a.translation - t).norm(), 1e-9);
    EXPECT_EQ(a.scale, 1.0);
    const auto b = fitSimilarity(from, similar);
    EXPECT_NEAR(b.scale, 1.002, 1e-12);
    for (size_t i = 0; i < from.size(); ++i) EXPECT_LT((b.apply(from[i]) - similar[i]).norm(), 1e-9);
    // A rigid fit of scaled data leaves residuals; the similarity fit does not.
    const auto c = fitRigid(from, similar);
    double worst = 0.0;
    for (size_t i = 0; i < from.size(); ++i) worst = std::max(worst, (c.apply(from[i]) - similar[i]).norm());
    EXPECT_GT(worst, 0.1);
}

TEST(BestFit, TooFewOrCollinearDatumHolesAreRefused) {
    const std::vector<Vec3> two{Vec3(0, 0, 0), Vec3(100, 0, 0)};
    EXPECT_NE(inputErrorOf([&] { fitRigid(two, two); }).find("at least three"), std::string::npos);
    const std::vector<Vec3> line{Vec3(0, 0, 0), Vec3(100, 50, 0), Vec3(200, 100, 0.0001), Vec3(300, 150, 0)};
    const auto msg = inputErrorOf([&] { fitSimilarity(line, line); });
    EXPECT_NE(msg.find("collinear"), std::string::npos) << msg;
    // Off the line by more than 1e-3 of the extent: accepted.
    const std::vector<Vec3> bent{Vec3(0, 0, 0), Vec3(100, 50, 0), Vec3(200, 100, 2.0), Vec3(300, 150, 0)};
    EXPECT_NO_THROW(fitRigid(bent, bent));
}

TEST(ResidualField, BothFieldsPassThroughTheDatumValues) {
    const auto pts = randomPoints(15, 5, 5.0);
    std::vector<Vec3> values;
    for (const auto& p : pts) values.emplace_back(std::sin(p.x() / 100), std::cos(p.y() / 70), 0.01 * p.z());
    const InverseDistanceField idw(pts, values);
    const ThinPlateSpline tps(pts, values);
    for (size_t i = 0; i < pts.size(); ++i) {
        EXPECT_LT((idw.at(pts[i]) - values[i]).norm(), 1e-12);
        EXPECT_LT((tps.at(pts[i]) - values[i]).norm(), 1e-9);
    }
}

TEST(ResidualField, ThinPlateSplineReproducesAnAffineFieldOnAPlane) {
    auto pts = randomPoints(10, 8, 0.0);
    auto field = [](const Vec3& p) { return Vec3(0.001 * p.x() - 0.002 * p.y() + 0.3, 0.0005 * p.x(), -0.2); };
    std::vector<Vec3> values;
    for (const auto& p : pts) values.push_back(field(p));
    const ThinPlateSpline tps(pts, values);
    for (const auto& q : randomPoints(50, 9, 0.0)) EXPECT_LT((tps.at(q) - field(q)).norm(), 1e-9);
}

TEST(ResidualField, CoincidentDatumHolesAreRefused) {
    std::vector<Vec3> pts{Vec3(0, 0, 0), Vec3(100, 0, 0), Vec3(0, 100, 0), Vec3(100, 0, 0)};
    std::vector<Vec3> values(4, Vec3(0, 0, 1));
    values[3] = Vec3(0, 0, 2);
    const auto msg = inputErrorOf([&] { ThinPlateSpline(pts, values); });
    EXPECT_NE(msg.find("same place"), std::string::npos) << msg;
}

TEST(ResidualField, ManyPointsAtOnceGiveWhatOneAtATimeGives) {
    const auto pts = randomPoints(40, 12, 10.0);
    std::vector<Vec3> values;
    for (const auto& p : pts) values.emplace_back(std::sin(p.x() / 90), p.y() * 1e-3, std::cos(p.z() / 20));
    const ThinPlateSpline tps(pts, values);
    auto query = randomPoints(700, 13, 10.0);
    query.push_back(pts[3]);  // on a node: the kernel's 0 log 0
    std::vector<Vec3> many(query.size(), Vec3(1, 2, 3));
    tps.addAt(query, many);
    for (size_t i = 0; i < query.size(); ++i) EXPECT_LT((many[i] - Vec3(1, 2, 3) - tps.at(query[i])).norm(), 1e-10) << i;
    EXPECT_LT((many.back() - Vec3(1, 2, 3) - values[3]).norm(), 1e-9);
}
