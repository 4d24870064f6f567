// Accuracy metrics on hand-made masks: every expected number below is counted by hand from the
// pictures in the comments (exact integer counts; percentages exact in binary to 1e-12).
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "reference/AccuracyMetrics.h"

using namespace sb;

namespace {
constexpr double kEps = 1e-12;

// 4x3 images, rows listed top to bottom here but stored bottom-up like GL read-backs; the metrics
// do not care about orientation, only about neighbours.
//   reference (1 lit, 0 shadow, -1 background)   technique
//   1 1 0 0                                        1 0 0 0      <- (1,0) false shadow (an edge pixel)
//   1 1 0 0                                        1 1 0 1      <- (3,1) false light (an edge pixel:
//   1 1 1 1                                        1 1 1 1         (2,2) and (3,2) below are lit)
std::vector<float> rows(std::initializer_list<std::initializer_list<float>> r) {
    std::vector<std::vector<float>> v;
    for (auto row : r) v.emplace_back(row);
    std::vector<float> out;
    for (auto it = v.rbegin(); it != v.rend(); ++it) out.insert(out.end(), it->begin(), it->end());
    return out;
}

TEST(AccuracyMetricsTest, HardRatesCountedByHand) {
    auto ref = rows({{1, 1, 0, 0}, {1, 1, 0, 0}, {1, 1, 1, 1}});
    auto tech = rows({{1, 0, 0, 0}, {1, 1, 0, 1}, {1, 1, 1, 1}});
    std::vector<uint8_t> mask(12, 1);
    HardMetrics m = AccuracyMetrics::hard(tech, ref, mask, 4, 3);
    EXPECT_EQ(m.evaluated, 12u);
    EXPECT_EQ(m.falseShadow, 1u);
    EXPECT_EQ(m.falseLight, 1u);
    EXPECT_NEAR(m.falseShadowPct, 100.0 / 12.0, kEps);
    EXPECT_NEAR(m.wrongPct, 200.0 / 12.0, kEps);
    // Edge band: pixels with a neighbour of the other class: (1,0) (2,0) (1,1) (2,1) (3,1) (1,2)
    // (2,2) (3,2) = 8. Interior: (0,0) (0,1) (0,2) and the shadowed (3,0), whose neighbours (2,0)
    // (2,1) (3,1) are all shadowed = 4, none of them wrong.
    std::vector<uint8_t> edge = AccuracyMetrics::edgeMask(ref, 4, 3);
    EXPECT_EQ(std::count(edge.begin(), edge.end(), 1), 8);
    EXPECT_EQ(m.evaluatedNoEdge, 4u);
    EXPECT_EQ(m.falseShadowNoEdge + m.falseLightNoEdge, 0u);
    EXPECT_NEAR(m.wrongNoEdgePct, 0.0, kEps);
}

TEST(AccuracyMetricsTest, GrossErrorSurvivesEdgeExclusion) {
    // A 5x5 lit reference with a technique that shadows the centre pixel: no reference edge exists,
    // so the error stays with the edge band excluded.
    std::vector<float> ref(25, 1.0f), tech(25, 1.0f);
    tech[12] = 0.0f;
    std::vector<uint8_t> mask(25, 1);
    HardMetrics m = AccuracyMetrics::hard(tech, ref, mask, 5, 5);
    EXPECT_EQ(m.falseShadowNoEdge, 1u);
    EXPECT_NEAR(m.falseShadowNoEdgePct, 4.0, kEps);
}

TEST(AccuracyMetricsTest, MaskAndBackgroundAreNotJudged) {
    std::vector<float> ref{1, 0, -1, 1}, tech{0, 1, 0, 0};
    std::vector<uint8_t> mask{0, 1, 0, 1};
    HardMetrics m = AccuracyMetrics::hard(tech, ref, mask, 4, 1);
    EXPECT_EQ(m.evaluated, 2u);
    EXPECT_EQ(m.falseLight, 1u);  // pixel 1
    EXPECT_EQ(m.falseShadow, 1u); // pixel 3
}

TEST(AccuracyMetricsTest, SoftErrorsByHand) {
    // errors 0.1, 0.3, 0 -> mean 0.4/3, max 0.3, rmse sqrt((0.01 + 0.09) / 3)
    std::vector<float> ref{0.5f, 0.2f, 1.0f}, tech{0.6f, 0.5f, 1.0f};
    SoftMetrics m = AccuracyMetrics::soft(tech, ref, {1, 1, 1});
    EXPECT_NEAR(m.meanAbs, 0.4 / 3.0, 1e-7); // float inputs: 1e-7 is their rounding
    EXPECT_NEAR(m.maxAbs, 0.3, 1e-7);
    EXPECT_NEAR(m.rmse, std::sqrt(0.1 / 3.0), 1e-7);
}

TEST(AccuracyMetricsTest, NonFiniteValuesAreCountedAndWrong) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    NumericSanity s = AccuracyMetrics::sanity({0.0f, 1.0f, nan, inf, -inf, 1.5f, -0.25f, 0.5f});
    EXPECT_EQ(s.nan, 1u);
    EXPECT_EQ(s.inf, 2u);
    EXPECT_EQ(s.outOfRange, 2u);
    EXPECT_EQ(s.total(), 5u);
    // A NaN visibility is always a wrong classification and the largest soft error.
    HardMetrics h = AccuracyMetrics::hard({nan, nan}, {1.0f, 0.0f}, {1, 1}, 2, 1);
    EXPECT_EQ(h.falseShadow + h.falseLight, 2u);
    SoftMetrics soft = AccuracyMetrics::soft({nan}, {0.5f}, {1});
    EXPECT_EQ(soft.maxAbs, 1.0);
}

TEST(AccuracyMetricsTest, StabilityRatios) {
    std::vector<float> a{1, 1, 0, 0}, b{1, 0, 0, 1};
    EXPECT_EQ(AccuracyMetrics::changedSamples(a, b, {1, 1, 1, 1}), 2u);
    EXPECT_EQ(AccuracyMetrics::changedSamples(a, b, {1, 0, 1, 1}), 1u);
    EXPECT_EQ(AccuracyMetrics::perturbationGain(6, 3), 2.0);
    EXPECT_EQ(AccuracyMetrics::perturbationGain(6, 0), 6.0); // max(1, reference changes)
    EXPECT_EQ(AccuracyMetrics::channel({1, 2, 3, 4, 5, 6, 7, 8}, 2), (std::vector<float>{3, 7}));
}
} // namespace
