#include "bench/Statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "scenes/Error.h"

namespace sb {

double Statistics::percentileSorted(const std::vector<double>& sorted, double q) {
    if (sorted.empty()) return 0.0;
    // Type 7: h = (n - 1) q, interpolate between floor(h) and floor(h) + 1.
    double h = (double(sorted.size()) - 1.0) * std::clamp(q, 0.0, 1.0);
    size_t lo = size_t(std::floor(h));
    size_t hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (h - double(lo)) * (sorted[hi] - sorted[lo]);
}

Statistics Statistics::compute(std::vector<double> samples) {
    Statistics s;
    s.n = samples.size();
    if (samples.empty()) return s;
    if (std::any_of(samples.begin(), samples.end(), [](double v) { return std::isnan(v); }))
        throw Error("statistics: a NaN sample would corrupt the order statistics", ExitCode::Failure);
    std::sort(samples.begin(), samples.end());
    s.min = samples.front();
    s.max = samples.back();
    s.median = percentileSorted(samples, 0.5);
    s.p5 = percentileSorted(samples, 0.05);
    s.p95 = percentileSorted(samples, 0.95);
    s.p99 = percentileSorted(samples, 0.99);
    s.mean = std::accumulate(samples.begin(), samples.end(), 0.0) / double(s.n);
    double ss = 0.0;
    for (double v : samples) ss += (v - s.mean) * (v - s.mean);
    s.stddev = s.n > 1 ? std::sqrt(ss / double(s.n - 1)) : 0.0;
    for (double& v : samples) v = std::abs(v - s.median); // reuse the buffer for the deviations
    std::sort(samples.begin(), samples.end());
    s.mad = percentileSorted(samples, 0.5);
    return s;
}

} // namespace sb
