// Statistics against hand-computed values (docs/ARCHITECTURE.md, "The timing contract").
// Tolerance kEps = 1e-12 absolute: every expected value is O(1..100) and comes from a few additions, one
// multiplication by an inexact fraction (0.05 * 9 = 0.45 is not exact in binary) or one square root, so
// the computed value can differ only in the last bits (~1e-14). A wrong rank or a wrong interpolation
// weight would be off by at least 0.01, so 1e-12 cannot hide a real error.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "bench/lib/statistics/Statistics.h"
#include "core/Error.h"

using sb::Statistics;

namespace {
constexpr double kEps = 1e-12;

TEST(StatisticsTest, OneToTenByHand) {
    // Type 7: h = (n - 1) q = 9q, value = x[floor h] + frac(h) * (x[floor h + 1] - x[floor h]).
    //   median: h = 4.5 -> 5 + 0.5 = 5.5;  p5: h = 0.45 -> 1 + 0.45 = 1.45
    //   p95: h = 8.55 -> 9 + 0.55 = 9.55;   p99: h = 8.91 -> 9 + 0.91 = 9.91
    // mean 55 / 10 = 5.5; squared deviations sum to 2 (4.5^2 + 3.5^2 + 2.5^2 + 1.5^2 + 0.5^2) = 82.5,
    // / (n - 1) = 9.1666..., sqrt = 3.0276503540974917.
    // |x - 5.5| = 4.5 3.5 2.5 1.5 .5 .5 1.5 2.5 3.5 4.5 -> sorted median (2.5 + 2.5) / 2 = 2.5.
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
    // Sorted {1, 2, 4, 8, 100}: median x[2] = 4 (h = 2 exactly, no interpolation).
    // |x - 4| = 3 2 0 4 96 -> sorted 0 2 3 4 96 -> MAD 3. Mean 115 / 5 = 23.
    // p95: h = 4 * 0.95 = 3.8 -> 8 + 0.8 * 92 = 81.6.  p5: h = 0.2 -> 1 + 0.2 * 1 = 1.2.
    // Squared deviations from 23: 484 + 441 + 361 + 225 + 5929 = 7440; / 4 = 1860; sqrt = 43.1277173...
    Statistics s = Statistics::compute({100, 1, 8, 2, 4});
    EXPECT_EQ(s.n, 5u);
    EXPECT_NEAR(s.median, 4.0, kEps);
    EXPECT_NEAR(s.mad, 3.0, kEps);
    EXPECT_NEAR(s.mean, 23.0, kEps);
    EXPECT_NEAR(s.p95, 81.6, kEps);
    EXPECT_NEAR(s.p5, 1.2, kEps);
    EXPECT_NEAR(s.stddev, std::sqrt(1860.0), kEps);
}

TEST(StatisticsTest, EvenCountMedianIsTheMeanOfTheMiddlePair) {
    // Sorted {1, 3, 5, 11}: h = 1.5 -> (3 + 5) / 2 = 4. |x - 4| = 3 1 1 7 -> sorted 1 1 3 7 -> MAD 2.
    // Mean 20 / 4 = 5; squared deviations 16 + 4 + 0 + 36 = 56; / 3; sqrt(56 / 3) = 4.3204937989...
    Statistics s = Statistics::compute({11, 5, 1, 3});
    EXPECT_NEAR(s.median, 4.0, kEps);
    EXPECT_NEAR(s.mad, 2.0, kEps);
    EXPECT_NEAR(s.mean, 5.0, kEps);
    EXPECT_NEAR(s.stddev, std::sqrt(56.0 / 3.0), kEps);
}

TEST(StatisticsTest, SingleSampleHasZeroSpread) {
    // Every order statistic of one value is that value; n - 1 = 0 gives no spread estimate, defined as 0.
    Statistics s = Statistics::compute({3.25});
    EXPECT_EQ(s.n, 1u);
    for (double v : {s.median, s.p5, s.p95, s.p99, s.mean, s.min, s.max}) EXPECT_EQ(v, 3.25);
    EXPECT_EQ(s.stddev, 0.0);
    EXPECT_EQ(s.mad, 0.0);
}

TEST(StatisticsTest, EmptyInputGivesZeros) {
    Statistics s = Statistics::compute({});
    EXPECT_EQ(s.n, 0u);
    for (double v : {s.median, s.p5, s.p95, s.p99, s.mean, s.stddev, s.mad, s.min, s.max}) EXPECT_EQ(v, 0.0);
}

TEST(StatisticsTest, NaNAndInfinityAreRejected) {
    EXPECT_THROW(Statistics::compute({1.0, std::nan(""), 2.0}), sb::Error);
    EXPECT_THROW(Statistics::compute({std::numeric_limits<double>::infinity()}), sb::Error);
    try {
        Statistics::compute({1.0, std::nan("")});
        ADD_FAILURE() << "NaN accepted";
    } catch (const sb::Error& e) {
        EXPECT_EQ(e.code(), sb::ExitCode::Failure); // a broken timer is a failed run, not bad input
        EXPECT_NE(std::string(e.what()).find("sample 1"), std::string::npos) << e.what();
    }
}

TEST(StatisticsTest, LargeSpreadFreeOffsetKeepsStddevAccurate) {
    // 1e9 + {0, 1, 2}: stddev 1 exactly. A one-pass sum-of-squares formula loses every digit here
    // (squares near 1e18 have a spacing of 128); the two-pass one is exact. Tolerance 1e-6: the mean
    // itself is only representable to ~1e-7 at this magnitude.
    Statistics s = Statistics::compute({1e9 + 2, 1e9, 1e9 + 1});
    EXPECT_NEAR(s.stddev, 1.0, 1e-6);
    EXPECT_NEAR(s.mad, 1.0, 1e-6);
}

TEST(StatisticsTest, PercentileSortedEndsInterpolationAndClamping) {
    std::vector<double> sorted{2, 4, 6};
    EXPECT_EQ(Statistics::percentileSorted(sorted, 0.0), 2.0);
    EXPECT_EQ(Statistics::percentileSorted(sorted, 1.0), 6.0);
    EXPECT_NEAR(Statistics::percentileSorted(sorted, 0.25), 3.0, kEps); // h = 0.5
    EXPECT_NEAR(Statistics::percentileSorted(sorted, 0.75), 5.0, kEps); // h = 1.5
    EXPECT_EQ(Statistics::percentileSorted(sorted, -1.0), 2.0);         // clamped, no out-of-bounds read
    EXPECT_EQ(Statistics::percentileSorted(sorted, 2.0), 6.0);
    EXPECT_EQ(Statistics::percentileSorted({}, 0.5), 0.0);
}

TEST(StatisticsTest, MillionSamplesAgreeWithClosedForm) {
    // A shuffled 0..999999: mean 499999.5 and median 499999.5 exactly; p99: h = 999999 * 0.99 =
    // 989999.01 -> 989999.01; MAD: deviations are 0.5, 0.5, 1.5, 1.5, ... -> median 250000;
    // sample stddev sqrt(n (n + 1) / 12) = sqrt(1e6 * 1000001 / 12). Tolerances: the order statistics
    // and the mean are exact up to 1e-6 absolute; the naive sum of 1e6 squared deviations (~1e11 each)
    // carries ~1e-12 relative rounding, so stddev is checked to 1e-9 relative. Also keeps the
    // O(n log n) path honest (well under a second at 1e6).
    std::vector<double> v(1000000);
    for (size_t i = 0; i < v.size(); ++i) v[i] = double(i);
    std::shuffle(v.begin(), v.end(), std::mt19937(7));
    Statistics s = Statistics::compute(v);
    EXPECT_NEAR(s.mean, 499999.5, 1e-6);
    EXPECT_NEAR(s.median, 499999.5, 1e-6);
    EXPECT_NEAR(s.p99, 989999.01, 1e-6);
    EXPECT_NEAR(s.mad, 250000.0, 1e-6);
    double expectedStddev = std::sqrt(1e6 * 1000001.0 / 12.0);
    EXPECT_NEAR(s.stddev, expectedStddev, 1e-9 * expectedStddev);
}
} // namespace
