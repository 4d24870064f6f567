#pragma once
// The run loop on Vulkan (bench/run/Harness.h on GL; docs/ARCHITECTURE.md, "Vulkan"): one device, one
// scene, one set of frame targets and one submitter, shared by the run's techniques.
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
// where bench/run/VulkanTimerTrust.h trusts them, as on GL. Scenes in motion are GL-only for now: a
// moving scene is refused (exit 3) with its reason.
#include <memory>
#include <string>
#include <vector>

#include "bench/run/Harness.h"
#include "bench/run/RunConfig.h"
#include "scenes/Scene.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/TimestampRing.h"

namespace sb {

class VulkanHarness {
public:
    /// Creates the device (config.vulkan), loads the scene, allocates targets and uploads geometry.
    explicit VulkanHarness(const RunConfig& config);
    ~VulkanHarness();

    const RunConfig& config() const { return mConfig; }
    const Scene& scene() const { return mScene; }
    const std::string& contentHash() const { return mContentHash; }
    VulkanContext& context() { return *mContext; }
    const VulkanContext& context() const { return *mContext; }
    VulkanTargets& targets() { return *mTargets; }
    const TimerVerdict& timerVerdict() const { return mVerdict; }
    const glm::mat4& view() const { return mView; }
    const glm::mat4& projection() const { return mProj; }
    double sceneLoadMs() const { return mSceneLoadMs; }
    /// What the rows and the console header take from this run (api "vulkan").
    RowSource rowSource() const;

    /// setScene and compile (untimed).
    void prepare(VulkanTechnique& technique);
    /// One frame, recorded, submitted and waited for.
    FrameSample renderFrame(VulkanTechnique& technique);
    /// Warm-up, measured frames, statistics and one census frame (submitted work per pass).
    RunResult measure(VulkanTechnique& technique);
    /// Validation messages so far (with --vk-validation), each once: a run prints them.
    std::vector<std::string> takeValidationMessages();

private:
    RunResult summarize(VulkanTechnique& technique, std::vector<FrameSample> samples);
    FrameLoads census(VulkanTechnique& technique);

    RunConfig mConfig;
    Scene mScene;
    std::string mContentHash;
    CameraPreset mCamera;
    glm::mat4 mView{1.0f}, mProj{1.0f};
    FrameUniformData mFrameData{};
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
    TimerVerdict mCalibration;                ///< what the frames are measured under
    TimerVerdict mVerdict;                    ///< what the last run ended with
    uint64_t mFrameIndex = 0;
    size_t mMessagesShown = 0;
    double mSceneLoadMs = 0.0;
};

} // namespace sb
