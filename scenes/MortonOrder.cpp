#include "scenes/MortonOrder.h"

#include <algorithm>
#include <numeric>

namespace sb {

namespace {

constexpr uint32_t kCells = 1024; // 10 bits per axis: 30 bits in all

/// `v` in [lo, hi] as a cell 0..kCells-1 (0 when the interval is empty).
uint32_t quantise(float v, float lo, float hi) {
    if (!(hi > lo)) return 0;
    const float t = std::clamp((v - lo) / (hi - lo), 0.0f, 1.0f);
    return std::min(kCells - 1, uint32_t(t * float(kCells)));
}

/// The 10 low bits of `v` spread out to every third bit (bit i to bit 3i).
uint32_t spreadBits(uint32_t v) {
    v &= 0x3FFu;
    v = (v | (v << 16)) & 0x030000FFu;
    v = (v | (v << 8)) & 0x0300F00Fu;
    v = (v | (v << 4)) & 0x030C30C3u;
    v = (v | (v << 2)) & 0x09249249u;
    return v;
}

} // namespace

uint32_t mortonCode(const glm::vec3& p, const Aabb& bounds) {
    const uint32_t x = quantise(p.x, bounds.min.x, bounds.max.x);
    const uint32_t y = quantise(p.y, bounds.min.y, bounds.max.y);
    const uint32_t z = quantise(p.z, bounds.min.z, bounds.max.z);
    return spreadBits(x) | (spreadBits(y) << 1) | (spreadBits(z) << 2);
}

std::vector<size_t> mortonOrder(const std::vector<glm::vec3>& points) {
    Aabb bounds;
    for (const glm::vec3& p : points) bounds.extend(p);
    std::vector<uint32_t> codes(points.size());
    for (size_t i = 0; i < points.size(); ++i) codes[i] = mortonCode(points[i], bounds);
    std::vector<size_t> order(points.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return codes[a] < codes[b]; });
    return order;
}

} // namespace sb
