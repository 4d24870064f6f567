#include "bench/lib/harness/WorkCensus.h"

#include <algorithm>

namespace sb {

namespace {
bool isZero(const PassWork& w) {
    const SubmitStats& s = w.submitted;
    const bool quiet = s.drawCalls == 0 && s.triangles == 0 && s.instances == 0 && s.glCalls == 0;
    const PipelineCounts p = w.pipeline.value_or(PipelineCounts{});
    return quiet && p.vertexShaderInvocations == 0 && p.primitivesSubmitted == 0 &&
           p.clippingOutputPrimitives == 0 && p.fragmentShaderInvocations == 0;
}
} // namespace

WorkCensus::WorkCensus(const Submitter& submitter, PipelineStatistics* statistics)
    : mSubmitter(submitter), mStatistics(statistics) {}

void WorkCensus::frameBegins() {
    mWork.clear();
    mSkipped.clear();
    openInterval("frame");
}

void WorkCensus::passBegins(const char* pass) {
    closeInterval();
    openInterval(pass);
}

void WorkCensus::framePassesEnd() {
    closeInterval();
}

void WorkCensus::passSkipped(const char* pass, const char* reason) {
    for (const auto& entry : mSkipped)
        if (entry.first == pass) return;
    mSkipped.emplace_back(pass, reason);
}

FrameWork WorkCensus::finish() {
    closeInterval();
    // The frame's own interval (clear, uniform upload) carries no counted work unless something draws
    // before the first pass; only then is it a column.
    auto frame = std::find_if(mWork.begin(), mWork.end(), [](const auto& p) { return p.first == "frame"; });
    if (frame != mWork.end() && isZero(frame->second)) mWork.erase(frame);
    return std::move(mWork);
}

void WorkCensus::openInterval(const std::string& pass) {
    mOpenPass = pass;
    mStart = mSubmitter.lifetimeStats();
    if (mStatistics) mStatistics->begin();
    mOpen = true;
}

void WorkCensus::closeInterval() {
    if (!mOpen) return;
    mOpen = false;
    PassWork w;
    if (mStatistics) w.pipeline = mStatistics->end();
    w.submitted = mSubmitter.lifetimeStats() - mStart;
    auto it = std::find_if(mWork.begin(), mWork.end(), [&](const auto& p) { return p.first == mOpenPass; });
    if (it == mWork.end()) {
        mWork.emplace_back(mOpenPass, w);
        return;
    }
    it->second.submitted += w.submitted;
    if (it->second.pipeline && w.pipeline) *it->second.pipeline += *w.pipeline;
}

} // namespace sb
