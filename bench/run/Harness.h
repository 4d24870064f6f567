#pragma once
// The run loop (docs/ARCHITECTURE.md, "Data flow" and "The timing contract"): one GL context, one scene, one
// set of frame targets and one submitter, shared by every technique of a run so that they are measured on
// identical state.
//
// Per frame, in this order:
//   t0  upload the frame uniforms, begin the timer-query frame, bind and clear the targets
//       technique.execute() (its passes call PassTimer::begin)
//   t1  end of the last GL call: CPU submit = t1 - t0
//       glFinish()
//   t2  wall = t2 - t0
// GPU pass times are read back from the query ring frames later and never stall the loop. Warm-up
// frames run the same path and are discarded. Where the timer is trusted, the calibration is repeated
// after the measured frames (outside them): the run's verdict is trusted only if both say so.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/run/FrameSample.h"
#include "bench/run/InjectedPass.h"
#include "bench/run/RowSource.h"
#include "bench/run/RunConfig.h"
#include "bench/run/Statistics.h"
#include "bench/run/TimerTrust.h"
#include "bench/run/WorkCensus.h"
#include "gl/Context.h"
#include "gl/FrameTargets.h"
#include "gl/PipelineStatistics.h"
#include "gl/ProgramCache.h"
#include "gl/TimerQueryRing.h"
#include "scenes/Scene.h"
#include "techniques/FrameUniforms.h"
#include "techniques/PassTimer.h"
#include "techniques/Technique.h"
#include "techniques/submit/Submitter.h"

namespace sb {

/// The loads of one untimed census frame (Harness::measureLoads): what the application submitted and,
/// where the context can count them, what the pipeline processed. The bottleneck study relates frame
/// time to these.
struct FrameLoads {
    SubmitStats submitted;
    std::optional<PipelineCounts> pipeline; ///< empty without GL_ARB_pipeline_statistics_query
    FrameWork passes;                       ///< the same, pass by pass (they sum to the above)
    SkippedPasses skipped;                  ///< passes the technique left out, with its reasons
};

struct RunResult {
    std::string technique;
    std::string properties;         ///< canonical PropertySet::toString()
    std::string permutation;        ///< program keys
    EffectMask effectsProduced = 0; ///< TechniqueInfo::effects (the row's effects_* columns)
    Counters counters;              ///< of the last measured frame
    std::vector<FrameSample> samples;
    Statistics cpuSubmit, wall;
    Statistics motion; ///< a scene in motion: FrameSample::motionMs (inside cpuSubmit)
    std::vector<std::pair<std::string, Statistics>> gpuPass; ///< per declared pass (raw timer values)
    Statistics gpuTotal;
    uint64_t gpuFramesMissing = 0; ///< measured frames whose queries never came back
    double setupMs = 0.0;          ///< setScene + compile (untimed for the frames)
    FrameLoads loads;              ///< census frame after the measured ones
};

class Harness {
public:
    /// Creates the context, loads the scene, allocates targets and uploads geometry. Throws sb::Error.
    explicit Harness(const RunConfig& config);
    ~Harness();

    const RunConfig& config() const { return mConfig; }
    Context& context() { return *mContext; }
    const Context& context() const { return *mContext; }
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
    /// Moves the scene to path time `t` now (the next frames go on from frame `frame` of the path):
    /// the accuracy evaluator judges frames along the path this way. Techniques see it at their next
    /// frame (Technique::sceneChanged).
    void seekPath(uint64_t frame);
    FrameTargets& targets() { return *mTargets; }
    Submitter& submitter() { return *mSubmitter; }
    ProgramCache& programs() { return mPrograms; }
    const CameraPreset& camera() const { return mCamera; }
    /// The verdict of the last measured run (TimerTrust::afterRun of the calibration and its re-check),
    /// or the calibration's before the first run.
    const TimerVerdict& timerVerdict() const { return mVerdict; }
    double sceneLoadMs() const { return mSceneLoadMs; }
    /// What the rows and the console header take from this run (api "gl").
    RowSource rowSource() const;

