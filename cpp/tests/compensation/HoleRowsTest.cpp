// Rows found from the hole positions alone, against the patterns' known rows.
#include "Fixtures.h"

#include <aeronc/compensation/HoleRows.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <set>

using namespace aeronc::compensation;
using namespace aeronc::compensation::test;

namespace {

std::set<std::set<int>> asSets(const std::vector<std::vector<int>>& rows) {
    std::set<std::set<int>> out;
    for (const auto& r : rows) out.insert(std::set<int>(r.begin(), r.end()));
    return out;
}

}  // namespace

TEST(HoleRows, FlatAndCurvedSkinRowsAreFound) {
    for (const Pattern& p : {flatSkin(), curvedSkin(), flatSkin(1, 30), curvedSkin(8, 40)}) {
        const HoleRows rows = findRows(p.points);
        EXPECT_EQ(asSets(rows.members), asSets(p.rows)) << p.name;
        // Stations are the distances travelled along the row.
        for (const auto& members : rows.members) {
            double s = 0.0;
            for (size_t k = 0; k < members.size(); ++k) {
                if (k) s += (p.points[static_cast<size_t>(members[k])] - p.points[static_cast<size_t>(members[k - 1])]).norm();
                EXPECT_NEAR(rows.station[static_cast<size_t>(members[k])], s, 1e-9);
            }
        }
    }
}

TEST(HoleRows, TheOrderOfTheHolesDoesNotMatter) {
    const Pattern p = curvedSkin(6, 25);
    std::vector<int> order(p.points.size());
    std::iota(order.begin(), order.end(), 0);
    std::mt19937 rng(11);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<Vec3> shuffled;
    for (int i : order) shuffled.push_back(p.points[static_cast<size_t>(i)]);
    const HoleRows rows = findRows(shuffled);
    std::vector<std::vector<int>> back;
    for (const auto& m : rows.members) {
        back.emplace_back();
        for (int i : m) back.back().push_back(order[static_cast<size_t>(i)]);
    }
    EXPECT_EQ(asSets(back), asSets(p.rows));
}

TEST(HoleRows, RowsDoNotTurnACorner) {
    // An L of holes: two rows meeting at right angles at a corner hole.
    std::vector<Vec3> pts;
    for (int k = 0; k < 8; ++k) pts.emplace_back(20.0 * k, 0, 0);
    for (int k = 1; k < 8; ++k) pts.emplace_back(140.0, 20.0 * k, 0);
    const HoleRows rows = findRows(pts);
    EXPECT_EQ(rows.members.size(), 2u);
    for (const auto& m : rows.members) EXPECT_GE(m.size(), 7u);
}

TEST(HoleRows, NonFiniteHoleRefused) {
    EXPECT_THROW(findRows({Vec3(0, 0, 0), Vec3(NAN, 0, 0)}), aeronc::Error);
    EXPECT_TRUE(findRows({}).members.empty());
    EXPECT_EQ(findRows({Vec3(1, 2, 3)}).members.size(), 1u);
}
