#pragma once
// `reference` on Vulkan: ReferenceGL's three passes with the same declaration, properties, tracer and
// counters (reference/ReferenceGL.h says what each pass does).
//   gbuffer  reference/VulkanGBufferRenderer.h with the frame's camera (its frame-block slot) and the
//            run's submitter; submitted and waited for on a command buffer of its own while the frame
//            is being recorded, because the trace needs its samples on the CPU now (GL's glReadPixels
//            waits the same way), so its GPU time lands in this pass's CPU span, not in a timestamp;
//   trace    ReferenceTracer on the CPU, as GL; the visibility (channel i = light i, -1 off geometry)
//            written into a host-visible staging buffer, its rows flipped to Vulkan's order;
//   shade    the staging buffer copied into an RGBA32F image (recorded in the frame, outside a render
//            pass), then common/scene.vert + reference/shade.frag over DrawSet::All into the frame
//            targets, the image fetched at gl_FragCoord (set 1, binding 0).
// Staging buffer, image, sampler, descriptor set and both pipelines are made in compile(); a frame
// allocates nothing on the device and writes no descriptor.
#include <memory>
#include <vector>

#include "reference/EmbreeScene.h"
#include "reference/GBuffer.h"
#include "reference/ReferenceTracer.h"
#include "reference/VulkanGBufferRenderer.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

class ReferenceVulkan final : public VulkanTechnique {
public:
    ReferenceVulkan();
    ~ReferenceVulkan() override;
    void setScene(const Scene& scene) override;
    /// As ReferenceGL: moving casters rebuild the Embree scene; the tracer reads the lights as they are.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    /// ReferenceGL's: draw_calls, triangles (G-buffer and shade passes), rays, rays_per_second_per_thread,
    /// noise_bound, samples_per_pixel.
    Counters counters() const override { return mCounters; }

private:
    /// The G-buffer renderer, visibility image, staging buffer and descriptor set for `ctx`'s targets
    /// (kept while the size is the same).
    void ensureTargets(const VulkanCompileContext& ctx);
    void trace();
    void writeVisibility();
    void recordUpload(VkCommandBuffer cmd);
    void updateCounters(const SubmitStats& shadeStats);
    void release();

    const Scene* mScene = nullptr;
    std::unique_ptr<EmbreeScene> mEmbree;
    std::unique_ptr<ReferenceTracer> mTracer;
    VkDevice mDevice = VK_NULL_HANDLE;
    std::unique_ptr<VulkanGBufferRenderer> mGBufferRenderer;
    VulkanImage mVisibilityImage;
    VulkanBuffer mStaging; ///< host-visible, w * h RGBA32F, rows top-down
    VkSampler mSampler = VK_NULL_HANDLE;
    DescriptorSets mSets;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    ScenePipeline mShadePipeline;
    int mWidth = 0, mHeight = 0;
    GBuffer mGBuffer;
    std::vector<VisibilityImage> mVisibility;
    std::vector<TraceStats> mTraceStats;
    Counters mCounters;
};

} // namespace sb
