#pragma once
// The measured run, once for every API (docs/ARCHITECTURE.md, "Data flow" and "The timing contract"): one
// scene, one camera, one submitter and one set of frame targets shared by every technique of a run, so that
// they are measured on identical state. This class holds what does not depend on the API (the scene and its
// motion, the camera and the frame block's contents, the timer verdict) and the run loop itself
// (measure()); bench/lib/harness/Harness.h (GL) and bench/lib/harness/VulkanHarness.h (Vulkan) implement the
// frame and what the API counts. The run command, the accuracy evaluator and the sweep workers hold harnesses
// by this class, so a run option, a column or a rule of the loop is written once and holds on every API.
//
// Per measured run: prepare (capabilities, setScene, compile; untimed), warm-up frames (discarded), the
// measured frames (config frames or seconds; callgrind counts only these), the timer re-check where the
// timer is trusted, the statistics, then one untimed census frame for the exact work.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "bench/lib/harness/FrameSample.h"
#include "bench/lib/harness/RowSource.h"
#include "bench/lib/harness/RunResult.h"
#include "bench/lib/harness/TimerTrust.h"
#include "bench/lib/options/RunConfig.h"
#include "core/PassTimes.h"
#include "reference/GBuffer.h"
#include "scenes/Scene.h"
#include "techniques/FrameBlock.h"
#include "techniques/PassClock.h"
#include "techniques/Technique.h"

namespace sb {

class MeasuredHarness {
public:
    virtual ~MeasuredHarness();
    /// Fixes glibc's heap thresholds for the process, before any frame: glibc trims the top of the heap
    /// whenever a free leaves more than the trim threshold there, and llvmpipe frees its per-draw vertex
    /// buffers every draw. Measured (none, aircraft x40, 160x160): ~300 brk calls and ~8000 page faults
    /// per frame, tripling CPU submit, gone when an unrelated allocation happened to pin the heap's top
    /// (an extra pass made the frame 3x faster). Frame times must not depend on heap-layout luck: no
    /// trimming below 256 MiB, mmap from 32 MiB (mallopt also stops glibc adjusting them at run time).
    static void pinAllocator();
    MeasuredHarness(const MeasuredHarness&) = delete;
    MeasuredHarness& operator=(const MeasuredHarness&) = delete;

    virtual Api api() const = 0;
    const RunConfig& config() const { return mConfig; }
    /// The scene as the last frame drew it (a scene in motion moves every frame).
    const Scene& scene() const { return mScene; }
    /// The scene as loaded, before any motion: what the content hash describes.
    const Scene& restScene() const { return mRest ? *mRest : mScene; }
    /// Scene::computeContentHash of the scene at rest (its motion included), computed once.
    const std::string& contentHash() const { return mContentHash; }
    /// The scene moves along its path frame by frame (it has motion and no --time freezes it).
    bool moving() const { return mScene.motion && mConfig.pathTime < 0.0; }
    /// The path time the last frame was drawn at (0 for a static scene).
    float pathTime() const { return mPathTime; }
    const CameraPreset& camera() const { return mCamera; }
    const glm::mat4& view() const { return mView; }
    const glm::mat4& projection() const { return mProj; }
    double sceneLoadMs() const { return mSceneLoadMs; }
    /// What the rows and the console header take from this run (the API's names for its device).
    virtual RowSource rowSource() const = 0;

    /// Runs the timer-trust calibration once (TimerTrust's rules on the API's timer); the verdict is
    /// cached. Where it is "untrusted", measured frames issue no timer queries at all: their numbers would
    /// never be shown, and on a software driver each query is extra work inside the frame being measured.
    virtual const TimerVerdict& calibrateTimer() = 0;
    /// The verdict of the last measured run (TimerTrust::afterRun of the calibration and its re-check), or
    /// the calibration's before the first run.
    const TimerVerdict& timerVerdict() const { return mVerdict; }
    /// Uses a verdict measured elsewhere (a sweep calibrates once and hands it to every worker process).
    void setTimerVerdict(const TimerVerdict& verdict);

