#include "bench/lib/harness/MeasuredHarness.h"

#include <chrono>
#include <malloc.h>
#include <map>

#include "bench/lib/options/QualitySweep.h"
#include "core/Error.h"
#include "core/Strings.h"
#include "registry/MemoryBudget.h"
#include "scenes/Math.h"
#include "scenes/Motion.h"
#include "scenes/SceneLoader.h"
#include "shading/ShaderLimits.h"

// Callgrind client requests around the measured frames (bench/lib/callgrind/InstructionCount.h):
// instrumentation on for them only, one dump per technique. Compiled in where valgrind's header exists
// (SB_HAVE_VALGRIND, set for this file only); natively a request is a handful of no-op instructions.
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

MeasuredHarness::MeasuredHarness(const RunConfig& config, bool motion) : mConfig(config) {
    const auto t0 = Clock::now();
    mScene = SceneLoader::load(config.scene, config.sceneOptions);
    mSceneLoadMs = msSince(t0, Clock::now());
    mCamera = pickCamera(mScene, config.camera);
    mContentHash = mScene.computeContentHash();
    if (!mScene.motion && (config.pathTime >= 0.0 || config.pathFrames > 0))
        throw Error(std::string(config.pathTime >= 0.0 ? "--time" : "--path-frames") + ": scene '" +
                    mScene.name + "' does not move (it has no \"motion\")");
    if (mScene.motion && !motion)
        throw Error("scene '" + mScene.name +
                        "' moves (\"motion\"); scenes in motion run on GL only for now " + "(--api gl)",
                    ExitCode::Unsupported);
    if (mScene.motion) {
        mRest = std::make_unique<Scene>(mScene);
        mCameraFollows = mCamera.name == Motion::kCameraName && mScene.motion->camera;
        if (config.pathFrames > 0) {
            auto moved = std::make_shared<Motion>(*mScene.motion);
            moved->frames = uint32_t(config.pathFrames);
            mScene.motion = mRest->motion = moved;
        }
        moveTo(config.pathTime >= 0.0 ? float(config.pathTime) : 0.0f);
    }
    if (mScene.lights.size() > size_t(kMaxLights))
        throw Error("scene '" + mScene.name + "' has " + std::to_string(mScene.lights.size()) +
                    " lights; at most " + std::to_string(kMaxLights) + " are supported");
    // Before the derived harness creates its targets and any technique its maps: the whole
    // configuration within --max-memory-gib, as the scene alone was when it loaded.
    const std::vector<TechniqueSpec> specs =
        config.sweep ? QualitySweep::expandAll(config.techniques) : config.techniques;
    MemoryBudget::check(specs, {config.width, config.height, int(mScene.lights.size())},
                        SceneLoader::estimateBytes(mScene), config.sceneOptions.memoryLimitBytes);
    updateFrameData();
}

MeasuredHarness::~MeasuredHarness() = default;

void MeasuredHarness::pinAllocator() {
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
}

void MeasuredHarness::setTimerVerdict(const TimerVerdict& verdict) {
    setCalibration(verdict);
}

void MeasuredHarness::setCalibration(const TimerVerdict& verdict) {
    mCalibration = mVerdict = verdict;
    timerQueriesChanged();
}

void MeasuredHarness::setCamera(const CameraPreset& camera) {
    mCamera = camera;
    updateFrameData();
}

void MeasuredHarness::setPixelShift(const glm::vec2& pixels) {
    mPixelShift = pixels;
    updateFrameData();
}

void MeasuredHarness::setLight(size_t index, const Light& light) {
    if (index >= mScene.lights.size())
        throw Error("light " + std::to_string(index) + " does not exist in scene '" + mScene.name + "'");
    mScene.lights[index] = light;
    updateFrameData();
}

void MeasuredHarness::moveTo(float t) {
    mPathTime = t;
    mScene.motion->apply(*mRest, mScene, t);
    if (mCameraFollows) mCamera = mScene.motion->cameraAt(t);
}

void MeasuredHarness::seekPath(uint64_t frame) {
    if (!moving()) return;
    mPathFrame = frame;
    moveTo(mScene.motion->timeOfFrame(frame));
    instancesMoved();
    updateFrameData();
}

double MeasuredHarness::advancePath(Technique& technique) {
    if (!moving()) return 0.0;
    const auto t0 = Clock::now();
    const Motion& motion = *mScene.motion;
    moveTo(motion.timeOfFrame(mPathFrame++));
    const uint32_t changes = motion.changes(mCameraFollows);
    if (changes & kCastersMoved) instancesMoved();
    updateFrameData();
    technique.sceneChanged(mScene, changes);
    return msSince(t0, Clock::now());
}

void MeasuredHarness::updateFrameData() {
    mView = cameraView(mCamera);
    mProj = cameraProjection(mCamera, float(mConfig.width) / float(mConfig.height));
    // One pixel is 2/width in NDC; translating clip x by shift * w after projection moves every sample.
    glm::mat4 shift(1.0f);
    shift[3] = glm::vec4(2.0f * mPixelShift.x / float(mConfig.width),
                         2.0f * mPixelShift.y / float(mConfig.height), 0.0f, 1.0f);
    mProj = shift * mProj;
    mFrameData = computeFrameUniforms(mScene, mView, mProj, mCamera.eye);
}

