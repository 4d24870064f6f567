#include "techniques/shadowmap/CascadeSplits.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "scenes/InstanceCulling.h"

namespace sb {

std::vector<float> CascadeSplits::practical(float nearZ, float farZ, int count, float lambda) {
    std::vector<float> c(size_t(count) + 1);
    const double n = nearZ, f = farZ, l = lambda;
    for (int i = 0; i <= count; ++i) {
        const double s = double(i) / double(count);
        const double logSplit = n * std::pow(f / n, s);
        const double uniSplit = n + (f - n) * s;
        c[size_t(i)] = float(l * logSplit + (1.0 - l) * uniSplit);
    }
    c.front() = nearZ; // exactly the ends, whatever pow rounds to
    c.back() = farZ;
    return c;
}

glm::vec2 CascadeSplits::nearFar(const glm::mat4& proj) {
    const double a = proj[2][2], b = proj[3][2];
    if (proj[2][3] != 0.0f) // perspective: w = -z
        return {float(b / (a - 1.0)), float(b / (a + 1.0))};
    return {float((b + 1.0) / a), float((b - 1.0) / a)}; // orthographic
}

glm::vec2 CascadeSplits::clipToReceivers(glm::vec2 nearFar, const glm::mat4& view, const glm::mat4& proj,
                                         const std::vector<Aabb>& receivers) {
    const glm::mat4 viewProj = proj * view;
    float lo = FLT_MAX, hi = -FLT_MAX;
    for (const Aabb& box : receivers) {
        if (!InstanceCulling::mayReach(box, viewProj, CullPlanes::All)) continue;
        for (const glm::vec3& c : box.corners()) {
            const float depth = -(view * glm::vec4(c, 1.0f)).z;
            lo = std::min(lo, depth);
            hi = std::max(hi, depth);
        }
    }
    if (lo > hi) return nearFar;
    return pad(lo, hi, nearFar);
}

glm::vec2 CascadeSplits::pad(float lo, float hi, glm::vec2 nearFar) {
    const float margin = 0.01f * (hi - lo) + 1e-5f * nearFar.y;
    const float n = std::clamp(lo - margin, nearFar.x, nearFar.y);
    float f = std::clamp(hi + margin, nearFar.x, nearFar.y);
    f = std::max(f, std::min(nearFar.y, n + 1e-4f * nearFar.y));
    return {n, std::max(f, n * (1.0f + 1e-6f))};
}

std::vector<float> CascadeSplits::sampleDistribution(glm::vec2 samples, glm::vec2 nearFar, int count) {
    const glm::vec2 range = samples.x > samples.y ? nearFar : pad(samples.x, samples.y, nearFar);
    return practical(range.x, range.y, count, 1.0f);
}

} // namespace sb
