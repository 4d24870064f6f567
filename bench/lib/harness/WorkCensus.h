#pragma once
// The exact work of one untimed frame, pass by pass: what the submitter issued (GL calls, draws,
// triangles) and, where the context can count them, what the pipeline processed (vertex and fragment
// shader invocations, primitives before and after clipping). On llvmpipe these were bit-identical
// across runs, LP_NUM_THREADS and load, so the perf gate's layer A compares them exactly
// (bench/lib/gate/WorkGate.h, README "Gate a change").
//
// The census observes PassTimer's boundaries: each pass gets its own pipeline-statistics queries,
// ended (and waited for) when the next pass begins. Work before a technique's first pass (the frame's
// clear and uniform upload) is booked to the pseudo-pass "frame". A pass entered several times a
// frame (once per light) is summed under its name. The timed frames never carry an observer.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gl/PipelineStatistics.h"
#include "techniques/FrameWork.h"
#include "techniques/PassObserver.h"
#include "techniques/gl/Submitter.h"

namespace sb {

class WorkCensus : public PassObserver {
public:
    /// `statistics` may be null (the context cannot count the pipeline); it must stay alive while
    /// the census runs.
    WorkCensus(const Submitter& submitter, PipelineStatistics* statistics);
    /// Opens the "frame" interval; call before the frame's first GL call.
    void frameBegins();
    void passBegins(const char* pass) override;
    void framePassesEnd() override;
    void passSkipped(const char* pass, const char* reason) override;
    /// Closes the open interval (if any) and returns the work per pass.
    FrameWork finish();
    /// The passes skipped in the frame, each pass once (the first reason given for it).
    const SkippedPasses& skipped() const { return mSkipped; }

private:
    void closeInterval();
    void openInterval(const std::string& pass);
    const Submitter& mSubmitter;
    PipelineStatistics* mStatistics;
    FrameWork mWork;
    SkippedPasses mSkipped;
    std::string mOpenPass;
    bool mOpen = false;
    SubmitStats mStart;
};

} // namespace sb
