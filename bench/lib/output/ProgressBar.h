#pragma once
// The progress of a long run on stderr: configurations done, failed, elapsed, an estimate of the time
// left and what runs now. On a terminal one line is redrawn in place; otherwise (CI logs, a pipe) one
// line per finished configuration, so logs stay readable and greppable.
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>
#include <type_traits>

namespace sb {

class ProgressBar {
public:
    /// `total` configurations of which `alreadyDone` finished in an earlier run (--resume).
    ProgressBar(std::FILE* out, size_t total, size_t alreadyDone, bool enabled = true);
    /// What runs now (shown on a terminal only).
    void setCurrent(const std::string& what);
    /// One configuration finished; `label` says which, `ok` whether it succeeded.
    void finished(const std::string& label, bool ok);
    /// Runs `work` as one configuration named `label`: shown as what runs now, then finished, ok unless
    /// `work` throws (counted as failed, and the exception goes on). Returns what `work` returns.
    template <class Work>
    auto step(const std::string& label, Work&& work) {
        setCurrent(label);
        try {
            if constexpr (std::is_void_v<decltype(work())>) {
                work();
                finished(label, true);
            } else {
                auto result = work();
                finished(label, true);
                return result;
            }
        } catch (...) {
            finished(label, false);
            close();
            throw;
        }
    }
    /// Ends the in-place line (call before printing anything else).
    void close();

    /// "1h02m", "3m05s", "12s" (for messages too).
    static std::string formatDuration(double seconds);

private:
    void draw();
    std::string status() const; ///< "12/48, 1 failed, 1m05s, ~3m15s left"
    std::string bar(size_t width) const;
    std::FILE* mOut;
    size_t mTotal, mBefore, mDone = 0, mFailed = 0;
    bool mEnabled, mTerminal;
    std::string mCurrent;
    std::chrono::steady_clock::time_point mStart = std::chrono::steady_clock::now();
};

} // namespace sb
