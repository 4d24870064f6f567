#pragma once
// Summary statistics of per-frame samples (docs/ARCHITECTURE.md, "The timing contract"): median, p5, p95,
// p99, mean, stddev (sample, n-1), MAD (median absolute deviation from the median, unscaled) and n.
// Percentiles use linear interpolation between closest ranks (R type 7 / numpy default), so
// percentile(0.5) of an even count is the mean of the two middle values.
#include <cstddef>
#include <vector>

namespace sb {

struct Statistics {
    size_t n = 0;
    double median = 0, p5 = 0, p95 = 0, p99 = 0, mean = 0, stddev = 0, mad = 0, min = 0, max = 0;

    /// Empty input gives n = 0 and zeros; NaN samples are rejected (sb::Error) since they would
    /// silently corrupt order statistics.
    static Statistics compute(std::vector<double> samples);
    /// Percentile q in [0,1] of sorted data (type 7 interpolation).
    static double percentileSorted(const std::vector<double>& sorted, double q);
};

} // namespace sb
