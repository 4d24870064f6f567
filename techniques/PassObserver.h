#pragma once
// A hook on the pass boundaries of one frame (PassTimer): the exact-work census
// (bench/lib/harness/WorkCensus.h) wraps each pass of an UNTIMED frame in its own counters. Timed frames run
// with no observer, so the measured path pays one null-pointer test per pass and nothing else.
namespace sb {

class PassObserver {
public:
    virtual ~PassObserver() = default;
    /// Called when `pass` starts (the previous pass, if any, has just ended).
    virtual void passBegins(const char* pass) = 0;
    /// Called when the frame's last pass ends.
    virtual void framePassesEnd() = 0;
    /// Called when a technique skips a declared pass this frame, with why (PassTimer::skip).
    virtual void passSkipped(const char* pass, const char* reason) = 0;
};

} // namespace sb
