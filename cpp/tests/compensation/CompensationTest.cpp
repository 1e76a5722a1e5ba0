// compensate(): the report's content, leave-one-out, the proposal and bad input.
#include "../ErrorOf.h"
#include "Fixtures.h"

#include <gtest/gtest.h>

using namespace aeronc::compensation;
using namespace aeronc::compensation::test;
using aeronc::test::inputErrorOf;

TEST(Compensation, ReportHasEveryHoleAndDatum) {
    const Pattern p = curvedSkin();
    CompensationInput in;
    in.datums = measuredDatums(p, distortions(p)[3].apply);
    in.holes = drillingHoles(p);
    in.tolerance = 1.3;
    const auto r = compensate(in);
    ASSERT_TRUE(r.proposed);
    EXPECT_EQ(r.method, *r.proposed);
    EXPECT_EQ(r.holes.size(), p.drilling.size());
    EXPECT_EQ(r.datums.size(), p.datums.size());
    EXPECT_EQ(r.leaveOneOut.size(), allMethods().size());
    int flagged = 0;
    for (const auto& h : r.holes) {
        EXPECT_LT((h.compensated - h.nominal - h.correction).norm(), 1e-12);
        EXPECT_NEAR(h.normal.norm(), 1.0, 1e-12);
        EXPECT_EQ(h.exceedsTolerance, h.correction.norm() > 1.3);
        flagged += h.exceedsTolerance;
    }
    EXPECT_EQ(flagged, r.flaggedHoles);
    EXPECT_GT(flagged, 0);
    EXPECT_LT(flagged, static_cast<int>(r.holes.size()));
    for (const auto& l : r.leaveOneOut) {
        EXPECT_TRUE(l.available) << methodName(l.method) << ": " << l.reason;
        EXPECT_EQ(l.errors.size(), p.datums.size());
    }
}

TEST(Compensation, MethodNamesRoundTrip) {
    for (Method m : allMethods()) EXPECT_EQ(methodFromName(methodName(m)), m);
    EXPECT_FALSE(methodFromName("kriging"));
}

TEST(Compensation, TwoDatumHolesLeaveOnlyTheSeedsMethod) {
    Pattern p = flatSkin(1, 11);
    p.datums = {p.rows[0][0], p.rows[0][10]};
    p.drilling = {p.rows[0].begin() + 1, p.rows[0].begin() + 10};
    CompensationInput in;
    in.datums = measuredDatums(p, distortions(p)[1].apply);
    in.holes = drillingHoles(p);
    const auto r = compensate(in);
    ASSERT_TRUE(r.proposed);
    EXPECT_EQ(*r.proposed, Method::Seed);
    for (const auto& l : r.leaveOneOut)
        if (l.method != Method::Seed) {
            EXPECT_FALSE(l.available);
            EXPECT_NE(l.reason.find("at least three"), std::string::npos) << l.reason;
        }
    const auto msg = inputErrorOf([&] { compensate(in, Method::Rigid); });
    EXPECT_NE(msg.find("at least three"), std::string::npos) << msg;
}

TEST(Compensation, CollinearDatumHolesRefuseA3DFit) {
    // Datum holes along one straight row only.
    Pattern p = flatSkin(3, 11);
    p.datums = {p.rows[1][0], p.rows[1][5], p.rows[1][10]};
    p.drilling.clear();
    for (const auto& row : p.rows)
        for (int i : row)
            if (std::find(p.datums.begin(), p.datums.end(), i) == p.datums.end()) p.drilling.push_back(i);
    CompensationInput in;
    in.datums = measuredDatums(p, distortions(p)[0].apply);
    in.holes = drillingHoles(p);
    for (Method m : allMethods()) {
        if (m == Method::Seed) continue;
        const auto msg = inputErrorOf([&] { compensate(in, m); });
        EXPECT_NE(msg.find("collinear datum holes"), std::string::npos) << methodName(m) << ": " << msg;
    }
    // The seed's method still works, and says where it has no datum hole in the row.
    const auto r = compensate(in);
    EXPECT_EQ(r.method, Method::Seed);
    int borrowed = 0;
    for (const auto& h : r.holes) borrowed += h.note.find("no datum hole in its row") != std::string::npos;
    EXPECT_EQ(borrowed, 22);
}

TEST(Compensation, BadInputIsRefused) {
    const Pattern p = flatSkin();
    CompensationInput in;
    in.datums = measuredDatums(p, distortions(p)[0].apply);
    in.holes = drillingHoles(p);

    auto one = in;
    one.datums.resize(1);
    EXPECT_NE(inputErrorOf([&] { compensate(one); }).find("fewer than two datum holes (1)"), std::string::npos);
    auto none = in;
    none.datums.clear();
    EXPECT_NE(inputErrorOf([&] { compensate(none); }).find("fewer than two datum holes (0)"), std::string::npos);
    auto twice = in;
    twice.datums[1].id = twice.datums[0].id;
    EXPECT_NE(inputErrorOf([&] { compensate(twice); }).find("given twice"), std::string::npos);
    auto nan = in;
    nan.datums[2].measured.x() = NAN;
    EXPECT_NE(inputErrorOf([&] { compensate(nan); }).find(nan.datums[2].id + ": nominal or measured"), std::string::npos);
    auto badHole = in;
    badHole.holes[4].normal = Vec3::Zero();
    EXPECT_NE(inputErrorOf([&] { compensate(badHole); }).find(badHole.holes[4].id), std::string::npos);
    auto tol = in;
    tol.tolerance = -1;
    EXPECT_NE(inputErrorOf([&] { compensate(tol); }).find("tolerance"), std::string::npos);
}

TEST(Compensation, LeaveOneOutPredictsEachDatumFromTheOthers) {
    // With a pure translation every method predicts every datum hole exactly.
    const Pattern p = curvedSkin();
    const auto shift = [](const Vec3& x) { return Vec3(x + Vec3(0.4, -0.3, 0.2)); };
    const auto loo = leaveOneOut([&] {
        auto ds = measuredDatums(p, shift);
        std::vector<NominalHole> none;
        assignRows(ds, none);
        return ds;
    }());
    for (const auto& l : loo) {
        ASSERT_TRUE(l.available) << l.reason;
        EXPECT_LT(l.max, 1e-9) << methodName(l.method);
    }
    EXPECT_EQ(proposedMethod(loo), Method::Seed);  // every method ties: the simplest wins
}
