#include "bench/lib/statistics/RankTests.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "bench/lib/statistics/Normal.h"
#include "core/Error.h"

namespace sb::ci {

namespace {

void checkValues(const std::vector<double>& v, const char* where) {
    if (v.empty()) throw Error(std::string(where) + ": no values", ExitCode::BadInput);
    for (double x : v)
        if (std::isnan(x)) throw Error(std::string(where) + ": a value is NaN", ExitCode::BadInput);
}

/// Doubled midranks (integers: a tie group over ranks i+1..j gets i + j + 1) of `values`, and the
/// tie term sum(t^3 - t) over tie groups of size t for the normal approximation's variance.
std::vector<long> doubledMidranks(const std::vector<double>& values, double& tieTerm) {
    std::vector<size_t> order(values.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t x, size_t y) { return values[x] < values[y]; });
    std::vector<long> ranks(values.size());
    tieTerm = 0;
    for (size_t i = 0; i < order.size();) {
        size_t j = i;
        while (j < order.size() && values[order[j]] == values[order[i]]) ++j;
        for (size_t k = i; k < j; ++k) ranks[order[k]] = long(i + j + 1); // 2 * mean of ranks i+1..j
        const double t = double(j - i);
        tieTerm += t * t * t - t;
        i = j;
    }
    return ranks;
}

/// Two-sided p from the counts of a discrete null distribution of an integer statistic: twice the
/// smaller tail at the observed value, capped at 1.
double twoSidedFromCounts(const std::vector<double>& counts, long observed) {
    const double total = std::accumulate(counts.begin(), counts.end(), 0.0);
    double lower = 0, upper = 0;
    for (long s = 0; s < long(counts.size()); ++s) {
        if (s <= observed) lower += counts[size_t(s)];
        if (s >= observed) upper += counts[size_t(s)];
    }
    return std::min(1.0, 2 * std::min(lower, upper) / total);
}

/// Two-sided normal p with a continuity correction of 1/2 on the statistic's scale.
double twoSidedNormal(double statistic, double mean, double variance) {
    if (variance <= 0) return 1.0;
    const double z = std::max(0.0, std::abs(statistic - mean) - 0.5) / std::sqrt(variance);
    return std::min(1.0, 2 * normalCdf(-z));
}

} // namespace

RankTest wilcoxonSignedRank(const std::vector<double>& d) {
    checkValues(d, "wilcoxonSignedRank");
    std::vector<double> magnitude;
    std::vector<bool> positive;
    for (double x : d)
        if (x != 0) {
            magnitude.push_back(std::abs(x));
            positive.push_back(x > 0);
        }
    RankTest out;
    out.n = magnitude.size();
    if (out.n == 0) return out;
    double tieTerm = 0;
    const std::vector<long> ranks = doubledMidranks(magnitude, tieTerm);
    long observed = 0; // doubled W+
    for (size_t i = 0; i < ranks.size(); ++i)
        if (positive[i]) observed += ranks[i];
    out.statistic = double(observed) / 2;
    const double n = double(out.n);
    if (out.n <= kWilcoxonExactMax) {
        // Under H0 each sign is + or - with probability 1/2 independently: counts[s] is the number of
        // the 2^n sign patterns whose positive doubled ranks sum to s (subset-sum DP, at most 25 x 650).
        const long total = std::accumulate(ranks.begin(), ranks.end(), 0L);
        std::vector<double> counts(size_t(total) + 1, 0.0);
        counts[0] = 1;
        long reach = 0;
        for (long r : ranks) {
            reach += r;
            for (long s = reach; s >= r; --s) counts[size_t(s)] += counts[size_t(s - r)];
        }
        out.p = twoSidedFromCounts(counts, observed);
        out.exact = true;
    } else {
        const double variance = n * (n + 1) * (2 * n + 1) / 24 - tieTerm / 48;
        out.p = twoSidedNormal(out.statistic, n * (n + 1) / 4, variance);
    }
    return out;
}

RankTest signTest(const std::vector<double>& d) {
    checkValues(d, "signTest");
    size_t k = 0, n = 0;
    for (double x : d) {
        n += x != 0 ? 1 : 0;
        k += x > 0 ? 1 : 0;
    }
    RankTest out;
    out.statistic = double(k);
    out.n = n;
    out.exact = true;
    if (n == 0) return out;
    // P(Bin(n, 1/2) <= m) summed in log space (lgamma), exact enough for any n a gate will see.
    const size_t m = std::min(k, n - k);
    double tail = 0;
    for (size_t i = 0; i <= m; ++i)
        tail += std::exp(std::lgamma(double(n) + 1) - std::lgamma(double(i) + 1) -
                         std::lgamma(double(n - i) + 1) - double(n) * std::log(2.0));
    out.p = std::min(1.0, 2 * tail);
    return out;
}

RankTest mannWhitneyU(const std::vector<double>& a, const std::vector<double>& b) {
    checkValues(a, "mannWhitneyU (first sample)");
    checkValues(b, "mannWhitneyU (second sample)");
    std::vector<double> pooled = a;
    pooled.insert(pooled.end(), b.begin(), b.end());
    double tieTerm = 0;
    const std::vector<long> ranks = doubledMidranks(pooled, tieTerm);
    const size_t n1 = a.size(), n2 = b.size(), total = n1 + n2;
    long observed = 0; // doubled rank sum of a
    for (size_t i = 0; i < n1; ++i) observed += ranks[i];
    RankTest out;
    out.n = total;
    // U = R_a - n1 (n1 + 1) / 2, the number of (a_i > b_j) pairs plus half the ties.
    out.statistic = double(observed) / 2 - double(n1 * (n1 + 1)) / 2;
    if (n1 <= kMannWhitneyExactMax && n2 <= kMannWhitneyExactMax) {
        // Under H0 every choice of n1 of the pooled values as "a" is equally likely: counts[k][s] is the
        // number of k-subsets of the values seen so far whose doubled ranks sum to s (C(40, 20) = 1.4e11
        // fits a double exactly).
        const long maxSum = std::accumulate(ranks.begin(), ranks.end(), 0L);
        std::vector<std::vector<double>> counts(n1 + 1, std::vector<double>(size_t(maxSum) + 1, 0.0));
        counts[0][0] = 1;
        for (long r : ranks)
            for (size_t k = n1; k >= 1; --k)
                for (long s = maxSum; s >= r; --s) counts[k][size_t(s)] += counts[k - 1][size_t(s - r)];
        out.p = twoSidedFromCounts(counts[n1], observed);
        out.exact = true;
    } else {
        const double N = double(total);
        const double variance = double(n1) * double(n2) / 12 * ((N + 1) - tieTerm / (N * (N - 1)));
        out.p = twoSidedNormal(out.statistic, double(n1) * double(n2) / 2, variance);
    }
    return out;
}

} // namespace sb::ci
