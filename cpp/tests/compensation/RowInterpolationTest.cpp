// The seed's formula 2, by hand and over whole rows of the known patterns.
#include "Fixtures.h"

#include <aeronc/compensation/RowInterpolation.h>

#include <gtest/gtest.h>

using namespace aeronc::compensation;
using namespace aeronc::compensation::test;

TEST(RowInterpolation, FormulaByHand) {
    // dP_i = dP_1 (S - S_i)/S + dP_n S_i/S with S = 4, S_i = 1: 3/4 of dP_1 and 1/4 of dP_n.
    const Vec3 c = rowCorrection(Vec3(1, 2, 3), Vec3(3, 2, -1), 4.0, 1.0);
    EXPECT_EQ(c, Vec3(1.5, 2.0, 2.0));
    EXPECT_EQ(rowCorrection(Vec3(1, 2, 3), Vec3(3, 2, -1), 4.0, 0.0), Vec3(1, 2, 3));
    EXPECT_EQ(rowCorrection(Vec3(1, 2, 3), Vec3(3, 2, -1), 4.0, 4.0), Vec3(3, 2, -1));
    EXPECT_THROW(rowCorrection(Vec3::Zero(), Vec3::Zero(), 0.0, 0.0), aeronc::Error);
}

// Every drilling hole between two datum holes of its row gets formula 2 of those two datum
// holes, S and S_i measured along the row (here computed independently of the core's rows).
TEST(RowInterpolation, SeedMethodIsTheFormulaOnEveryHole) {
    for (const Pattern& p : {flatSkin(), curvedSkin()})
        for (const auto& d : distortions(p)) {
            CompensationInput in;
            in.datums = measuredDatums(p, d.apply);
            in.holes = drillingHoles(p);
            const auto r = compensate(in, Method::Seed);
            ASSERT_EQ(r.holes.size(), p.drilling.size());
            int checked = 0;
            for (size_t h = 0; h < p.drilling.size(); ++h) {
                const int index = p.drilling[h];
                for (const auto& row : p.rows) {
                    const auto at = std::find(row.begin(), row.end(), index);
                    if (at == row.end()) continue;
                    std::vector<double> station(row.size(), 0.0);
                    for (size_t k = 1; k < row.size(); ++k)
                        station[k] = station[k - 1] + (p.points[static_cast<size_t>(row[k])] - p.points[static_cast<size_t>(row[k - 1])]).norm();
                    const auto k = static_cast<size_t>(at - row.begin());
                    size_t a = k, b = k;
                    auto isDatum = [&](size_t j) {
                        return std::find(p.datums.begin(), p.datums.end(), row[j]) != p.datums.end();
                    };
                    while (!isDatum(a)) --a;
                    while (!isDatum(b)) ++b;
                    const Vec3 dp1 = d.apply(p.points[static_cast<size_t>(row[a])]) - p.points[static_cast<size_t>(row[a])];
                    const Vec3 dpn = d.apply(p.points[static_cast<size_t>(row[b])]) - p.points[static_cast<size_t>(row[b])];
                    const double S = station[b] - station[a], Si = station[k] - station[a];
                    const Vec3 expected = dp1 * (S - Si) / S + dpn * Si / S;
                    EXPECT_LT((r.holes[h].correction - expected).norm(), 1e-12) << p.name << " " << d.name << " hole " << index;
                    EXPECT_TRUE(r.holes[h].note.empty()) << r.holes[h].note;
                    ++checked;
                }
            }
            EXPECT_EQ(checked, static_cast<int>(p.drilling.size()));
        }
}

TEST(RowInterpolation, BeyondTheLastDatumTakesItsDeviationAndSaysSo) {
    Pattern p = flatSkin(1, 11);
    p.datums = {p.rows[0][0], p.rows[0][5]};
    p.drilling.clear();
    for (int i = 0; i < 11; ++i)
        if (i != 0 && i != 5) p.drilling.push_back(p.rows[0][static_cast<size_t>(i)]);
    const auto d = distortions(p)[3].apply;
    CompensationInput in;
    in.datums = measuredDatums(p, d);
    in.holes = drillingHoles(p);
    const auto r = compensate(in, Method::Seed);
    const Vec3 last = in.datums[1].deviation();
    int beyond = 0;
    for (const auto& h : r.holes)
        if (h.nominal.x() > 125.0) {
            EXPECT_EQ(h.correction, last);
            EXPECT_NE(h.note.find("beyond the last datum hole"), std::string::npos) << h.note;
            ++beyond;
        }
    EXPECT_EQ(beyond, 5);
}