    /// Checks the technique's capabilities on this API (Error(Unsupported) naming the missing one), then
    /// setScene and compile (untimed). `technique` must be of this harness's API.
    virtual void prepare(Technique& technique) = 0;
    /// Prepare, warm-up, the measured frames, the timer re-check, statistics, then one untimed census
    /// frame for the loads. The same loop on every API.
    RunResult measure(Technique& technique);
    /// One extra frame, not timed, with every pass's work counted (the census: the submitter's draws
    /// and, where the API counts them, a pipeline-statistics query per pass). What explain prints, and
    /// -t auto's exact work on the API it calibrates on.
    FrameLoads measureLoads(Technique& technique) { return census(technique); }
    /// One frame, not timed beyond its sample, with the visibility target written (what accuracy, images
    /// and the viewer read).
    virtual FrameSample renderFrame(Technique& technique) = 0;
    /// The last frame's targets, rows bottom-up (row 0 is the bottom of the image) on every API: RGBA8
    /// colour, and the visibility target as 4 floats a pixel (channel i = light i).
    virtual std::vector<unsigned char> readColor() = 0;
    virtual std::vector<float> readVisibility() = 0;
    /// The G-buffer (reference/GBuffer.h) of the current camera, pixel shift and scene, drawn by this
    /// API with the run's submitter and a lighting pass's rasterisation, read back rows bottom-up: the
    /// sample positions the accuracy evaluator judges this harness's frames at (untimed, between frames).
    virtual GBuffer renderGBuffer() = 0;
    int width() const { return mConfig.width; }
    int height() const { return mConfig.height; }
    /// Messages of the API's validation since the last call (Vulkan with --vk-validation), each once.
    virtual std::vector<std::string> takeValidationMessages() { return {}; }
    /// Validation errors so far: a run with any did not render what the API promises (exit 1).
    virtual size_t validationErrors() const { return 0; }
    /// Moves the camera (the viewer's orbit); measurements use the configured preset.
    void setCamera(const CameraPreset& camera);
    /// Shifts the image by `pixels` (sub-pixel camera perturbations of the stability metrics): a
    /// translation of the projection in NDC, so every sample moves by the same screen offset.
    void setPixelShift(const glm::vec2& pixels);
    /// Replaces light `index` (light perturbations). Techniques must be prepared again afterwards
    /// (their light-dependent precompute lives in setScene).
    void setLight(size_t index, const Light& light);
    /// Moves the scene to the step `frame` of its path now (the next frames go on from there): the
    /// accuracy evaluator judges frames along the path this way. Techniques see it at their next frame
    /// (Technique::sceneChanged).
    void seekPath(uint64_t frame);

protected:
    /// Loads the scene, picks the camera, applies --time and --path-frames and checks the light limit;
    /// an API that cannot draw a scene in motion (`motion` false) refuses one with exit 3 and its reason.
    MeasuredHarness(const RunConfig& config, bool motion);

    /// Advances a scene in motion one step of its path and lets `technique` follow
    /// (Technique::sceneChanged), casters first (instancesMoved). Returns the milliseconds it took (0 for a
    /// static scene): part of the frame, as an application animates before it draws.
    double advancePath(Technique& technique);
    /// The frame block's contents for the current camera, pixel shift and lights.
    const FrameUniformData& frameData() const { return mFrameData; }
    uint64_t nextFrameIndex() { return mFrameIndex++; }
    uint64_t frameIndex() const { return mFrameIndex; }
    /// Whether measured frames issue timer queries: the calibration says the timer is trusted.
    bool timing() const { return mCalibration.checked && mCalibration.trusted; }
    /// The calibration the frames are measured under (set by calibrateTimer or setTimerVerdict).
    void setCalibration(const TimerVerdict& verdict);
    const TimerVerdict& calibration() const { return mCalibration; }
    /// Where the API's pass timer records each pass's CPU begin; renderFrame starts it with the frame.
    PassClock& passClock() { return mPassClock; }
    /// Fills `s` from the frame's clock readings: start `t0`, end of submission `t1`, end of the wait `t2`
    /// (cpuSubmitMs, wallMs, startMs) and the per-pass spans passClock() recorded since t0. Called after
    /// t2, so building the spans is outside both measured intervals.
    void recordFrameTimes(FrameSample& s, PassClock::Clock::time_point t0, PassClock::Clock::time_point t1,
                          PassClock::Clock::time_point t2) const;

    // What each API implements for the loop.
    /// Timed frames render what an application would: no visibility target (the harness's instrument).
    virtual void setVisibilityOutput(bool on) = 0;
    /// The GPU times read back so far (frames later than their submission), emptied; with `wait`, every
    /// outstanding frame's (outside the timed frames only).
    virtual std::vector<PassTimes> collectGpuTimes(bool wait) = 0;
    /// The calibration again, after a trusted run.
    virtual TimerVerdict recalibrate() = 0;
    /// The timer turned on or off for the frames that follow (the verdict changed).
    virtual void timerQueriesChanged() {}
    /// One untimed frame with every pass's work counted.
    virtual FrameLoads census(Technique& technique) = 0;
    /// A scene in motion moved its casters: submitters that keep per-instance data upload it again.
    virtual void instancesMoved() = 0;

private:
    void moveTo(float t);
    void updateFrameData();
    void recheckTimer(std::vector<FrameSample>& samples, const std::vector<PassTimes>& gpu, uint64_t first);

    RunConfig mConfig;
    Scene mScene;
    std::unique_ptr<Scene> mRest; ///< a scene in motion at rest (null for a static scene)
    std::string mContentHash;
    double mSceneLoadMs = 0.0;
    uint64_t mPathFrame = 0; ///< the next frame's step along the path
    float mPathTime = 0.0f;
    bool mCameraFollows = false; ///< --camera path
    CameraPreset mCamera;
    glm::mat4 mView{1.0f}, mProj{1.0f};
    glm::vec2 mPixelShift{0.0f};
    FrameUniformData mFrameData{};
    TimerVerdict mCalibration; ///< what the frames are measured under
    TimerVerdict mVerdict;     ///< what the last run ended with
    uint64_t mFrameIndex = 0;
    PassClock mPassClock;
};

/// The statistics of a measured run: median, percentiles and the rest per series (CPU submit, wall, the
/// motion's share, GPU total and per declared pass, from the frames whose times came back).
RunResult summarizeRun(const Technique& technique, std::vector<FrameSample> samples, bool timing);

} // namespace sb
