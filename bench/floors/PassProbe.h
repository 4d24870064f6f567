#pragma once
// A pass observer (techniques/PassObserver.h) for `bench floors`: it cuts a technique's frame at its pass
// boundaries with glFinish, so that each pass is timed alone (wall time from one boundary to the next,
// the pass's submission and its rasterisation both inside) and, under callgrind, counted alone (one
// client-request dump per pass, named by dumpPrefix() + the pass). In an inspecting frame it also reads
// each pass's target at the pass's end (bench/floors/PassTarget.h). It starts no query of its own: a
// technique may run one inside a pass (volume counts its marked samples), and GL allows one per target. The
// work before the first pass (the harness's clear of the frame targets) is the interval "frame".
//
// The glFinish at every boundary changes the frame (llvmpipe would otherwise overlap a depth pass's
// rasterisation with the next pass's submission), which is why its floor is cut the same way; the
// measured runs of `bench` never carry this observer.
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "bench/floors/PassTarget.h"
#include "techniques/PassObserver.h"

namespace sb {

/// One interval of a probed frame (a pass entered twice is two intervals).
struct ProbedPass {
    std::string name;
    double ms = 0.0;   ///< wall time, glFinish to glFinish
    PassTarget target; ///< inspecting frames only
};

class PassProbe : public PassObserver {
public:
    /// `inspect`: read each pass's target at its end; otherwise time only.
    explicit PassProbe(bool inspect);

    /// Waits for earlier work and opens the interval "frame"; call right before the harness's frame.
    void frameBegins();
    void passBegins(const char* pass) override;
    void framePassesEnd() override;
    void passSkipped(const char*, const char*) override {}

    /// The intervals of the last frame, in order, "frame" first.
    const std::vector<ProbedPass>& passes() const { return mPasses; }
    /// Callgrind dumps at each boundary are named `prefix + pass`; "" (the default): none.
    void setDumpPrefix(std::string prefix) { mDumpPrefix = std::move(prefix); }

private:
    void open(const char* pass);
    void close();

    bool mInspect;
    bool mOpen = false;
    std::string mDumpPrefix;
    std::chrono::steady_clock::time_point mStart;
    std::vector<ProbedPass> mPasses;
};

/// True when this process runs under valgrind (callgrind's dumps then count each pass and floor).
bool callgrindRunning();
/// Callgrind's instrumentation on or off (`--instr-atstart=no` leaves it off until the measured frames);
/// a no-op outside callgrind.
void callgrindInstrumentation(bool on);
/// Waits for the GL work so far, then dumps callgrind's counts since the last dump under `name` (a
/// no-op outside callgrind, or with `name` empty).
void finishAndDump(const std::string& name);

} // namespace sb
