#include "techniques/ResourceEstimate.h"

#include <algorithm>

namespace sb {

namespace {

/// a * b, saturating: a hostile property combination must never wrap to a small estimate.
uint64_t times(uint64_t a, uint64_t b) {
    return a != 0 && b > UINT64_MAX / a ? UINT64_MAX : a * b;
}

uint64_t plus(uint64_t a, uint64_t b) {
    return b > UINT64_MAX - a ? UINT64_MAX : a + b;
}

} // namespace

ResourceEstimate squareMaps(int64_t resolution, uint64_t bytesPerTexel, uint64_t layers,
                            const ResourceInputs& in, uint64_t extraPerTexel) {
    const uint64_t lights = uint64_t(std::max(1, in.lights));
    const uint64_t texels = times(uint64_t(resolution), uint64_t(resolution));
    const uint64_t perTexel = plus(times(times(bytesPerTexel, layers), lights), extraPerTexel);
    std::string how = std::to_string(resolution) + "^2 texels x (" + std::to_string(bytesPerTexel) + " B";
    if (layers > 1) how += " x " + std::to_string(layers) + " layers";
    how += " x " + std::to_string(lights) + (lights == 1 ? " light" : " lights");
    if (extraPerTexel) how += " + " + std::to_string(extraPerTexel) + " B";
    return {times(texels, perTexel), how + ")"};
}

} // namespace sb
