#pragma once
// Can GL timer queries be trusted on this context (docs/ARCHITECTURE.md, "The timing contract")? Measured,
// not assumed from the renderer's name: the same fill-bound workload (a full-screen quad with a long fragment
// loop) runs at two resolutions, 4x the pixels apart. Where the GPU timer measures the frame, its ratio
// follows the wall-clock ratio and it covers most of the wall time. On Mesa llvmpipe TIME_ELAPSED covers
// roughly one tile's work: it neither grows with the pixel count nor covers the frame, so the verdict is
// "untrusted" and the harness never reports those numbers as GPU time.
#include <string>

#include "gl/ProgramCache.h"

namespace sb {

struct TimerVerdict {
    bool checked = false;
    bool trusted = false;
    std::string reason; ///< one line with the evidence
    double wallSmallMs = 0, wallLargeMs = 0, gpuSmallMs = 0, gpuLargeMs = 0;
    const char* label() const { return !checked ? "unchecked" : (trusted ? "trusted" : "untrusted"); }
};

class TimerTrust {
public:
    /// Runs the calibration on the current context (~0.5-2 s on llvmpipe, milliseconds on a GPU).
    static TimerVerdict calibrate(ProgramCache& programs);
    /// The decision rule, separated for unit tests: trusted when the GPU-time ratio reaches at least
    /// half the pixel ratio (2x for 4x pixels) and the timer covers at least half the wall time of the
    /// large run.
    static TimerVerdict judge(double wallSmallMs, double wallLargeMs, double gpuSmallMs, double gpuLargeMs,
                              double pixelRatio);
};

} // namespace sb
