#include "bench/lib/harness/TimerTrust.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

#include <epoxy/gl.h>

#include "gl/TextureFramebuffer.h"
#include "gl/TimerQueryRing.h"

namespace sb {

namespace {
using Clock = std::chrono::steady_clock;

constexpr double kMinLargeWallMs = 15.0; // below this, fixed per-draw costs blur the ratios
constexpr int kMaxIterations = 1 << 24;  // a fast GPU needs long loops to reach kMinLargeWallMs
constexpr const char* kPass = "calibrate/fill";

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

/// One draw into a GL target timed as Harness times a frame: a ring frame, the target bound and cleared,
/// one pass around the draw, read back through the ring (drain waits, which is fine outside measured
/// frames), and the wall clock from an idle GPU to glFinish. The clear matters on llvmpipe: without an
/// active scene the first timestamp is taken at submission, with one (as in every frame) it is taken per
/// tile.
class GlFill final : public TimedFill {
public:
    GlFill(const TextureFramebuffer& small, const TextureFramebuffer& large, TimerQueryRing& ring)
        : mSmall(small), mLarge(large), mRing(ring) {}
    Timing draw(bool large, int iterations) override {
        static constexpr GLfloat kBlack[] = {0.0f, 0.0f, 0.0f, 1.0f};
        (large ? mLarge : mSmall).bind();
        glUniform1i(0, iterations);
        glFinish();
        const Clock::time_point t0 = Clock::now();
        mRing.beginFrame();
        glClearBufferfv(GL_COLOR, 0, kBlack);
        mRing.beginPass(kPass);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        mRing.endFrame();
        glFinish();
        const double wallMs = msSince(t0);
        const std::vector<PassTimes> frames = mRing.drain();
        return {wallMs, frames.empty() ? 0.0 : frames.back().totalMs};
    }

private:
    const TextureFramebuffer& mSmall;
    const TextureFramebuffer& mLarge;
    TimerQueryRing& mRing;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// Medians of kRepeats consecutive draws into one target, as measured frames follow each other.
TimedFill::Timing medianDraw(TimedFill& fill, bool large, int iterations) {
    std::vector<double> wall, timer;
    for (int i = 0; i < TimerTrust::kRepeats; ++i) {
        const TimedFill::Timing d = fill.draw(large, iterations);
        wall.push_back(d.wallMs);
        timer.push_back(d.timerMs);
    }
    return {median(wall), median(timer)};
}

/// Doubles the loop length (from 1) until one large draw takes kMinLargeWallMs. Single draws: a draw
/// slowed by the machine's load only ends the search early, and the rounds take medians anyway.
int findIterations(TimedFill& fill) {
    int iterations = 1;
    fill.draw(true, iterations); // JIT the shader outside the measurement
    while (iterations < kMaxIterations && fill.draw(true, iterations).wallMs < kMinLargeWallMs)
        iterations *= 2;
    return iterations;
}

std::string format(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

/// "1.02x 0.98x 1.10x": one value per round.
std::string perRound(const std::vector<CalibrationRound>& rounds, const char* f,
                     const std::function<double(const CalibrationRound&)>& value) {
    std::string s;
    for (const CalibrationRound& r : rounds) s += (s.empty() ? "" : " ") + format(f, value(r));
    return s;
}

std::string band(const char* f, double lo, double hi) {
    return "[" + format(f, lo) + ", " + format(f, hi) + "]";
}

std::string evidence(const std::vector<CalibrationRound>& rounds) {
    using T = TimerTrust;
    return "timer growth " + perRound(rounds, "%.2fx", &CalibrationRound::timerGrowth) + " " +
           band("%.1fx", T::kMinGrowth * T::kPixelRatio, T::kMaxGrowth * T::kPixelRatio) + ", wall growth " +
           perRound(rounds, "%.2fx", &CalibrationRound::wallGrowth) + ", timer/wall " +
           perRound(rounds, "%.2f", &CalibrationRound::coverage) + " " +
           band("%.2f", T::kMinCoverage, T::kMaxCoverage) + " of " +
           perRound(rounds, "%.1f", [](const CalibrationRound& r) { return r.wallLargeMs; }) + " ms";
}

void appendFailure(std::string& why, const std::string& what) {
    why += (why.empty() ? "" : "; ") + what;
}
} // namespace

std::string TimerTrust::checkRound(const CalibrationRound& r) {
    std::string why;
    const double growth = r.timerGrowth() / kPixelRatio;
    const double vsWall = r.wallGrowth() > 0.0 ? r.timerGrowth() / r.wallGrowth() : 0.0;
    if (growth < kMinGrowth) appendFailure(why, "the timer does not grow with the fill work");
    if (growth > kMaxGrowth) appendFailure(why, "the timer grows far more than the fill work");
    if (vsWall < kMinGrowthVsWall || vsWall > kMaxGrowthVsWall)
        appendFailure(why, "the timer does not scale like the wall clock");
    if (r.coverage() < kMinCoverage) appendFailure(why, "the timer misses most of the frame");
    if (r.coverage() > kMaxCoverage) appendFailure(why, "the timer exceeds the wall time that encloses it");
    return why;
}

TimerVerdict TimerTrust::judge(const std::vector<CalibrationRound>& rounds, const std::string& timer) {
    TimerVerdict v;
    v.checked = true;
    v.rounds = rounds;
    std::string failures;
    for (size_t i = 0; i < rounds.size(); ++i) {
        const std::string why = checkRound(rounds[i]);
        if (!why.empty()) appendFailure(failures, "round " + std::to_string(i + 1) + ": " + why);
    }
    // (A calibration stops at its first failed round; that round is the reason, not the count.)
    if (rounds.size() < size_t(kRounds) && failures.empty())
        appendFailure(failures, "only " + std::to_string(rounds.size()) + " of " + std::to_string(kRounds) +
                                    " rounds measured, all are needed");
    if (failures.empty()) {
        // Every round passed on its own; repeated measurements of one device must also agree.
        double lo = rounds.front().timerGrowth(), hi = lo;
        for (const CalibrationRound& r : rounds) {
            lo = std::min(lo, r.timerGrowth());
            hi = std::max(hi, r.timerGrowth());
        }
        if (hi > kMaxRoundSpread * lo)
            appendFailure(failures, "the rounds disagree (timer growths " + format("%.2fx", lo) + " to " +
                                        format("%.2fx", hi) + ")");
    }
    v.trusted = failures.empty();
    v.reason = timer + ", " + std::to_string(kSmall) + "^2 vs " + std::to_string(kLarge) + "^2 (" +
               format("%.0fx", kPixelRatio) + " pixels), " + std::to_string(rounds.size()) + " of " +
               std::to_string(kRounds) + " rounds: " + evidence(rounds);
    if (!v.trusted) v.reason += "; " + failures;
    return v;
}

TimerVerdict TimerTrust::calibrate(ProgramCache& programs) {
    const Clock::time_point t0 = Clock::now();
    GLint bits = 0;
    glGetQueryiv(GL_TIMESTAMP, GL_QUERY_COUNTER_BITS, &bits);
    if (bits == 0) {
        TimerVerdict v;
        v.checked = true;
        v.reason = "GL_TIMESTAMP has 0 counter bits on this context";
        return v;
    }
    const Program& program = programs.get({"common/fullscreen.vert", "calibrate/fill.frag", ""}, {});
    // One colour attachment: the workload is the fragment loop, not the frame targets' bandwidth.
    TextureFramebuffer small("timer calibration", kSmall, kSmall, {GL_RGBA8});
    TextureFramebuffer large("timer calibration", kLarge, kLarge, {GL_RGBA8});
    TimerQueryRing ring(1, 1);
    GLint previousProgram = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &previousProgram);
    const GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glDisable(GL_DEPTH_TEST);
    program.use();
    GlFill fill(small, large, ring);
    TimerVerdict v = calibrateWith(fill, "GL_TIMESTAMP pairs");
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    if (depthTest) glEnable(GL_DEPTH_TEST);
    glUseProgram(GLuint(previousProgram));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    v.calibrationMs = msSince(t0);
    v.reason += format(" (%.2f s)", v.calibrationMs * 1e-3);
    return v;
}

TimerVerdict TimerTrust::calibrateWith(TimedFill& fill, const std::string& timer) {
    const int iterations = findIterations(fill);
    std::vector<CalibrationRound> rounds;
    // A failed round decides "untrusted" (trust needs all of them), so the rest are not measured:
    // on llvmpipe the calibration costs one round.
    for (int i = 0; i < kRounds; ++i) {
        const TimedFill::Timing s = medianDraw(fill, false, iterations);
        const TimedFill::Timing l = medianDraw(fill, true, iterations);
        rounds.push_back({s.wallMs, l.wallMs, s.timerMs, l.timerMs});
        if (!checkRound(rounds.back()).empty()) break;
    }
    TimerVerdict v = judge(rounds, timer);
    v.iterations = iterations;
    return v;
}

TimerVerdict TimerTrust::afterRun(const TimerVerdict& before, const TimerVerdict& after) {
    if (!before.checked || !before.trusted) return before;
    TimerVerdict v = before;
    if (after.trusted) {
        v.reason += "; re-checked after the run: trusted";
        return v;
    }
    v.trusted = false;
    v.revoked = true;
    v.rounds = after.rounds;
    v.reason = "trusted before the run, untrusted when re-checked after it: " + after.reason;
    return v;
}

} // namespace sb