RunResult MeasuredHarness::measure(Technique& technique) {
    const auto setup0 = Clock::now();
    prepare(technique);
    const double setupMs = msSince(setup0, Clock::now());
    // Warm-up and measured frames render what an application would: no visibility target (the
    // harness's instrument). The census frame after them, and every frame rendered outside measure()
    // (accuracy, images, the viewer), write it.
    setVisibilityOutput(false);
    struct VisibilityBackOn { // also when a frame throws: the next reader gets a visibility target
        MeasuredHarness& harness;
        ~VisibilityBackOn() { harness.setVisibilityOutput(true); }
    } visibilityBackOn{*this};
    for (int i = 0; i < mConfig.warmup; ++i) renderFrame(technique);
    collectGpuTimes(true); // warm-up timings are discarded

    std::vector<FrameSample> samples;
    std::vector<PassTimes> gpu;
    const uint64_t firstFrame = mFrameIndex;
    const auto start = Clock::now();
    CALLGRIND_START_INSTRUMENTATION; // counts only the measured frames, one dump per technique
    for (;;) {
        samples.push_back(renderFrame(technique));
        for (PassTimes& t : collectGpuTimes(false)) gpu.push_back(std::move(t));
        const int n = int(samples.size());
        if (mConfig.seconds > 0.0) {
            if (n >= RunConfig::kMinFrames && msSince(start, Clock::now()) >= mConfig.seconds * 1000.0) break;
        } else if (n >= mConfig.frames) {
            break;
        }
    }
    CALLGRIND_STOP_INSTRUMENTATION; // before the dump: nothing after it leaks into the next technique
    CALLGRIND_DUMP_STATS_AT(technique.name().c_str());
    setVisibilityOutput(true);
    for (PassTimes& t : collectGpuTimes(true)) gpu.push_back(std::move(t));
    recheckTimer(samples, gpu, firstFrame);
    RunResult r = summarizeRun(technique, std::move(samples), timing());
    r.setupMs = setupMs;
    r.loads = census(technique);
    return r;
}

void MeasuredHarness::recordFrameTimes(FrameSample& s, Clock::time_point t0, Clock::time_point t1,
                                       Clock::time_point t2) const {
    s.cpuSubmitMs = msSince(t0, t1);
    s.wallMs = msSince(t0, t2);
    s.startMs = std::chrono::duration<double, std::milli>(t0.time_since_epoch()).count();
    const auto& begins = mPassClock.begins();
    s.cpuPasses.clear();
    s.cpuPasses.reserve(begins.size());
    for (size_t i = 0; i < begins.size(); ++i) {
        const Clock::time_point end = i + 1 < begins.size() ? begins[i + 1].second : t1;
        s.cpuPasses.push_back(
            {begins[i].first, msSince(t0, begins[i].second), msSince(begins[i].second, end)});
    }
}

void MeasuredHarness::recheckTimer(std::vector<FrameSample>& samples, const std::vector<PassTimes>& gpu,
                                   uint64_t first) {
    mVerdict = mCalibration;
    if (!timing()) return; // a verdict is never upgraded: nothing to check where it is untrusted
    mVerdict = TimerTrust::afterRun(mCalibration, recalibrate());
    if (mVerdict.revoked) {
        // A timer that failed once in this process is not trusted again: later runs keep the withdrawn
        // verdict and issue no timer queries, and this run's times are not shown.
        setCalibration(mVerdict);
        return;
    }
    for (const PassTimes& t : gpu) {
        if (t.frame < first || t.frame - first >= samples.size()) continue;
        FrameSample& s = samples[size_t(t.frame - first)];
        s.gpuPassMs = t.passMs;
        s.gpuTotalMs = t.totalMs;
    }
}

RunResult summarizeRun(const Technique& technique, std::vector<FrameSample> samples, bool timing) {
    RunResult r;
    r.technique = technique.name();
    r.properties = technique.properties().toString();
    r.permutation = technique.permutationKey();
    r.effectsProduced = technique.info().effects;
    r.counters = technique.counters();
    std::vector<double> cpu, wall, total, motion;
    std::map<std::string, std::vector<double>> perPass, cpuPerPass;
    for (const FrameSample& s : samples) {
        std::map<std::string, double> cpuFrame; // a pass entered several times is summed per frame
        for (const CpuPassSpan& p : s.cpuPasses) cpuFrame[p.pass] += p.durationMs;
        for (const auto& [pass, ms] : cpuFrame) cpuPerPass[pass].push_back(ms);
        cpu.push_back(s.cpuSubmitMs);
        wall.push_back(s.wallMs);
        motion.push_back(s.motionMs);
        if (s.gpuTotalMs < 0.0) {
            r.gpuFramesMissing += timing ? 1 : 0;
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
    for (const std::string& pass : technique.info().passes) {
        r.gpuPass.emplace_back(pass, Statistics::compute(perPass[pass]));
        r.cpuPass.emplace_back(pass, Statistics::compute(cpuPerPass[pass]));
    }
    r.samples = std::move(samples);
    return r;
}

} // namespace sb
