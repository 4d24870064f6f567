#include "bench/lib/output/ProgressBar.h"

#include <unistd.h>

namespace sb {

ProgressBar::ProgressBar(std::FILE* out, size_t total, size_t alreadyDone, bool enabled)
    : mOut(out), mTotal(total), mBefore(alreadyDone), mEnabled(enabled), mTerminal(::isatty(::fileno(out))) {
    if (mEnabled && mBefore)
        std::fprintf(mOut, "%zu of %zu configurations done in an earlier run; %zu to go\n", mBefore, mTotal,
                     mTotal - mBefore);
}

std::string ProgressBar::formatDuration(double seconds) {
    const long s = long(seconds + 0.5);
    char buf[32];
    if (s >= 3600)
        std::snprintf(buf, sizeof buf, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
    else if (s >= 60)
        std::snprintf(buf, sizeof buf, "%ldm%02lds", s / 60, s % 60);
    else
        std::snprintf(buf, sizeof buf, "%lds", s);
    return buf;
}

std::string ProgressBar::bar(size_t width) const {
    const size_t done = mBefore + mDone;
    const size_t filled = mTotal ? done * width / mTotal : width;
    return "[" + std::string(filled, '#') + std::string(width - filled, '.') + "]";
}

void ProgressBar::setCurrent(const std::string& what) {
    mCurrent = what;
    if (mEnabled && mTerminal) draw();
}

void ProgressBar::finished(const std::string& label, bool ok) {
    ++mDone;
    mFailed += ok ? 0 : 1;
    if (!mEnabled) return;
    if (mTerminal) {
        draw();
        return;
    }
    std::fprintf(mOut, "%s %s  (%s)\n", ok ? "ok    " : "FAILED", label.c_str(), status().c_str());
    std::fflush(mOut);
}

std::string ProgressBar::status() const {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
    const size_t left = mTotal - mBefore - mDone;
    // The mean time per configuration so far: configurations of one sweep differ, but shards take every
    // N-th group, so the mean settles quickly.
    std::string out = std::to_string(mBefore + mDone) + "/" + std::to_string(mTotal) +
                      (mFailed ? ", " + std::to_string(mFailed) + " failed" : "") + ", " +
                      formatDuration(elapsed);
    if (mDone && left) out += ", ~" + formatDuration(elapsed / double(mDone) * double(left)) + " left";
    return out;
}

void ProgressBar::draw() {
    std::string line = bar(24) + " " + status() + (mCurrent.empty() ? "" : " | " + mCurrent);
    if (line.size() > 150) line = line.substr(0, 147) + "...";
    std::fprintf(mOut, "\r\033[K%s", line.c_str());
    std::fflush(mOut);
}

void ProgressBar::close() {
    if (mEnabled && mTerminal) std::fprintf(mOut, "\n");
}

} // namespace sb
