#pragma once
// The run loop on GL (bench/lib/harness/MeasuredHarness.h holds the loop itself; docs/ARCHITECTURE.md, "The
// timing contract"): one GL context, its frame targets and submitter, the GPU timer-query ring and the
// census's pipeline-statistics queries.
//
// Per frame, in this order:
//   t0  a scene in motion moves; upload the frame uniforms, begin the timer-query frame, bind and clear
//       the targets; technique.execute() (its passes call PassTimer::begin)
//   t1  end of the last GL call: CPU submit = t1 - t0
//       glFinish()
//   t2  wall = t2 - t0
// GPU pass times are read back from the query ring frames later and never stall the loop.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench/lib/harness/FrameSample.h"
#include "bench/lib/harness/InjectedPass.h"
#include "bench/lib/harness/MeasuredHarness.h"
#include "bench/lib/harness/RowSource.h"
#include "bench/lib/harness/RunResult.h"
#include "bench/lib/harness/TimerTrust.h"
#include "bench/lib/harness/WorkCensus.h"
#include "bench/lib/options/RunConfig.h"
#include "gl/Context.h"
#include "gl/FrameTargets.h"
#include "gl/PipelineStatistics.h"
#include "gl/ProgramCache.h"
#include "gl/TimerQueryRing.h"
#include "reference/GBufferRenderer.h"
#include "scenes/Scene.h"
#include "techniques/gl/FrameUniforms.h"
#include "techniques/gl/GlTechnique.h"
#include "techniques/gl/PassTimer.h"
#include "techniques/gl/Submitter.h"

namespace sb {

class Harness final : public MeasuredHarness {
public:
    /// Creates the context, loads the scene, allocates targets and uploads geometry. Throws sb::Error.
    explicit Harness(const RunConfig& config);
    ~Harness() override;

    Api api() const override { return Api::GL; }
    Context& context() { return *mContext; }
    const Context& context() const { return *mContext; }
    FrameTargets& targets() { return *mTargets; }
    Submitter& submitter() { return *mSubmitter; }
    ProgramCache& programs() { return mPrograms; }
    /// The pass timer the techniques' frames go through: `bench floors` sets an observer on it around
    /// frames of its own (bench/floors/PassProbe.h); the measured frames never carry one.
    PassTimer& passTimer() { return *mPassTimer; }
    RowSource rowSource() const override;

    const TimerVerdict& calibrateTimer() override;
    bool timerQueriesEnabled() const { return timing(); }

    /// Checks capabilities (throws ExitCode::Unsupported naming the missing one), then setScene and
    /// compile. `technique` must be a GL form (GlTechnique).
    void prepare(Technique& technique) override;
    /// One frame, timed. Returns the CPU/wall sample; GPU times arrive later through the ring.
    FrameSample renderFrame(Technique& technique) override;
    std::vector<unsigned char> readColor() override { return mTargets->readColorRGBA8(); }
    std::vector<float> readVisibility() override { return mTargets->readVisibilityRGBA32F(); }
    /// reference/GBufferRenderer.h with this harness's submitter, programs and projection * view.
    GBuffer renderGBuffer() override;

private:
    void setVisibilityOutput(bool on) override { mTargets->setVisibilityOutput(on); }
    std::vector<PassTimes> collectGpuTimes(bool wait) override;
    TimerVerdict recalibrate() override;
    void timerQueriesChanged() override;
    FrameLoads census(Technique& technique) override;
    void instancesMoved() override;
    static GlTechnique& glForm(Technique& technique);

    std::unique_ptr<Context> mContext;
    std::unique_ptr<FrameTargets> mTargets;
    std::unique_ptr<Submitter> mSubmitter;
    std::unique_ptr<FrameUniforms> mFrameUniforms;
    std::unique_ptr<TimerQueryRing> mRing;
    std::unique_ptr<PassTimer> mPassTimer;
    std::unique_ptr<PipelineStatistics> mPipelineStatistics; ///< created on the first census
    ProgramCache mPrograms;
    InjectedPass mInjectedPass;                ///< after mContext: its GL objects go first
    std::unique_ptr<GBufferRenderer> mGBuffer; ///< created on the first renderGBuffer (after mContext)
};

} // namespace sb