    /// Checks capabilities (throws ExitCode::Unsupported naming the missing one), then setScene and
    /// compile.
    void prepare(Technique& technique);
    /// One frame, timed. Returns the CPU/wall sample; GPU times arrive later through the ring.
    FrameSample renderFrame(Technique& technique);
    /// Warm-up, then the measured frames (config frames or seconds), the timer re-check where the
    /// timer is trusted (recheckTimer), statistics, then one untimed census frame for the loads.
    RunResult measure(Technique& technique);
    /// One extra frame, not timed, each pass wrapped in pipeline-statistics queries where the context
    /// has them (WorkCensus).
    FrameLoads measureLoads(Technique& technique);
    /// Uses a verdict measured elsewhere (a sweep calibrates once and hands it to every worker process)
    /// instead of calibrating here.
    void setTimerVerdict(const TimerVerdict& verdict);
    /// Moves the camera (the viewer's orbit); measurements use the configured preset.
    void setCamera(const CameraPreset& camera);
    /// Shifts the image by `pixels` (sub-pixel camera perturbations of the stability metrics): a
    /// translation of the projection in NDC, so every sample moves by the same screen offset.
    void setPixelShift(const glm::vec2& pixels);
    /// Replaces light `index` (light perturbations). Techniques must be prepared again afterwards
    /// (their light-dependent precompute lives in setScene).
    void setLight(size_t index, const Light& light);
    const glm::mat4& view() const { return mView; }
    const glm::mat4& projection() const { return mProj; }
    /// Runs the timer-trust calibration (once; the verdict is cached). Where the verdict is
    /// "untrusted", measured frames issue no timer queries at all: their numbers would never be shown,
    /// and on llvmpipe each query is extra driver work inside the frame being measured.
    const TimerVerdict& calibrateTimer();
    bool timerQueriesEnabled() const { return mTimerQueries; }
    /// Repeats the calibration after a run measured under a trusted verdict; when it no longer holds,
    /// the run's verdict is "untrusted" (revoked) and so is every later run's: timer queries stay off
    /// for the rest of the harness's life. Nothing to do where the timer is untrusted or unchecked (a
    /// verdict is never upgraded), so on llvmpipe it costs nothing.
    const TimerVerdict& recheckTimer();

private:
    void setFrameState();
    /// A scene in motion: moves it to the next step of its path and lets `technique` follow
    /// (Technique::sceneChanged). Returns the milliseconds it took (0 for a static scene).
    double advancePath(Technique& technique);
    /// Sets lights, casters and the following camera to path time `t`.
    void moveTo(float t);
    RunResult summarize(Technique& technique, std::vector<FrameSample> samples, uint64_t firstFrame);
    RunConfig mConfig;
    std::unique_ptr<Context> mContext;
    Scene mScene;
    std::unique_ptr<Scene> mRest; ///< a scene in motion at rest (null for a static scene)
    std::string mContentHash;
    uint64_t mPathFrame = 0; ///< the next frame's step along the path
    float mPathTime = 0.0f;
    bool mCameraFollows = false; ///< --camera path
    CameraPreset mCamera;
    glm::mat4 mView{1.0f}, mProj{1.0f};
    glm::vec2 mPixelShift{0.0f};
    void updateFrameData();
    std::unique_ptr<FrameTargets> mTargets;
    std::unique_ptr<Submitter> mSubmitter;
    std::unique_ptr<FrameUniforms> mFrameUniforms;
    FrameUniformData mFrameData{};
    std::unique_ptr<TimerQueryRing> mRing;
    std::unique_ptr<PassTimer> mPassTimer;
    std::unique_ptr<PipelineStatistics> mPipelineStatistics; ///< created on the first census
    ProgramCache mPrograms;
    TimerVerdict mCalibration; ///< what the frames are measured under (calibrateTimer, setTimerVerdict)
    TimerVerdict mVerdict;     ///< what the last run ended with
    uint64_t mFrameIndex = 0;
    bool mTimerQueries = true;
    double mSceneLoadMs = 0.0;
    InjectedPass mInjectedPass; ///< after mContext: its GL objects go first
};

} // namespace sb
