#pragma once
// The run loop on Vulkan (bench/lib/harness/MeasuredHarness.h holds the loop itself; docs/ARCHITECTURE.md,
// "Vulkan"): one device, its frame targets, submitter, pipelines and shader modules, the timestamp ring
// and the census's pipeline-statistics queries.
//
// Per frame, in this order:
//   t0  begin the frame's command buffer, write the frame block, the timestamp slot, clear the targets
//       technique.execute() records its passes (each begins with a timestamp)
//       end the command buffer, vkQueueSubmit
//   t1  CPU record + submit = t1 - t0 (the `cpu_submit_ms` of a Vulkan row)
//       vkWaitForFences
//   t2  wall = t2 - t0
// One command buffer, re-recorded every frame as an application's render loop records it (retained:
// a draw per instance; instanced: a draw per mesh). Timestamps are read back frames later and shown only
// where bench/lib/harness/VulkanTimerTrust.h trusts them, as on GL. A scene in motion moves at the start of
// each frame, inside t0..t1 as on GL (`motion_ms`): the submitter's instance records follow the casters and
// the technique's sceneChanged runs before anything is recorded.
#include <memory>
#include <string>
#include <vector>

#include "bench/lib/harness/MeasuredHarness.h"
#include "bench/lib/options/RunConfig.h"
#include "reference/VulkanGBufferRenderer.h"
#include "scenes/Scene.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/TimestampRing.h"

namespace sb {

class VulkanHarness final : public MeasuredHarness {
public:
    /// Creates the device (config.vulkan), loads the scene, allocates targets and uploads geometry.
    explicit VulkanHarness(const RunConfig& config);
    ~VulkanHarness() override;

    Api api() const override { return Api::Vulkan; }
    VulkanContext& context() { return *mContext; }
    const VulkanContext& context() const { return *mContext; }
    VulkanTargets& targets() { return *mTargets; }
    RowSource rowSource() const override;
    const TimerVerdict& calibrateTimer() override;

    /// Checks the Vulkan capabilities (exit 3 naming the missing one), then setScene and compile
    /// (untimed). `technique` must be a Vulkan form (VulkanTechnique).
    void prepare(Technique& technique) override;
    /// One frame, recorded, submitted and waited for.
    FrameSample renderFrame(Technique& technique) override;
    std::vector<unsigned char> readColor() override { return mTargets->readColorRGBA8(); }
    std::vector<float> readVisibility() override { return mTargets->readVisibilityRGBA32F(); }
    /// reference/VulkanGBufferRenderer.h with this harness's submitter and a slot of its frame block
    /// written for the current camera: no GL anywhere in a Vulkan run's judgement.
    GBuffer renderGBuffer() override;
    /// Validation messages so far (with --vk-validation), each once: a run prints them.
    std::vector<std::string> takeValidationMessages() override;
    size_t validationErrors() const override { return mContext->validationErrors(); }

private:
    void setVisibilityOutput(bool on) override { mTargets->setVisibilityOutput(on); }
    std::vector<PassTimes> collectGpuTimes(bool wait) override;
    TimerVerdict recalibrate() override;
    FrameLoads census(Technique& technique) override;
    void instancesMoved() override;
    static VulkanTechnique& vulkanForm(Technique& technique);

    std::unique_ptr<VulkanContext> mContext;
    std::unique_ptr<VulkanTargets> mTargets;
    std::unique_ptr<ShaderModuleCache> mShaders;
    std::unique_ptr<VulkanPipelineCache> mPipelines;
    std::unique_ptr<VulkanFrameBlock> mFrameBlock;
    std::unique_ptr<VulkanSubmitter> mSubmitter;
    std::unique_ptr<TimestampRing> mRing;
    VulkanPassTimer mPasses;
    VkCommandBuffer mCmd = VK_NULL_HANDLE;
    VkFence mFence = VK_NULL_HANDLE;
    VkQueryPool mStatistics = VK_NULL_HANDLE; ///< the census's pipeline statistics (where supported)
    size_t mMessagesShown = 0;
    std::unique_ptr<VulkanGBufferRenderer> mGBuffer; ///< created on the first renderGBuffer
};

} // namespace sb
