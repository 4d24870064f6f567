#include "bench/run/VulkanHarness.h"

#include <algorithm>
#include <chrono>
#include <map>

#include "bench/run/VulkanTimerTrust.h"
#include "core/Error.h"
#include "core/Strings.h"
#include "scenes/Math.h"
#include "scenes/SceneLoader.h"

namespace sb {

namespace {
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}
constexpr uint32_t kRingFrames = 4, kPassesPerFrame = 32;
} // namespace

VulkanHarness::VulkanHarness(const RunConfig& config) : mConfig(config) {
    auto t0 = Clock::now();
    mScene = SceneLoader::load(config.scene, config.sceneOptions);
    mSceneLoadMs = msSince(t0, Clock::now());
    const CameraPreset* camera = mScene.findCamera(config.camera);
    if (!camera)
        throw Error("--camera " + config.camera + ": scene '" + mScene.name +
                    "' has no such camera (known: " +
                    join(mScene.cameras, ", ", [](const CameraPreset& c) { return c.name; }) + ")");
    mCamera = *camera;
    mContentHash = mScene.computeContentHash();
    if (mScene.motion)
        throw Error("scene '" + mScene.name +
                        "' moves (\"motion\"); scenes in motion run on GL only for now (--api gl)",
                    ExitCode::Unsupported);
    if (mScene.lights.size() > size_t(kMaxLights))
        throw Error("scene '" + mScene.name + "' has " + std::to_string(mScene.lights.size()) +
                    " lights; at most " + std::to_string(kMaxLights) + " are supported");

    mContext = std::make_unique<VulkanContext>(config.vulkan);
    mTargets = std::make_unique<VulkanTargets>(*mContext, config.width, config.height);
    mShaders = std::make_unique<ShaderModuleCache>(*mContext);
    mPipelines = std::make_unique<VulkanPipelineCache>(*mContext);
    mFrameBlock = std::make_unique<VulkanFrameBlock>(*mContext);
    mSubmitter = std::make_unique<VulkanSubmitter>(*mContext, config.submit);
    mSubmitter->upload(mScene);
    mView = cameraView(mCamera);
    mProj = cameraProjection(mCamera, float(config.width) / float(config.height));
    mFrameData = FrameUniforms::compute(mScene, mView, mProj, mCamera.eye);
    if (mContext->timestampPeriodNs() > 0.0)
        mRing = std::make_unique<TimestampRing>(*mContext, kRingFrames, kPassesPerFrame);
    // As on GL: the timestamps are checked against the frame before any is shown (--no-timer-check
    // leaves the verdict "unchecked" and shows none).
    if (config.checkTimer) mCalibration = mVerdict = VulkanTimerTrust::calibrate(*mContext, *mShaders);

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
    return {mConfig,      mScene, mContentHash, false,    mVerdict, "vulkan",
            d.apiVersion, d.name, "",           d.driver, "vulkan", std::to_string(d.index) + ": " + d.name};
}

std::vector<std::string> VulkanHarness::takeValidationMessages() {
    const auto& all = mContext->validationMessages();
    std::vector<std::string> out(all.begin() + long(std::min(mMessagesShown, all.size())), all.end());
    mMessagesShown = all.size();
    return out;
}

void VulkanHarness::prepare(VulkanTechnique& technique) {
    technique.setScene(mScene);
    technique.compile({*mContext, *mShaders, mScene, *mSubmitter, *mTargets, *mFrameBlock, *mPipelines});
}

