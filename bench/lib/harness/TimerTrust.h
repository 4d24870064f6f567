#pragma once
// Can GL timer queries be trusted on this context (docs/ARCHITECTURE.md, "The timing contract")? Measured,
// not assumed from the renderer's name, and with the queries the frames use: GL_TIMESTAMP pairs through a
// TimerQueryRing, read exactly as Harness reads a frame.
//
// The workload is fill-bound (a full-screen triangle with a long fragment loop, shaders/calibrate/) and runs
// at two resolutions, kPixelRatio times the pixels apart. Where the timer measures the frame, three things
// hold at once, and each is checked with a lower and an upper bound:
//   - proportionality: the timer grows like the work, timer(large) / timer(small) within
//     [kMinGrowth, kMaxGrowth] x kPixelRatio, and like the CPU wall clock
//     (kMinGrowthVsWall..kMaxGrowthVsWall);
//   - coverage: the timer spans most of the wall time of the large draw, timer / wall within
//     [kMinCoverage, kMaxCoverage] (above 1 is impossible for a timer read inside the wall interval);
//   - agreement: kRounds independent rounds all pass and their timer growths differ by at most
//     kMaxRoundSpread (max / min).
// A single lucky round decides nothing. On Mesa llvmpipe the timestamps are taken per tile by the rasteriser
// threads, so a pair spans about one tile's work: it does not follow the pixels and misses most of the
// frame, and when the machine is loaded a descheduled thread makes it jump at random (growths from 0.01x to
// over 1000x for 4x the pixels were measured) - the bands on both sides turn each such round into
// "untrusted". (Without an active scene llvmpipe takes the first stamp at submission instead, which covers
// the whole draw; frames clear before their first stamp, and so does the calibration.)
#include <string>
#include <vector>

#include "gl/ProgramCache.h"

namespace sb {

/// One round of the calibration: the medians of kRepeats timed draws at each size (interleaved).
struct CalibrationRound {
    double wallSmallMs = 0, wallLargeMs = 0;   ///< CPU wall clock, glFinish to glFinish
    double timerSmallMs = 0, timerLargeMs = 0; ///< the GL_TIMESTAMP pair around the draw
    double timerGrowth() const { return timerSmallMs > 0.0 ? timerLargeMs / timerSmallMs : 0.0; }
    double wallGrowth() const { return wallSmallMs > 0.0 ? wallLargeMs / wallSmallMs : 0.0; }
    double coverage() const { return wallLargeMs > 0.0 ? timerLargeMs / wallLargeMs : 0.0; }
};

struct TimerVerdict {
    bool checked = false;
    bool trusted = false;
    /// Trusted at the calibration, untrusted when re-checked after a measured run (TimerTrust::afterRun).
    bool revoked = false;
    std::string reason;                   ///< one line with the evidence
    std::vector<CalibrationRound> rounds; ///< the evidence (empty when the verdict came from elsewhere)
    int iterations = 0;                   ///< fragment-loop length the calibration settled on
    double calibrationMs = 0.0;           ///< how long the calibration took, wall clock
    const char* label() const { return !checked ? "unchecked" : (trusted ? "trusted" : "untrusted"); }
};

/// One fill-bound draw timed as a frame is, by one API: the part of the calibration that differs between
/// GL (TimerTrust::calibrate) and Vulkan (VulkanTimerTrust::calibrate). The procedure that uses it, the
/// rounds and the rules are TimerTrust's, the same on both.
class TimedFill {
public:
    struct Timing {
        double wallMs = 0.0, timerMs = 0.0;
    };
    virtual ~TimedFill() = default;
    /// The full-screen fill with `iterations` loop steps per fragment into the small (kSmall^2) or large
    /// (kLarge^2) target: wall clock from an idle device to the frame's end, and the timer's pair.
    virtual Timing draw(bool large, int iterations) = 0;
};

class TimerTrust {
public:
    static constexpr int kSmall = 512, kLarge = 1024; ///< square sizes: 4x the pixels
    static constexpr double kPixelRatio = double(kLarge) * kLarge / (double(kSmall) * kSmall);
    static constexpr int kRounds = 3;  ///< independent rounds that must all pass
    static constexpr int kRepeats = 3; ///< draws per size and round (the median is kept)
    /// Timer growth over pixel growth. 4x the pixels of a fill-bound draw is 4x the work; the band is
    /// wide enough for a GPU whose small draw does not quite fill it, narrow enough that a timer
    /// covering one tile (about 1x) or jumping with the scheduler (tens of x) fails.
    static constexpr double kMinGrowth = 0.6, kMaxGrowth = 1.5;
    /// Timer growth over wall-clock growth: the timer must see the same scaling the CPU sees.
    static constexpr double kMinGrowthVsWall = 0.75, kMaxGrowthVsWall = 1.33;
    /// Timer over wall time of the large draw. The wall interval encloses both timestamps (it runs
    /// from an idle GPU to glFinish), so a timer above it is wrong; 5% is left for clock granularity.
    static constexpr double kMinCoverage = 0.6, kMaxCoverage = 1.05;
    /// Largest max/min of the rounds' timer growths: repeated measurements of one device agree.
    static constexpr double kMaxRoundSpread = 1.25;

    /// Runs the calibration on the current context: a search for a loop length that makes the large
    /// draw take 15 ms, then up to kRounds rounds; the first failed round ends it (trust needs all), so
    /// llvmpipe pays for one round (measured 0.1-0.2 s with 2 threads, up to 0.9 s on a loaded machine).
    /// Leaves the GL state as it found it, except the bound framebuffer and VAO (0).
    static TimerVerdict calibrate(ProgramCache& programs);
    /// The calibration's procedure with any API's fill (the search for the loop length, the rounds of
    /// kRepeats medians, the first failed round ending it, the verdict); `timer` names the API's timer in
    /// the reason ("GL_TIMESTAMP pairs", "vkCmdWriteTimestamp pairs").
    static TimerVerdict calibrateWith(TimedFill& fill, const std::string& timer);
    /// The decision rule, separated for unit tests: trusted when every round passes checkRound and the
    /// rounds agree (kMaxRoundSpread). The reason lists the evidence and every failed condition.
    static TimerVerdict judge(const std::vector<CalibrationRound>& rounds,
                              const std::string& timer = "GL_TIMESTAMP pairs");
    /// Why one round fails ("" when it passes): each failed condition, semicolon-separated.
    static std::string checkRound(const CalibrationRound& round);
    /// The verdict a run ends with: `before` (the calibration the run was measured under) confirmed by
    /// `after` (the calibration repeated after the measured frames). Trusted only when both are; a
    /// trusted `before` with an untrusted `after` is "untrusted" and `revoked`.
    static TimerVerdict afterRun(const TimerVerdict& before, const TimerVerdict& after);
};

} // namespace sb
