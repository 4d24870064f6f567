#include "techniques/ViewDepth.h"

#include <algorithm>

namespace sb {

uint64_t ViewDepth::bytes(int width, int height) {
    return uint64_t(std::max(0, width)) * uint64_t(std::max(0, height)) * kTexelBytes;
}

std::string ViewDepth::describe(int width, int height, const std::string& user) {
    return std::to_string(width) + "x" + std::to_string(height) + " pixels x " + std::to_string(kTexelBytes) +
           " B (" + user + "'s view depth pre-pass)";
}

float ViewDepth::viewDepth(float window, const glm::mat4& proj) {
    // In double: near the far end of a 1:1000 perspective b / (z + a) divides by a small difference.
    const double a = proj[2][2], b = proj[3][2];
    const double z = 2.0 * double(window) - 1.0;
    return proj[2][3] != 0.0f ? float(b / (z + a)) : float((b - z) / a);
}

glm::vec2 ViewDepth::viewDepths(glm::vec2 window, const glm::mat4& proj) {
    return {viewDepth(window.x, proj), viewDepth(window.y, proj)};
}

} // namespace sb
