#include "bench/lib/statistics/WallTimeStats.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <numbers>
#include <string>
#include <tuple>

#include "bench/lib/statistics/Normal.h"
#include "bench/lib/statistics/Statistics.h"
#include "core/Error.h"
#include "core/SplitMix64.h"

namespace sb::ci {

namespace {

double medianOf(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return Statistics::percentileSorted(v, 0.5);
}

void checkMdeArguments(double sd, size_t n, double alpha, double power, const char* where) {
    if (!(sd >= 0) || n < 1 || !(alpha > 0 && alpha < 1) || !(power > 0 && power < 1))
        throw Error(std::string(where) + ": needs sd >= 0, n >= 1, alpha and power in (0, 1) (got sd " +
                        std::to_string(sd) + ", n " + std::to_string(n) + ", alpha " + std::to_string(alpha) +
                        ", power " + std::to_string(power) + ")",
                    ExitCode::BadInput);
}

/// Two-sided exact (or, above kWilcoxonExactMax, approximate) p of every W+ = 0 .. n(n+1)/2 for n
/// untied values, from wilcoxonSignedRank itself: signed ranks whose positive part sums to w, chosen
/// greedily from n down (every w in range is reachable that way).
std::vector<double> wilcoxonPByStatistic(size_t n) {
    const long total = long(n * (n + 1) / 2);
    std::vector<double> p(size_t(total) + 1);
    for (long w = 0; w <= total; ++w) {
        std::vector<double> d;
        long left = w;
        for (long k = long(n); k >= 1; --k) {
            const bool positive = left >= k;
            left -= positive ? k : 0;
            d.push_back(positive ? double(k) : -double(k));
        }
        p[size_t(w)] = wilcoxonSignedRank(d).p;
    }
    return p;
}

/// The standardised MDE shift c = log(1 + MDE) / s of the exact Wilcoxon test (see the header).
double wilcoxonShiftCoefficient(size_t n, double alpha, double power) {
    constexpr int kDatasets = 4000;
    constexpr double kMaxShift = 20; // 20 sd: beyond it every sign is + and more shift cannot help
    const std::vector<double> pOf = wilcoxonPByStatistic(n);
    if (pOf.back() >= alpha) return std::numeric_limits<double>::infinity();
    // Standard normal noise by Box-Muller on SplitMix64 (reproducible on every standard library).
    SplitMix64 rng(0x5EEDull + n);
    std::vector<double> noise(size_t(kDatasets) * n);
    for (double& z : noise) {
        const double u1 = 1.0 - rng.uniform(), u2 = rng.uniform();
        z = std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
    }
    std::vector<std::pair<double, bool>> shifted(n);
    auto powerAt = [&](double c) {
        int rejected = 0;
        for (int k = 0; k < kDatasets; ++k) {
            for (size_t i = 0; i < n; ++i) {
                const double x = noise[size_t(k) * n + i] + c;
                shifted[i] = {std::abs(x), x > 0};
            }
            std::sort(shifted.begin(), shifted.end());
            long w = 0;
            for (size_t i = 0; i < n; ++i) w += shifted[i].second ? long(i + 1) : 0;
            rejected += pOf[size_t(w)] < alpha ? 1 : 0;
        }
        return double(rejected) / kDatasets;
    };
    if (powerAt(kMaxShift) < power) return std::numeric_limits<double>::infinity();
    double lo = 0, hi = kMaxShift;
    for (int step = 0; step < 40; ++step) {
        const double mid = (lo + hi) / 2;
        (powerAt(mid) >= power ? hi : lo) = mid;
    }
    return hi;
}

} // namespace

std::pair<double, double> bootstrapMedianCI(const std::vector<double>& values, double confidence,
                                            uint64_t seed, int resamples) {
    if (values.empty() || resamples < 1 || !(confidence > 0 && confidence < 1))
        throw Error("bootstrapMedianCI: needs values, resamples >= 1 and confidence in (0, 1) (got " +
                        std::to_string(values.size()) + " values, " + std::to_string(resamples) +
                        " resamples, confidence " + std::to_string(confidence) + ")",
                    ExitCode::BadInput);
    SplitMix64 rng(seed);
    const size_t n = values.size();
    std::vector<double> medians(static_cast<size_t>(resamples));
    std::vector<double> sample(n);
    for (double& m : medians) {
        // uniform() * n: the index from the top 53 bits, free of the modulo bias of next() % n.
        for (double& x : sample) x = values[std::min(n - 1, size_t(rng.uniform() * double(n)))];
        m = medianOf(sample);
    }
    std::sort(medians.begin(), medians.end());
    const double tail = (1 - confidence) / 2;
    return {Statistics::percentileSorted(medians, tail), Statistics::percentileSorted(medians, 1 - tail)};
}

double mdeNormal(double sd, size_t n, double alpha, double power) {
    checkMdeArguments(sd, n, alpha, power, "mdeNormal");
    const double z = normalQuantile(1 - alpha / 2) + normalQuantile(power);
    return std::exp(z * sd / std::sqrt(double(n))) - 1;
}

double mdeWilcoxon(double sd, size_t n, double alpha, double power) {
    checkMdeArguments(sd, n, alpha, power, "mdeWilcoxon");
    static std::mutex mutex;
    static std::map<std::tuple<size_t, double, double>, double> cache;
    double c;
    {
        std::lock_guard<std::mutex> lock(mutex);
        const auto key = std::make_tuple(n, alpha, power);
        auto it = cache.find(key);
        if (it == cache.end()) it = cache.emplace(key, wilcoxonShiftCoefficient(n, alpha, power)).first;
        c = it->second;
    }
    if (std::isinf(c)) return c;
    return std::exp(c * sd) - 1;
}

WallTimeStats WallTimeStats::compute(const std::vector<double>& base, const std::vector<double>& head,
                                     double confidence, uint64_t seed, int resamples) {
    if (base.size() != head.size() || base.size() < 2)
        throw Error("WallTimeStats: base and head need the same number of rounds, at least 2 (got " +
                        std::to_string(base.size()) + " and " + std::to_string(head.size()) + ")",
                    ExitCode::BadInput);
    std::vector<double> ratios, logs;
    for (size_t i = 0; i < base.size(); ++i) {
        if (!(base[i] > 0 && head[i] > 0 && std::isfinite(base[i]) && std::isfinite(head[i])))
            throw Error("WallTimeStats: round " + std::to_string(i) +
                            " has a time that is not a positive number",
                        ExitCode::BadInput);
        ratios.push_back(head[i] / base[i]);
        logs.push_back(std::log(head[i] / base[i]));
    }
    WallTimeStats s;
    s.n = ratios.size();
    s.medianRatio = medianOf(ratios);
    std::tie(s.ciLow, s.ciHigh) = bootstrapMedianCI(ratios, confidence, seed, resamples);
    s.confidence = confidence;
    double mean = 0;
    for (double l : logs) mean += l / double(s.n);
    double squares = 0;
    for (double l : logs) squares += (l - mean) * (l - mean);
    s.logSd = std::sqrt(squares / double(s.n - 1));
    s.wilcoxon = wilcoxonSignedRank(logs);
    s.sign = signTest(logs);
    return s;
}

} // namespace sb::ci
