// Statistics against hand-computed values. Tolerance 1e-12: every value here is a short sum of exact
// binary fractions or one square root, so only the last bits of rounding may differ.
#include <cmath>

#include <gtest/gtest.h>

#include "bench/Statistics.h"
#include "scenes/Error.h"

using sb::Statistics;

namespace {
constexpr double kEps = 1e-12;

TEST(StatisticsTest, OneToTenByHand) {
    // Type 7: h = 9q. p5: h = 0.45 -> 1 + 0.45 = 1.45; p95: h = 8.55 -> 9.55; p99: h = 8.91 -> 9.91.
    // mean 5.5; sum of squared deviations 82.5, / 9 -> stddev sqrt(9.1666...) = 3.0276503540974917.
    // Deviations from 5.5: 4.5 3.5 2.5 1.5 .5 .5 1.5 2.5 3.5 4.5 -> median 2.5.
    Statistics s = Statistics::compute({7, 3, 10, 1, 5, 2, 9, 4, 8, 6}); // unsorted on purpose
    EXPECT_EQ(s.n, 10u);
    EXPECT_NEAR(s.median, 5.5, kEps);
    EXPECT_NEAR(s.p5, 1.45, kEps);
    EXPECT_NEAR(s.p95, 9.55, kEps);
    EXPECT_NEAR(s.p99, 9.91, kEps);
    EXPECT_NEAR(s.mean, 5.5, kEps);
    EXPECT_NEAR(s.stddev, 3.0276503540974917, kEps);
    EXPECT_NEAR(s.mad, 2.5, kEps);
    EXPECT_EQ(s.min, 1.0);
    EXPECT_EQ(s.max, 10.0);
}

TEST(StatisticsTest, OddCountMedianIsTheMiddleValue) {
    // {1, 2, 4, 8, 100}: median 4; deviations 3 2 0 4 96 -> MAD 3; mean 23.
    Statistics s = Statistics::compute({100, 1, 8, 2, 4});
    EXPECT_NEAR(s.median, 4.0, kEps);
    EXPECT_NEAR(s.mad, 3.0, kEps);
    EXPECT_NEAR(s.mean, 23.0, kEps);
    // p95: h = 4 * 0.95 = 3.8 -> 8 + 0.8 * 92 = 81.6
    EXPECT_NEAR(s.p95, 81.6, 1e-9);
}

TEST(StatisticsTest, SingleSampleHasZeroSpread) {
    Statistics s = Statistics::compute({3.25});
    EXPECT_EQ(s.n, 1u);
    EXPECT_EQ(s.median, 3.25);
    EXPECT_EQ(s.p5, 3.25);
    EXPECT_EQ(s.p99, 3.25);
    EXPECT_EQ(s.stddev, 0.0);
    EXPECT_EQ(s.mad, 0.0);
}

TEST(StatisticsTest, EmptyInputGivesNZero) {
    Statistics s = Statistics::compute({});
    EXPECT_EQ(s.n, 0u);
    EXPECT_EQ(s.median, 0.0);
}

TEST(StatisticsTest, NaNIsRejected) {
    EXPECT_THROW(Statistics::compute({1.0, std::nan(""), 2.0}), sb::Error);
}

TEST(StatisticsTest, PercentileEndsAreMinAndMax) {
    std::vector<double> sorted{2, 4, 6};
    EXPECT_EQ(Statistics::percentileSorted(sorted, 0.0), 2.0);
    EXPECT_EQ(Statistics::percentileSorted(sorted, 1.0), 6.0);
    EXPECT_NEAR(Statistics::percentileSorted(sorted, 0.25), 3.0, kEps); // h = 0.5
}
} // namespace
