#pragma once
// `synthetic` on Vulkan (techniques/vulkan/VulkanTechnique.h): SyntheticGL's calibration workloads
// recorded into the frame's command buffer, so `bench bottleneck --api vulkan` can check its classifier
// against workloads of known bottleneck on the Vulkan driver:
//   fill-bound:   fragment_iterations=N, draw_scene=false (a full-screen triangle, N steps per pixel);
//   vertex-bound: the scene's triangles with vertex_iterations=N;
//   CPU-bound:    many small instances in retained submission (one vkCmdDrawIndexed and one push per
//                 instance; Vulkan has no immediate mode, the CPU workload's GL submission).
// The same passes ("scene", "fill"), shaders (synthetic/, with push constants for the GL uniforms) and
// counters as SyntheticGL. Visibility is 1 everywhere.
#include "techniques/vulkan/ScenePass.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

class SyntheticVulkan final : public VulkanTechnique {
public:
    SyntheticVulkan();
    ~SyntheticVulkan() override;
    void setScene(const Scene&) override {}
    /// The workloads do not depend on where the lights and casters are (as SyntheticGL).
    void sceneChanged(const Scene&, uint32_t) override {}
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }

private:
    void recordScene(VulkanFrameContext& ctx);
    void recordFill(VulkanFrameContext& ctx);

    VkDevice mDevice = VK_NULL_HANDLE;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    ScenePipeline mScene, mFill;
    bool mDrawScene = false, mDrawFill = false;
    int mVertexIterations = 0, mFragmentIterations = 0; ///< read once per compile, not per frame
    Counters mCounters;
};

} // namespace sb
