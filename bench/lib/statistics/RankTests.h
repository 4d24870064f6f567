#pragma once
// Distribution-free tests for the wall-time gate (layer C). Wall times on a shared machine are skewed
// and carry outliers (a neighbour's burst makes one round 45% slow), so the gate uses rank tests,
// which need no normality and which one wild round moves by one rank only:
//   - wilcoxonSignedRank: paired, on the per-round log ratios log(head_i / base_i) of interleaved
//     rounds: "is the median log ratio 0?". The main test of the gate.
//   - signTest: paired, the count of rounds where head was slower. Weaker than Wilcoxon (it ignores
//     sizes) but needs not even symmetry; reported beside it as a cross-check.
//   - mannWhitneyU: unpaired, for two files of repeated rounds that were not interleaved (`bench
//     compare`), as Google Benchmark's compare.py does over >= 9 repetitions.
// Every p-value is two-sided. Exact distributions are computed by dynamic programming over (doubled)
// midranks, so ties are handled exactly (the permutation distribution given the tie pattern) rather
// than by a correction; above the exact limits the normal approximation with tie correction and a
// continuity correction of 1/2 is used.
#include <cstddef>
#include <vector>

namespace sb::ci {

/// The outcome of one rank test.
struct RankTest {
    double statistic = 0; ///< Wilcoxon: W+ (sum of ranks of positive values); sign: # positive; MWU: U of a
    double p = 1;         ///< two-sided p-value
    size_t n = 0;         ///< values used (Wilcoxon and sign: non-zero values; MWU: n1 + n2)
    bool exact = false;   ///< true when p comes from the exact distribution, false for the normal one
};

/// Exact distributions up to this many non-zero paired values (2^25 sign patterns, counted by DP).
constexpr size_t kWilcoxonExactMax = 25;
/// Exact Mann-Whitney distribution while both samples have at most this many values.
constexpr size_t kMannWhitneyExactMax = 20;

/// Wilcoxon signed-rank test of "median of d is 0", d being paired differences (log ratios). Zeros are
/// dropped (Wilcoxon's original treatment, scipy's zero_method="wilcox"); ties among |d| get midranks.
/// With no non-zero value p = 1. Exact for n <= kWilcoxonExactMax. NaN or empty d: sb::Error.
RankTest wilcoxonSignedRank(const std::vector<double>& d);

/// Two-sided sign test: k positives among the n non-zero values, p = min(1, 2 P(Bin(n, 1/2) <= min(k,
/// n - k))). Always exact. NaN or empty d: sb::Error.
RankTest signTest(const std::vector<double>& d);

/// Mann-Whitney U test of "a and b come from one distribution"; U counts pairs with a_i > b_j plus
/// half the ties. Exact while n1, n2 <= kMannWhitneyExactMax. NaN or an empty sample: sb::Error.
RankTest mannWhitneyU(const std::vector<double>& a, const std::vector<double>& b);

} // namespace sb::ci
