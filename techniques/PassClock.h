#pragma once
// The CPU side of a frame's passes, on either API: the moment each pass begins (PassTimer::begin on GL,
// VulkanPassTimer::begin on Vulkan), read from the clock the harness times the frame with. The harness
// starts it with the frame and turns the moments into per-pass CPU submit spans after the frame
// (bench/lib/harness/FrameSample.h, `cpuPasses`): a pass's span runs from its begin to the next pass's
// begin, the last one to the end of the frame's submission.
//
// Cost inside a timed frame: one steady_clock read and one store per pass (the storage is kept from frame
// to frame, so nothing is allocated after the first frame). Pass names are kept by pointer: they live for
// the process (the same rule as the timer rings, techniques/gl/PassTimer.h).
#include <chrono>
#include <utility>
#include <vector>

namespace sb {

class PassClock {
public:
    using Clock = std::chrono::steady_clock;

    /// Forgets the last frame's passes; `start` is the frame's own start (its CPU submit begins there).
    void frameBegins(Clock::time_point start) {
        mStart = start;
        mBegins.clear();
    }
    /// Records that `pass` begins now.
    void passBegins(const char* pass) { mBegins.emplace_back(pass, Clock::now()); }

    Clock::time_point frameStart() const { return mStart; }
    /// Each pass begun since frameBegins, in order (a pass entered twice, twice), with its moment.
    const std::vector<std::pair<const char*, Clock::time_point>>& begins() const { return mBegins; }

private:
    Clock::time_point mStart{};
    std::vector<std::pair<const char*, Clock::time_point>> mBegins;
};

} // namespace sb
