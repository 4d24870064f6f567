#pragma once
// One frame of a technique rendered through the Vulkan harness (lavapipe) with the Khronos validation
// layer on, and the check that the layer reported no error: the set-up of every test that runs a whole
// technique on Vulkan (tests/ShadowMapVkTest.cpp, tests/GlVulkanImageVkTest.cpp,
// tests/hard/HardCaseVkTest.cpp). The tests of vk/ alone use the VulkanTest fixture of
// tests/VkTestSupport.h; this header needs bench/ and registry/, so it is kept apart from that one and
// those tests still link sb_vk only (tests/CMakeLists.txt).
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "VkTestSupport.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "bench/lib/options/RunConfig.h"
#include "registry/TechniqueRegistry.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb::test {

/// "" where the default device (lavapipe of the driver this process runs on) has what the Vulkan form of
/// technique `spec` needs, else its refusal: raytraced needs ray queries, which Mesa 22.3.6 lacks. A test
/// run in-process on the system driver skips such a technique with this message.
inline std::string vulkanRefusal(const std::string& spec) {
    const VulkanContext context(VulkanOptions{});
    return TechniqueRegistry::createVulkan(TechniqueSpec::parse(spec))->checkCapabilities(context);
}

class VulkanFrame {
public:
    /// Runs `config` on Vulkan with the validation layer on (whatever its api and vulkan.validation
    /// said), creates the Vulkan form of the technique `spec` ("shadowmap:pcf=3"), prepares it and
    /// renders one frame. Throws what the harness or the registry throws.
    VulkanFrame(const RunConfig& config, const std::string& spec)
        : mHarness(withValidation(config)),
          mTechnique(TechniqueRegistry::createVulkan(TechniqueSpec::parse(spec))) {
        mHarness.prepare(*mTechnique);
        mHarness.renderFrame(*mTechnique);
    }
    /// Expects that the layer reported no error so far (a non-fatal failure printing the errors when it
    /// did), then releases the technique before the harness's device.
    ~VulkanFrame() {
        EXPECT_EQ(validationErrorLog(mHarness.context()), "");
        mTechnique.reset();
    }
    VulkanFrame(const VulkanFrame&) = delete;
    VulkanFrame& operator=(const VulkanFrame&) = delete;

    /// The harness after the frame: its targets, scene, camera matrices and context.
    VulkanHarness& harness() { return mHarness; }
    /// The technique that rendered the frame.
    VulkanTechnique& technique() { return *mTechnique; }

private:
    static RunConfig withValidation(RunConfig config) {
        config.api = RunConfig::Api::Vulkan;
        config.vulkan.validation = true;
        return config;
    }

    VulkanHarness mHarness;
    std::unique_ptr<VulkanTechnique> mTechnique; ///< declared after mHarness: released before it
};

} // namespace sb::test
