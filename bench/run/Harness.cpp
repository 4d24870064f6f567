#include "bench/run/Harness.h"
#include "core/Strings.h"

#include <chrono>
#include <map>

#include "core/Error.h"
#include "gl/DebugOutput.h"
#include "gl/backends/BackendRegistry.h"
#include "scenes/Math.h"
#include "scenes/Motion.h"
#include "scenes/SceneLoader.h"
#include "techniques/FrameState.h"

// Instructions per measured frame under callgrind (bench/ci/InstructionCount.h): natively each request
// is a handful of no-op instructions, so the timed frames are unchanged.
#ifdef SB_HAVE_VALGRIND
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_STOP_INSTRUMENTATION
#define CALLGRIND_DUMP_STATS_AT(name) (void)(name)
#endif

namespace sb {

namespace {
using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

const CameraPreset& pickCamera(const Scene& scene, const std::string& name) {
    if (const CameraPreset* c = scene.findCamera(name)) return *c;
    std::string known = join(scene.cameras, ", ", [](const CameraPreset& c) { return c.name; });
    throw Error("--camera " + name + ": scene '" + scene.name + "' has no such camera (known: " + known +
                ")");
}
} // namespace

Harness::Harness(const RunConfig& config) : mConfig(config) {
    auto t0 = Clock::now();
    mScene = SceneLoader::load(config.scene, config.sceneOptions);
    mSceneLoadMs = msSince(t0, Clock::now());
    mCamera = pickCamera(mScene, config.camera);
    mContentHash = mScene.computeContentHash();
    if (!mScene.motion && (config.pathTime >= 0.0 || config.pathFrames > 0))
        throw Error(std::string(config.pathTime >= 0.0 ? "--time" : "--path-frames") + ": scene '" +
                    mScene.name + "' does not move (it has no \"motion\")");
    if (mScene.motion) {
        mRest = std::make_unique<Scene>(mScene);
        mCameraFollows = mCamera.name == Motion::kCameraName && mScene.motion->camera;
        if (config.pathFrames > 0) {
            auto motion = std::make_shared<Motion>(*mScene.motion);
            motion->frames = uint32_t(config.pathFrames);
            mScene.motion = mRest->motion = motion;
        }
        moveTo(config.pathTime >= 0.0 ? float(config.pathTime) : 0.0f);
    }
    if (mScene.lights.size() > size_t(kMaxLights))
        throw Error("scene '" + mScene.name + "' has " + std::to_string(mScene.lights.size()) +
                    " lights; at most " + std::to_string(kMaxLights) + " are supported");

    mContext = createContext(config.context);
    mPrograms.setDumpDirectory(config.dumpShadersPath);
    DebugOutput::install();
    mTargets = std::make_unique<FrameTargets>(config.width, config.height);
    mSubmitter = Submitter::create(config.submit);
    mSubmitter->upload(mScene);
    mFrameUniforms = std::make_unique<FrameUniforms>();
    setCamera(mCamera);
    mRing = std::make_unique<TimerQueryRing>(4, 16);
    mPassTimer = std::make_unique<PassTimer>(mRing.get());
    DebugOutput::check();
}

Harness::~Harness() = default;

RowSource Harness::rowSource() const {
    const Context& c = *mContext;
    return {mConfig,
            mScene,
            mContentHash,
            moving(),
            mVerdict,
            "gl",
            c.version,
            c.renderer,
            c.version,
            c.vendor,
            backendName(c.backend()),
            c.deviceName};
}

void Harness::setCamera(const CameraPreset& camera) {
    mCamera = camera;
    updateFrameData();
}

void Harness::setPixelShift(const glm::vec2& pixels) {
    mPixelShift = pixels;
    updateFrameData();
}

void Harness::setLight(size_t index, const Light& light) {
    if (index >= mScene.lights.size())
        throw Error("light " + std::to_string(index) + " does not exist in scene '" + mScene.name + "'");
    mScene.lights[index] = light;
    updateFrameData();
}

void Harness::moveTo(float t) {
    mPathTime = t;
    mScene.motion->apply(*mRest, mScene, t);
    if (mCameraFollows) mCamera = mScene.motion->cameraAt(t);
}

void Harness::seekPath(uint64_t frame) {
    if (!moving()) return;
    mPathFrame = frame;
    moveTo(mScene.motion->timeOfFrame(frame));
    if (mSubmitter) mSubmitter->instancesMoved(mScene);
    updateFrameData();
}

double Harness::advancePath(Technique& technique) {
    if (!moving()) return 0.0;
    const auto t0 = Clock::now();
    const Motion& motion = *mScene.motion;
    moveTo(motion.timeOfFrame(mPathFrame++));
    const uint32_t changes = motion.changes(mCameraFollows);
    if (changes & kCastersMoved) mSubmitter->instancesMoved(mScene);
    updateFrameData();
    technique.sceneChanged(mScene, changes);
    return msSince(t0, Clock::now());
}

void Harness::updateFrameData() {
    mView = cameraView(mCamera);
    mProj = cameraProjection(mCamera, float(mConfig.width) / float(mConfig.height));
    // One pixel is 2/width in NDC; translating clip x by shift * w after projection moves every sample.
    glm::mat4 shift(1.0f);
    shift[3] = glm::vec4(2.0f * mPixelShift.x / float(mConfig.width),
                         2.0f * mPixelShift.y / float(mConfig.height), 0.0f, 1.0f);
    mProj = shift * mProj;
    mFrameData = FrameUniforms::compute(mScene, mView, mProj, mCamera.eye);
}

const TimerVerdict& Harness::calibrateTimer() {
    mPrograms.setDumpLabel("timer_trust");
    if (!mCalibration.checked) setTimerVerdict(TimerTrust::calibrate(mPrograms));
    return mVerdict;
}

const TimerVerdict& Harness::recheckTimer() {
    if (!mCalibration.checked || !mCalibration.trusted) return mVerdict = mCalibration;
    mPrograms.setDumpLabel("timer_trust");
    mVerdict = TimerTrust::afterRun(mCalibration, TimerTrust::calibrate(mPrograms));
    // A timer that failed once in this process is not trusted again: later runs keep the withdrawn
    // verdict and issue no timer queries.
    if (mVerdict.revoked) setTimerVerdict(mVerdict);
    return mVerdict;
}

void Harness::prepare(Technique& technique) {
    std::string missing = technique.checkCapabilities(*mContext);
    if (!missing.empty()) throw Error(missing, ExitCode::Unsupported);
    DebugOutput::setCurrentPass(technique.name() + "/setup");
    technique.setScene(mScene);
    mPrograms.setDumpLabel(technique.name());
    technique.compile({mPrograms, mScene, *mSubmitter, *mContext});
    DebugOutput::check();
    DebugOutput::setCurrentPass("");
    mPassTimer->setTechnique(technique.name());
}

void Harness::setFrameState() {
    // The state every technique may assume at the start of execute(); techniques restore what they
    // change (techniques/FrameState.h).
    resetFrameState();
}

FrameSample Harness::renderFrame(Technique& technique) {
    FrameSample s;
    auto t0 = Clock::now();
    // A scene in motion moves first, as an application animates before it draws: part of the frame.
    s.motionMs = advancePath(technique);
    mFrameUniforms->upload(mFrameData);
    if (mTimerQueries) mRing->beginFrame();
    setFrameState();
    mTargets->bind();
    mTargets->clear(0.55f, 0.65f, 0.8f);
    FrameContext ctx{mScene,      mView,       mProj,         mCamera.eye,         *mTargets,
                     *mSubmitter, *mPassTimer, mFrameIndex++, mFrameUniforms.get()};
    technique.execute(ctx);
    mInjectedPass.execute(mPrograms, *mPassTimer,
                          FrameTargets::kColourAttachments); // nothing unless the perf gate's proof asks
    mPassTimer->end();
    if (mTimerQueries) mRing->endFrame();
    auto t1 = Clock::now();
    glFinish();
    auto t2 = Clock::now();
    s.cpuSubmitMs = msSince(t0, t1);
    s.wallMs = msSince(t0, t2);
    return s;
}

RunResult Harness::measure(Technique& technique) {
    auto setup0 = Clock::now();
    prepare(technique);
    double setupMs = msSince(setup0, Clock::now());
    // Warm-up and measured frames render what an application would: no visibility target (the
    // harness's instrument). The census frame after them, and every frame rendered outside measure()
    // (accuracy, images, the viewer), write it (gl/FrameTargets.h).
    mTargets->setVisibilityOutput(false);
    struct VisibilityBackOn { // also when a frame throws: the next reader gets a visibility target
        FrameTargets& targets;
        ~VisibilityBackOn() { targets.setVisibilityOutput(true); }
    } visibilityBackOn{*mTargets};
    for (int i = 0; i < mConfig.warmup; ++i) renderFrame(technique);
    if (mTimerQueries) mRing->drain(); // warm-up timings are discarded

    std::vector<FrameSample> samples;
    uint64_t firstFrame = mFrameIndex;
    std::map<uint64_t, PassGpuTimes> gpu;
    auto collect = [&](std::vector<PassGpuTimes> v) {
        for (auto& g : v) gpu[g.frame] = std::move(g);
    };
    auto start = Clock::now();
    CALLGRIND_START_INSTRUMENTATION; // counts only the measured frames, one dump per technique
    for (;;) {
        samples.push_back(renderFrame(technique));
        if (mTimerQueries) collect(mRing->collect());
        int n = int(samples.size());
        if (mConfig.seconds > 0.0) {
            if (n >= RunConfig::kMinFrames && msSince(start, Clock::now()) >= mConfig.seconds * 1000.0) break;
        } else if (n >= mConfig.frames) {
            break;
        }
    }
    CALLGRIND_STOP_INSTRUMENTATION; // before the dump: nothing after it leaks into the next technique
    CALLGRIND_DUMP_STATS_AT(technique.name().c_str());
    mTargets->setVisibilityOutput(true);
    if (mTimerQueries) collect(mRing->drain());
    recheckTimer();
    for (size_t i = 0; i < samples.size(); ++i) {
        auto it = gpu.find(firstFrame + i);
        if (it == gpu.end()) continue;
        samples[i].gpuPassMs = it->second.passMs;
        samples[i].gpuTotalMs = it->second.totalMs;
    }
    RunResult r = summarize(technique, std::move(samples), firstFrame);
    r.setupMs = setupMs;
    r.loads = measureLoads(technique);
    return r;
}

FrameLoads Harness::measureLoads(Technique& technique) {
    const bool counting = PipelineStatistics::available(
        mContext->glMajor, mContext->glMinor, mContext->hasExtension("GL_ARB_pipeline_statistics_query"));
    if (counting && !mPipelineStatistics) mPipelineStatistics = std::make_unique<PipelineStatistics>();
    WorkCensus census(*mSubmitter, counting ? mPipelineStatistics.get() : nullptr);
    mPassTimer->setObserver(&census);
    census.frameBegins();
    renderFrame(technique);
    mPassTimer->setObserver(nullptr);
    FrameLoads loads;
    loads.passes = census.finish();
    loads.skipped = census.skipped();
    const PassWork total = totalWork(loads.passes);
    loads.submitted = total.submitted;
    loads.pipeline = total.pipeline;
    DebugOutput::check();
    return loads;
}

void Harness::setTimerVerdict(const TimerVerdict& verdict) {
    mCalibration = mVerdict = verdict;
    mTimerQueries = mVerdict.checked && mVerdict.trusted;
    mPassTimer->setRing(mTimerQueries ? mRing.get() : nullptr);
}

RunResult Harness::summarize(Technique& technique, std::vector<FrameSample> samples, uint64_t) {
    RunResult r;
    r.technique = technique.name();
    r.properties = technique.properties().toString();
    r.permutation = technique.permutationKey();
    r.effectsProduced = technique.info().effects;
    r.counters = technique.counters();
    std::vector<double> cpu, wall, total, motion;
    std::map<std::string, std::vector<double>> perPass;
    for (const FrameSample& s : samples) {
        cpu.push_back(s.cpuSubmitMs);
        wall.push_back(s.wallMs);
        motion.push_back(s.motionMs);
        if (s.gpuTotalMs < 0.0) {
            r.gpuFramesMissing += mTimerQueries ? 1 : 0;
            continue;
        }
        total.push_back(s.gpuTotalMs);
        // A pass a technique enters several times a frame (once per light) is summed per frame.
        std::map<std::string, double> frame;
        for (const auto& [pass, ms] : s.gpuPassMs) frame[pass] += ms;
        for (const auto& [pass, ms] : frame) perPass[pass].push_back(ms);
    }
    r.cpuSubmit = Statistics::compute(cpu);
    r.wall = Statistics::compute(wall);
    r.motion = Statistics::compute(motion);
    r.gpuTotal = Statistics::compute(total);
    for (const std::string& pass : technique.info().passes)
        r.gpuPass.emplace_back(pass, Statistics::compute(perPass[pass]));
    r.samples = std::move(samples);
    return r;
}

} // namespace sb