FrameSample VulkanHarness::renderFrame(VulkanTechnique& technique) {
    FrameSample s;
    const auto t0 = Clock::now();
    VulkanContext::check(vkResetCommandBuffer(mCmd, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VulkanContext::check(vkBeginCommandBuffer(mCmd, &begin), "vkBeginCommandBuffer");
    mFrameBlock->beginFrame();
    const uint32_t frameOffset = mFrameBlock->write(mFrameData);
    const bool timing = mRing && mCalibration.checked && mCalibration.trusted;
    mPasses.setRing(timing ? mRing.get() : nullptr);
    mPasses.setCommandBuffer(mCmd);
    if (timing) mRing->beginFrame(mCmd, mFrameIndex);
    mTargets->recordClear(mCmd, 0.55f, 0.65f, 0.8f);
    VulkanFrameContext ctx{mScene,  mView,        mProj,       mCamera.eye, *mTargets,    *mSubmitter,
                           mPasses, *mFrameBlock, frameOffset, mCmd,        mFrameIndex++};
    technique.execute(ctx);
    mPasses.endCensusFrame();
    if (timing) mRing->endFrame(mCmd);
    VulkanContext::check(vkEndCommandBuffer(mCmd), "vkEndCommandBuffer");
    mContext->submit(mCmd, mFence);
    const auto t1 = Clock::now();
    VulkanContext::check(vkWaitForFences(mContext->device(), 1, &mFence, VK_TRUE, UINT64_MAX),
                         "vkWaitForFences");
    const auto t2 = Clock::now();
    VulkanContext::check(vkResetFences(mContext->device(), 1, &mFence), "vkResetFences");
    s.cpuSubmitMs = msSince(t0, t1);
    s.wallMs = msSince(t0, t2);
    return s;
}

RunResult VulkanHarness::measure(VulkanTechnique& technique) {
    const auto setup0 = Clock::now();
    prepare(technique);
    const double setupMs = msSince(setup0, Clock::now());
    // As on GL: the timed frames write no visibility target (the harness's instrument).
    mTargets->setVisibilityOutput(false);
    struct VisibilityBackOn {
        VulkanTargets& targets;
        ~VisibilityBackOn() { targets.setVisibilityOutput(true); }
    } visibilityBackOn{*mTargets};
    for (int i = 0; i < mConfig.warmup; ++i) renderFrame(technique);
    if (mRing) mRing->collect(); // warm-up timings are discarded
    std::vector<FrameSample> samples;
    std::map<uint64_t, VulkanPassTimes> gpu;
    const uint64_t firstFrame = mFrameIndex;
    const auto start = Clock::now();
    for (;;) {
        samples.push_back(renderFrame(technique));
        if (mRing && mCalibration.trusted)
            for (VulkanPassTimes& t : mRing->collect()) gpu[t.frame] = std::move(t);
        const int n = int(samples.size());
        if (mConfig.seconds > 0.0) {
            if (n >= RunConfig::kMinFrames && msSince(start, Clock::now()) >= mConfig.seconds * 1000.0) break;
        } else if (n >= mConfig.frames) {
            break;
        }
    }
    mTargets->setVisibilityOutput(true);
    if (mRing && mCalibration.trusted)
        for (VulkanPassTimes& t : mRing->collect()) gpu[t.frame] = std::move(t);
    // As on GL (Harness::recheckTimer): a trusted verdict is checked again after the run; if it no longer
    // holds the run's times are withdrawn and no later run shows any.
    mVerdict = mCalibration;
    if (mCalibration.checked && mCalibration.trusted) {
        mVerdict = TimerTrust::afterRun(mCalibration, VulkanTimerTrust::calibrate(*mContext, *mShaders));
        if (mVerdict.revoked) {
            mCalibration = mVerdict; // not trusted again in this process
            gpu.clear();
        }
    }
    for (size_t i = 0; i < samples.size(); ++i) {
        auto it = gpu.find(firstFrame + i);
        if (it == gpu.end()) continue;
        samples[i].gpuPassMs = it->second.passMs;
        samples[i].gpuTotalMs = it->second.totalMs;
    }
    RunResult r = summarize(technique, std::move(samples));
    r.setupMs = setupMs;
    r.loads = census(technique);
    return r;
}

FrameLoads VulkanHarness::census(VulkanTechnique& technique) {
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

RunResult VulkanHarness::summarize(VulkanTechnique& technique, std::vector<FrameSample> samples) {
    RunResult r;
    r.technique = technique.name();
    r.properties = technique.properties().toString();
    r.permutation = technique.permutationKey();
    r.effectsProduced = technique.info().effects;
    r.counters = technique.counters();
    std::vector<double> cpu, wall, total;
    std::map<std::string, std::vector<double>> perPass;
    for (const FrameSample& s : samples) {
        cpu.push_back(s.cpuSubmitMs);
        wall.push_back(s.wallMs);
        if (s.gpuTotalMs < 0.0) {
            r.gpuFramesMissing += mCalibration.trusted ? 1 : 0;
            continue;
        }
        total.push_back(s.gpuTotalMs);
        std::map<std::string, double> frame; // a pass entered once per light is summed per frame
        for (const auto& [pass, ms] : s.gpuPassMs) frame[pass] += ms;
        for (const auto& [pass, ms] : frame) perPass[pass].push_back(ms);
    }
    r.cpuSubmit = Statistics::compute(cpu);
    r.wall = Statistics::compute(wall);
    r.motion = Statistics::compute(std::vector<double>(samples.size(), 0.0));
    r.gpuTotal = Statistics::compute(total);
    for (const std::string& pass : technique.info().passes)
        r.gpuPass.emplace_back(pass, Statistics::compute(perPass[pass]));
    r.samples = std::move(samples);
    return r;
}

} // namespace sb
