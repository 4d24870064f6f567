#include "bench/lib/harness/Harness.h"

#include <chrono>

#include "core/DriverTable.h"
#include "core/Error.h"
#include "gl/DebugOutput.h"
#include "gl/backends/BackendRegistry.h"
#include "techniques/gl/FrameState.h"

namespace sb {

namespace {
using Clock = std::chrono::steady_clock;
} // namespace

Harness::Harness(const RunConfig& config) : MeasuredHarness(config, true) {
    mContext = createContext(config.context);
    mPrograms.setDumpDirectory(config.dumpShadersPath);
    DebugOutput::install();
    mTargets = std::make_unique<FrameTargets>(config.width, config.height);
    mSubmitter = Submitter::create(config.submit);
    mSubmitter->setBackFaces(config.backFaces);
    mSubmitter->upload(scene());
    mFrameUniforms = std::make_unique<FrameUniforms>();
    mRing = std::make_unique<TimerQueryRing>(4, 16);
    // No timer queries until a calibration trusts the timer (timerQueriesChanged).
    mPassTimer = std::make_unique<PassTimer>(nullptr);
    mPassTimer->setClock(&passClock());
    DebugOutput::check();
}

Harness::~Harness() = default;

RowSource Harness::rowSource() const {
    const Context& c = *mContext;
    return {config(),
            scene(),
            contentHash(),
            moving(),
            timerVerdict(),
            "gl",
            c.version,
            c.renderer,
            c.version,
            c.vendor,
            backendName(c.backend()),
            c.deviceName,
            DriverTable::versionInGlVersion(c.version)};
}

GlTechnique& Harness::glForm(Technique& technique) {
    if (technique.api() != Api::GL)
        throw Error(technique.name() + ": a " + apiName(technique.api()) + " form handed to the GL harness",
                    ExitCode::Failure);
    return static_cast<GlTechnique&>(technique);
}

const TimerVerdict& Harness::calibrateTimer() {
    mPrograms.setDumpLabel("timer_trust");
    if (!calibration().checked) setCalibration(TimerTrust::calibrate(mPrograms));
    return timerVerdict();
}

TimerVerdict Harness::recalibrate() {
    mPrograms.setDumpLabel("timer_trust");
    return TimerTrust::calibrate(mPrograms);
}

void Harness::timerQueriesChanged() {
    mPassTimer->setRing(timing() ? mRing.get() : nullptr);
}

void Harness::instancesMoved() {
    if (mSubmitter) mSubmitter->instancesMoved(scene());
}

void Harness::prepare(Technique& technique) {
    GlTechnique& gl = glForm(technique);
    std::string missing = gl.checkCapabilities(*mContext);
    if (!missing.empty()) throw Error(missing, ExitCode::Unsupported);
    DebugOutput::setCurrentPass(technique.name() + "/setup");
    gl.setScene(scene());
    mPrograms.setDumpLabel(technique.name());
    gl.compile({mPrograms, scene(), *mSubmitter, *mContext});
    DebugOutput::check();
    DebugOutput::setCurrentPass("");
    mPassTimer->setTechnique(technique.name());
}

FrameSample Harness::renderFrame(Technique& technique) {
    GlTechnique& gl = glForm(technique);
    FrameSample s;
    auto t0 = Clock::now();
    passClock().frameBegins(t0);
    // A scene in motion moves first, as an application animates before it draws: part of the frame.
    s.motionMs = advancePath(technique);
    mFrameUniforms->upload(frameData());
    const bool queries = timing();
    if (queries) mRing->beginFrame();
    // The state every technique may assume at the start of execute(); techniques restore what they
    // change (techniques/gl/FrameState.h).
    resetFrameState();
    mTargets->bind();
    mTargets->clear(0.55f, 0.65f, 0.8f);
    FrameContext ctx{scene(),     view(),      projection(),     camera().eye,        *mTargets,
                     *mSubmitter, *mPassTimer, nextFrameIndex(), mFrameUniforms.get()};
    gl.execute(ctx);
    mInjectedPass.execute(mPrograms, *mPassTimer,
                          FrameTargets::kColourAttachments); // nothing unless the perf gate's proof asks
    mPassTimer->end();
    if (queries) mRing->endFrame();
    auto t1 = Clock::now();
    glFinish();
    auto t2 = Clock::now();
    recordFrameTimes(s, t0, t1, t2);
    return s;
}

std::vector<PassTimes> Harness::collectGpuTimes(bool wait) {
    if (!timing()) return {};
    return wait ? mRing->drain() : mRing->collect();
}

GBuffer Harness::renderGBuffer() {
    if (!mGBuffer) {
        mGBuffer = std::make_unique<GBufferRenderer>(width(), height());
        mGBuffer->setScene(scene()); // immediate/displaylist G-buffers draw per instance themselves
    }
    return mGBuffer->render(*mSubmitter, mPrograms, projection() * view());
}

FrameLoads Harness::census(Technique& technique) {
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

} // namespace sb
