#include "bench/lib/harness/VulkanHarness.h"

#include <algorithm>
#include <chrono>
#include <map>

#include "bench/lib/harness/VulkanTimerTrust.h"
#include "core/Error.h"
#include "core/Strings.h"
#include "scenes/Math.h"
#include "scenes/SceneLoader.h"

namespace sb {

namespace {
using Clock = std::chrono::steady_clock;
constexpr uint32_t kRingFrames = 4, kPassesPerFrame = 32;
} // namespace

VulkanHarness::VulkanHarness(const RunConfig& config) : MeasuredHarness(config, true) {
    mContext = std::make_unique<VulkanContext>(config.vulkan);
    mTargets = std::make_unique<VulkanTargets>(*mContext, config.width, config.height);
    mShaders = std::make_unique<ShaderModuleCache>(*mContext);
    mPipelines = std::make_unique<VulkanPipelineCache>(*mContext);
    mFrameBlock = std::make_unique<VulkanFrameBlock>(*mContext);
    mSubmitter = std::make_unique<VulkanSubmitter>(*mContext, config.submit);
    mSubmitter->setBackFaces(config.backFaces);
    mSubmitter->upload(scene());
    mShaders->setDumpDirectory(config.dumpShadersPath);
    if (mContext->timestampPeriodNs() > 0.0)
        mRing = std::make_unique<TimestampRing>(*mContext, kRingFrames, kPassesPerFrame);
    mPasses.setClock(&passClock());

    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = mContext->commandPool();
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VulkanContext::check(vkAllocateCommandBuffers(mContext->device(), &alloc, &mCmd),
                         "vkAllocateCommandBuffers");
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VulkanContext::check(vkCreateFence(mContext->device(), &fence, nullptr, &mFence), "vkCreateFence");
    if (mContext->pipelineStatistics()) {
        VkQueryPoolCreateInfo pool{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        pool.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
        pool.queryCount = VulkanPassTimer::kMaxCensusPasses;
        pool.pipelineStatistics = VulkanPassTimer::kStatistics;
        VulkanContext::check(vkCreateQueryPool(mContext->device(), &pool, nullptr, &mStatistics),
                             "vkCreateQueryPool (pipeline statistics)");
    }
}

VulkanHarness::~VulkanHarness() {
    if (!mContext) return;
    vkDeviceWaitIdle(mContext->device());
    vkDestroyFence(mContext->device(), mFence, nullptr);
    vkDestroyQueryPool(mContext->device(), mStatistics, nullptr);
    vkFreeCommandBuffers(mContext->device(), mContext->commandPool(), 1, &mCmd);
}

RowSource VulkanHarness::rowSource() const {
    const VulkanDeviceInfo& d = mContext->info();
    return {config(),     scene(),        contentHash(),
            moving(),     timerVerdict(), "vulkan",
            d.apiVersion, d.name,         "",
            d.driver,     "vulkan",       std::to_string(d.index) + ": " + d.name,
            d.driverInfo};
}

VulkanTechnique& VulkanHarness::vulkanForm(Technique& technique) {
    if (technique.api() != Api::Vulkan)
        throw Error(technique.name() + ": a " + apiName(technique.api()) +
                        " form handed to the Vulkan harness",
                    ExitCode::Failure);
    return static_cast<VulkanTechnique&>(technique);
}

const TimerVerdict& VulkanHarness::calibrateTimer() {
    mShaders->setDumpLabel("timer_trust");
    if (!calibration().checked) setCalibration(VulkanTimerTrust::calibrate(*mContext, *mShaders));
    return timerVerdict();
}

TimerVerdict VulkanHarness::recalibrate() {
    mShaders->setDumpLabel("timer_trust");
    return VulkanTimerTrust::calibrate(*mContext, *mShaders);
}

void VulkanHarness::instancesMoved() {
    // Retained draws push each instance's transform from the scene as it is now; instanced draws read
    // the instance buffer, rewritten in place (the previous frame's fence was waited for).
    mSubmitter->instancesMoved(scene());
}

std::vector<PassTimes> VulkanHarness::collectGpuTimes(bool) {
    // Every frame is waited for (its fence) before the next: what was written is there to read.
    if (!mRing || !timing()) return {};
    return mRing->collect();
}

std::vector<std::string> VulkanHarness::takeValidationMessages() {
    const auto& all = mContext->validationMessages();
    std::vector<std::string> out(all.begin() + long(std::min(mMessagesShown, all.size())), all.end());
    mMessagesShown = all.size();
    return out;
}

void VulkanHarness::prepare(Technique& technique) {
    VulkanTechnique& vk = vulkanForm(technique);
    const std::string missing = vk.checkCapabilities(*mContext);
    if (!missing.empty()) throw Error(missing, ExitCode::Unsupported);
    vk.setScene(scene());
    mShaders->setDumpLabel(technique.name());
    vk.compile({*mContext, *mShaders, scene(), *mSubmitter, *mTargets, *mFrameBlock, *mPipelines});
}

FrameSample VulkanHarness::renderFrame(Technique& technique) {
    VulkanTechnique& vk = vulkanForm(technique);
    FrameSample s;
    const auto t0 = Clock::now();
    passClock().frameBegins(t0);
    // A scene in motion moves first, as an application animates before it draws: part of the frame, as
    // on GL (the instance records rewritten, the techniques' sceneChanged, the frame block below).
    s.motionMs = advancePath(technique);
    VulkanContext::check(vkResetCommandBuffer(mCmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VulkanContext::check(vkBeginCommandBuffer(mCmd, &begin), "vkBeginCommandBuffer");
    mFrameBlock->beginFrame();
    const uint32_t frameOffset = mFrameBlock->write(frameData());
    const bool stamps = mRing && timing();
    const uint64_t frame = nextFrameIndex();
    mPasses.setRing(stamps ? mRing.get() : nullptr);
    mPasses.setCommandBuffer(mCmd);
    if (stamps) mRing->beginFrame(mCmd, frame);
    mTargets->recordClear(mCmd, 0.55f, 0.65f, 0.8f);
    VulkanFrameContext ctx{scene(), view(),       projection(), camera().eye, *mTargets, *mSubmitter,
                           mPasses, *mFrameBlock, frameOffset,  mCmd,         frame};
    vk.execute(ctx);
    mPasses.endCensusFrame();
    if (stamps) mRing->endFrame(mCmd);
    VulkanContext::check(vkEndCommandBuffer(mCmd), "vkEndCommandBuffer");
    mContext->submit(mCmd, mFence);
    const auto t1 = Clock::now();
    VulkanContext::check(vkWaitForFences(mContext->device(), 1, &mFence, VK_TRUE, UINT64_MAX),
                         "vkWaitForFences");
    const auto t2 = Clock::now();
    VulkanContext::check(vkResetFences(mContext->device(), 1, &mFence), "vkResetFences");
    recordFrameTimes(s, t0, t1, t2);
    return s;
}

GBuffer VulkanHarness::renderGBuffer() {
    if (!mGBuffer)
        mGBuffer = std::make_unique<VulkanGBufferRenderer>(*mContext, *mShaders, *mSubmitter, *mFrameBlock,
                                                           width(), height());
    // Between frames (the last frame's fence was waited for): slot 0 is free to hold this camera.
    mFrameBlock->beginFrame();
    return mGBuffer->render(*mSubmitter, mFrameBlock->write(frameData()));
}

FrameLoads VulkanHarness::census(Technique& technique) {
    // One more frame with the visibility target on: what each pass submitted, counted between the
    // passes' begins while the frame is recorded, and where the device counts them, what the pipeline
    // processed (a pipeline-statistics query per pass, as GL's census has one per pass).
    mPasses.startCensus(*mSubmitter, mStatistics);
    renderFrame(technique);
    FrameLoads loads;
    for (auto& [pass, work] : mPasses.finishCensus()) {
        loads.submitted += work;
        loads.passes.emplace_back(pass, PassWork{work, std::nullopt});
    }
    loads.skipped = mPasses.takeSkipped();
    const std::vector<std::string>& queried = mPasses.queriedPasses();
    if (!mStatistics || queried.empty()) return loads;
    std::vector<uint64_t> values(queried.size() * 4);
    VulkanContext::check(vkGetQueryPoolResults(mContext->device(), mStatistics, 0, uint32_t(queried.size()),
                                               values.size() * sizeof(uint64_t), values.data(),
                                               4 * sizeof(uint64_t),
                                               VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                         "vkGetQueryPoolResults (pipeline statistics)");
    PipelineCounts total;
    for (size_t q = 0; q < queried.size(); ++q) {
        PipelineCounts c;
        c.primitivesSubmitted = values[q * 4 + 0];
        c.vertexShaderInvocations = values[q * 4 + 1];
        c.clippingOutputPrimitives = values[q * 4 + 2];
        c.fragmentShaderInvocations = values[q * 4 + 3];
        total += c;
        for (auto& [pass, work] : loads.passes)
            if (pass == queried[q]) {
                if (!work.pipeline) work.pipeline = PipelineCounts{};
                *work.pipeline += c;
            }
    }
    loads.pipeline = total;
    return loads;
}

} // namespace sb
