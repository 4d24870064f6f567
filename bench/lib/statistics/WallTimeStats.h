#pragma once
// The paired analysis of one configuration in the wall-time gate (layer C of the perf-regression
// gate; layers A and B count work and instructions exactly, this one measures time and must therefore
// reason about noise). Input: per round i (base and head run back to back, in the order of
// interleave(), see Interleave.h), base_i and head_i, each the median of that round's frame times.
// Everything works on r_i = head_i / base_i and l_i = log r_i: a ratio is what a reader wants ("7%
// slower"), and the log makes a 2x slowdown and a 2x speedup symmetric (+-0.69).
//
// Bootstrap: percentile interval, not BCa. The median of 9 values takes at most 9 distinct values over
// all resamples, so BCa's bias correction z0 (from the share of resamples below the estimate, a quarter
// of which equal it exactly) and its acceleration (a jackknife, which is inconsistent for the median)
// are ruled by that discreteness rather than by skew; the percentile interval is simple and its
// coverage is checked by simulation (tests/WallTimeStatsTest.cpp: ~95% nominal on lognormal data).
//
// Minimum detectable effect (MDE), two ways, both two-sided at alpha with power 1 - beta (0.8):
//   mdeNormal:   MDE = exp((z_{1-alpha/2} + z_{power}) * s / sqrt(n)) - 1
//                the textbook z-test formula for the mean log ratio with sd s over n rounds (s treated
//                as known). Closed form, easy to quote; it is the large-n limit of the next one (the
//                rank test's efficiency against the t-test is 3/pi = 0.955 under normality) and
//                optimistic for small n: it ignores that s is estimated (a t-based version would widen
//                it) and that an exact rank test at small alpha has only a few rejecting outcomes.
//   mdeWilcoxon: the smallest shift log(1 + MDE) = c * s at which the gate's actual test (the exact
//                Wilcoxon signed-rank test at alpha) rejects in >= power of 4000 simulated normal
//                datasets of n rounds, found by bisection on c with common random numbers (W+ only
//                grows with the shift, so the power is monotone). c depends only on (n, alpha, power)
//                because the test is scale-free, so it is computed once per triple and cached. It is
//                infinite when no outcome of n rounds can reach alpha (2^(1-n) >= alpha, e.g. n <= 8 at
//                alpha 0.005, n <= 10 at 0.005 / 4). This is the MDE the verdict uses and prints.
// Both are ratios minus 1 (0.27 = "could detect >= 27% slowdowns").
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "bench/lib/statistics/RankTests.h"

namespace sb::ci {

/// Head against base over n interleaved rounds (or an A/A control: the same build twice).
struct WallTimeStats {
    size_t n = 0;             ///< rounds
    double medianRatio = 1;   ///< median of r_i (type 7: the mean of the two middle ratios for even n)
    double ciLow = 1;         ///< percentile bootstrap interval of the median ratio at `confidence`
    double ciHigh = 1;        ///< (same)
    double confidence = 0.95; ///< of [ciLow, ciHigh]
    double logSd = 0;         ///< sample sd (n - 1) of l_i: the noise the MDE is computed from
    RankTest wilcoxon;        ///< on l_i: the gate's test
    RankTest sign;            ///< on l_i: the cross-check

    /// base and head: one positive time per round, same length, at least 2 rounds; anything else is
    /// bad input (sb::Error). `seed` and `resamples` drive the bootstrap, so one input gives one result.
    static WallTimeStats compute(const std::vector<double>& base, const std::vector<double>& head,
                                 double confidence = 0.95, uint64_t seed = 1, int resamples = 2000);
};

/// Percentile bootstrap interval {low, high} of the median (type 7) of `values` at `confidence` in
/// (0, 1): `resamples` resamples with replacement drawn by SplitMix64(seed). Empty values, resamples
/// < 1 or confidence outside (0, 1): sb::Error.
std::pair<double, double> bootstrapMedianCI(const std::vector<double>& values, double confidence,
                                            uint64_t seed, int resamples = 2000);

/// The closed-form MDE above (ratio minus 1). sd >= 0, n >= 1, alpha and power in (0, 1).
double mdeNormal(double sd, size_t n, double alpha, double power = 0.8);

/// The simulated MDE of the exact Wilcoxon test above (ratio minus 1, or +infinity). Same arguments.
double mdeWilcoxon(double sd, size_t n, double alpha, double power = 0.8);

} // namespace sb::ci
