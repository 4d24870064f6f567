#pragma once
// The separable Gaussian's weights that both APIs' blurs use (techniques/gl/SeparableBlur.h and
// techniques/vulkan/VulkanSeparableBlur.h, Kernel::TexelIntegral): a Gaussian of sigma = width / 4
// truncated to [-width / 2, width / 2], each tap's weight the integral of that truncated Gaussian over the
// tap's texel, [k - 0.5, k + 0.5], normalised to sum 1. Computed once, so both APIs blur with the same
// floats.
#include <vector>

namespace sb {

struct GaussianKernel {
    /// Taps 0..width/2 (the kernel is symmetric: tap -k has the weight of tap k); they sum to 1 over all
    /// 2 (width/2) + 1 taps. Width 0 and 1 give {1}.
    static std::vector<float> texelIntegral(int width);
};

} // namespace sb
