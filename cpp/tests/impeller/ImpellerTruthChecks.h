#pragma once
// Recognition and dimensions of a generated impeller against the generator's truth, shared by
// the recognition and family tests: counts, hub, bore, planes, rim, every blade's roles, the
// blades' angular order and the measured sizes to the 1e-3 mm.
#include <aeronc/impeller/ImpellerDimensions.h>
#include <aeronc/impeller/ImpellerFeatures.h>
#include <aeronc/testparts/ImpellerGenerator.h>

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace aeronc::impeller::truthchecks {

constexpr double kDimTol = 1e-3;  // mm, the bound for measured against generated sizes

inline std::set<int> asSet(const std::vector<int>& v) { return {v.begin(), v.end()}; }

inline void expectMatchesTruth(const ImpellerFeatures& f, const ImpellerDimensions& d,
                               const testparts::ImpellerTruth& t, bool splitters) {
    EXPECT_EQ(f.bladeCount, t.bladeCount);
    EXPECT_EQ(f.splitterCount, splitters ? t.bladeCount : 0);
    EXPECT_EQ(f.hub, t.hub);
    EXPECT_EQ(f.bore, t.bore);
    EXPECT_EQ(asSet(f.planes), asSet(t.planes));
    EXPECT_EQ(f.turned, std::vector<int>{t.rim});
    EXPECT_TRUE(f.holes.empty());
    ASSERT_EQ(f.blades.size(), t.blades.size());
    std::map<int, const testparts::BladeTruth*> byShroud;
    for (const auto& b : t.blades) byShroud[b.shroud] = &b;
    for (const auto& b : f.blades) {
        SCOPED_TRACE("blade with shroud face " + std::to_string(b.shroud));
        ASSERT_TRUE(byShroud.count(b.shroud));
        const auto& tb = *byShroud[b.shroud];
        EXPECT_EQ(b.splitter, tb.splitter);
        EXPECT_EQ(b.pressure, tb.pressure);
        EXPECT_EQ(b.suction, tb.suction);
        EXPECT_EQ(b.leading, tb.leading);
        EXPECT_EQ(b.trailing, tb.trailing);
        EXPECT_EQ(asSet(b.walls), (std::set<int>{tb.pressure, tb.suction, tb.leading, tb.trailing}));
        EXPECT_EQ(asSet(b.fillets), asSet(tb.fillets));
        EXPECT_EQ(b.shroudFaces, std::vector<int>{tb.shroud});
        byShroud.erase(b.shroud);
    }
    // Angular order, starting at a main blade: main and splitter alternate, the angles rise
    // once round (one step back, where the list wraps past 360 degrees or closes), and the
    // closest shroud pair is adjacent.
    const int n = static_cast<int>(f.blades.size());
    int stepsBack = 0;
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(f.blades[i].splitter, splitters && i % 2 == 1);
        if (f.blades[(i + 1) % n].angleDeg < f.blades[i].angleDeg) ++stepsBack;
    }
    EXPECT_EQ(stepsBack, 1);
    EXPECT_EQ((f.closestPair[0] + 1) % n, f.closestPair[1]);

    EXPECT_NEAR(d.boreDiameter, t.boreDiameter, kDimTol);
    EXPECT_NEAR(d.boreDepth, t.boreDepth, kDimTol);
    EXPECT_NEAR(d.filletRadius, t.filletRadius, kDimTol);
    EXPECT_NEAR(d.bladeHeight, t.bladeHeight, kDimTol);
    if (splitters) EXPECT_NEAR(d.splitterHeight, t.bladeHeight, kDimTol);
    EXPECT_NEAR(d.minChannelWidth, t.minChannelWidth, kDimTol);
    EXPECT_EQ((d.channelBlades[0] + 1) % n, d.channelBlades[1]);
}

}  // namespace aeronc::impeller::truthchecks
