#include "techniques/shadowmap/PoissonDisk.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/SplitMix64.h"

namespace sb {

namespace {
constexpr int kMissesBeforeShrink = 1000;
constexpr double kShrink = 0.9;

/// A point uniform in the unit disk: rejection from the square (no trigonometry, exact in the disk).
glm::dvec2 dart(SplitMix64& rng) {
    for (;;) {
        glm::dvec2 p(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0));
        if (glm::dot(p, p) <= 1.0) return p;
    }
}

bool farFromAll(const std::vector<glm::dvec2>& kept, const glm::dvec2& p, double r) {
    for (const glm::dvec2& q : kept)
        if (glm::dot(p - q, p - q) < r * r) return false;
    return true;
}
} // namespace

std::vector<glm::vec2> PoissonDisk::generate(int count, uint64_t seed) {
    count = std::max(count, 1);
    SplitMix64 rng(seed);
    std::vector<glm::dvec2> kept;
    // Hexagonal packing of `count` discs of radius r/2 in the unit disk: count * (sqrt(3)/2) r^2 = pi.
    double r = count > 1 ? 0.85 * std::sqrt(2.0 * M_PI / (std::sqrt(3.0) * count)) : 0.0;
    int misses = 0;
    while (int(kept.size()) < count) {
        glm::dvec2 p = dart(rng);
        if (farFromAll(kept, p, r)) {
            kept.push_back(p);
            misses = 0;
        } else if (++misses >= kMissesBeforeShrink) {
            r *= kShrink;
            misses = 0;
        }
    }
    if (count == 1) return {glm::vec2(0.0f)};
    double meanSquare = 0.0;
    for (const glm::dvec2& p : kept) meanSquare += glm::dot(p, p);
    meanSquare /= double(kept.size());
    const double scale = std::sqrt(0.5 / meanSquare);
    std::vector<glm::vec2> out;
    out.reserve(kept.size());
    for (const glm::dvec2& p : kept) out.emplace_back(p * scale);
    return out;
}

float PoissonDisk::minDistance(const std::vector<glm::vec2>& points) {
    float best = std::numeric_limits<float>::infinity();
    for (size_t i = 0; i < points.size(); ++i)
        for (size_t j = i + 1; j < points.size(); ++j)
            best = std::min(best, glm::length(points[i] - points[j]));
    return best;
}

} // namespace sb
