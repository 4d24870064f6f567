#include "bench/lib/statistics/Statistics.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/Error.h"

namespace sb {

namespace {

// NaN breaks the strict weak ordering std::sort needs (the result is unspecified, not merely wrong
// at the NaN), and an infinity turns mean and stddev into inf/NaN. Either means a timer or a clock
// went wrong, which is a failed run rather than bad user input.
void rejectNonFinite(const std::vector<double>& samples) {
    for (size_t i = 0; i < samples.size(); ++i)
        if (!std::isfinite(samples[i]))
            throw Error("statistics: sample " + std::to_string(i) + " of " + std::to_string(samples.size()) +
                            " is " + std::to_string(samples[i]) + " (only finite samples can be summarised)",
                        ExitCode::Failure);
}

double meanOf(const std::vector<double>& v) {
    double sum = 0;
    for (double x : v) sum += x;
    return sum / double(v.size());
}

// Two-pass (sum of squared deviations from the already known mean) instead of sum(x^2) - n*mean^2:
// frame times are large numbers with small spread, where the one-pass formula cancels catastrophically.
double sampleStddev(const std::vector<double>& v, double mean) {
    if (v.size() < 2) return 0.0; // n-1 = 0: no spread can be estimated from one sample
    double ss = 0;
    for (double x : v) ss += (x - mean) * (x - mean);
    return std::sqrt(ss / double(v.size() - 1));
}

// Median absolute deviation, unscaled (no 1.4826 factor: the CSV reports the raw robust spread).
double medianAbsDeviation(const std::vector<double>& sorted, double median) {
    std::vector<double> dev;
    dev.reserve(sorted.size());
    for (double x : sorted) dev.push_back(std::abs(x - median));
    std::sort(dev.begin(), dev.end());
    return Statistics::percentileSorted(dev, 0.5);
}

} // namespace

Statistics Statistics::compute(std::vector<double> samples) {
    Statistics s;
    if (samples.empty()) return s;
    rejectNonFinite(samples);
    std::sort(samples.begin(), samples.end()); // the one O(n log n) step; every order statistic reads it
    s.n = samples.size();
    s.min = samples.front();
    s.max = samples.back();
    s.median = percentileSorted(samples, 0.5);
    s.p5 = percentileSorted(samples, 0.05);
    s.p95 = percentileSorted(samples, 0.95);
    s.p99 = percentileSorted(samples, 0.99);
    s.mean = meanOf(samples);
    s.stddev = sampleStddev(samples, s.mean);
    s.mad = medianAbsDeviation(samples, s.median);
    return s;
}

// Type 7 (R default, numpy "linear"): position h = (n-1) q between closest ranks, linear interpolation.
// q outside [0,1] is clamped so callers get min/max rather than an out-of-bounds read.
double Statistics::percentileSorted(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return 0.0;
    if (std::isnan(q)) throw Error("statistics: percentile of NaN requested", ExitCode::Failure);
    q = std::clamp(q, 0.0, 1.0);
    double h = double(sorted.size() - 1) * q;
    size_t lo = size_t(std::floor(h));
    size_t hi = std::min(lo + 1, sorted.size() - 1);
    double a = sorted[lo], b = sorted[hi];
    return a + (h - double(lo)) * (b - a);
}

} // namespace sb
