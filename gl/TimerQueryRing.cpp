#include "gl/TimerQueryRing.h"

#include <algorithm>

#include "core/Error.h"

namespace sb {
namespace {

constexpr double kNsPerMs = 1.0e6;

double elapsedMs(GLuint64 from, GLuint64 to) {
    // Signed: a driver whose timestamps are not monotonic across a frame shows up as a negative time
    // rather than as a huge unsigned wrap-around.
    return static_cast<double>(static_cast<int64_t>(to - from)) / kNsPerMs;
}

} // namespace

TimerQueryRing::TimerQueryRing(int depth, int maxPassesPerFrame)
    : mSlots(std::max(depth, 1)), mMaxPasses(maxPassesPerFrame) {
    if (maxPassesPerFrame < 1)
        throw Error("TimerQueryRing: maxPassesPerFrame must be >= 1", ExitCode::Failure);
    for (Slot& slot : mSlots) {
        // maxPasses pass starts + the end-of-frame stamp.
        slot.queries.resize(static_cast<size_t>(mMaxPasses) + 1);
        glCreateQueries(GL_TIMESTAMP, static_cast<GLsizei>(slot.queries.size()), slot.queries.data());
        slot.names.reserve(static_cast<size_t>(mMaxPasses));
    }
}

TimerQueryRing::~TimerQueryRing() {
    for (Slot& slot : mSlots) glDeleteQueries(static_cast<GLsizei>(slot.queries.size()), slot.queries.data());
}

void TimerQueryRing::beginFrame() {
    mCurrent = (mCurrent + 1) % static_cast<int>(mSlots.size());
    Slot& slot = mSlots[mCurrent];
    if (slot.pending) {
        // The ring came round before anyone collected this frame: keep it if the GPU is done, else drop it
        // (waiting here would stall the frame being measured).
        if (std::optional<PassTimes> times = read(slot, false)) {
            mReady.push_back(std::move(*times));
        } else {
            ++mDropped;
            slot.pending = false;
        }
    }
    slot.frame = mFrame++;
    slot.names.clear();
    slot.used = 0;
}

void TimerQueryRing::beginPass(const char* name) {
    if (mCurrent < 0) throw Error("TimerQueryRing: beginPass before beginFrame", ExitCode::Failure);
    Slot& slot = mSlots[mCurrent];
    if (slot.used >= mMaxPasses)
        throw Error("TimerQueryRing: more than " + std::to_string(mMaxPasses) + " passes in a frame (pass '" +
                        name + "')",
                    ExitCode::Failure);
    glQueryCounter(slot.queries[slot.used], GL_TIMESTAMP);
    slot.names.push_back(name);
    ++slot.used;
}

void TimerQueryRing::endFrame() {
    if (mCurrent < 0) return;
    Slot& slot = mSlots[mCurrent];
    if (slot.used == 0) return; // nothing timed: no record
    glQueryCounter(slot.queries[slot.used], GL_TIMESTAMP);
    slot.pending = true;
}

std::optional<PassTimes> TimerQueryRing::read(Slot& s, bool wait) {
    const int stamps = s.used + 1;
    if (!wait) {
        // Every stamp is checked, not only the last: the spec does not order availability.
        for (int i = 0; i < stamps; ++i) {
            GLint available = GL_FALSE;
            glGetQueryObjectiv(s.queries[i], GL_QUERY_RESULT_AVAILABLE, &available);
            if (!available) return std::nullopt;
        }
    }
    std::vector<GLuint64> time(static_cast<size_t>(stamps));
    for (int i = 0; i < stamps; ++i) glGetQueryObjectui64v(s.queries[i], GL_QUERY_RESULT, &time[i]);
    PassTimes result;
    result.frame = s.frame;
    for (int i = 0; i < s.used; ++i) result.passMs.emplace_back(s.names[i], elapsedMs(time[i], time[i + 1]));
    result.totalMs = elapsedMs(time[0], time[s.used]);
    s.pending = false;
    return result;
}

std::vector<PassTimes> TimerQueryRing::collect() {
    std::vector<PassTimes> out = std::move(mReady);
    mReady.clear();
    // Oldest first: the slots after the current one, wrapping round, end with the current one.
    const int depth = static_cast<int>(mSlots.size());
    for (int k = 1; k <= depth; ++k) {
        Slot& slot = mSlots[(mCurrent + k) % depth];
        if (!slot.pending) continue;
        std::optional<PassTimes> times = read(slot, false);
        if (!times) break; // a newer frame is not reported before an older one
        out.push_back(std::move(*times));
    }
    return out;
}

std::vector<PassTimes> TimerQueryRing::drain() {
    std::vector<PassTimes> out = std::move(mReady);
    mReady.clear();
    const int depth = static_cast<int>(mSlots.size());
    for (int k = 1; k <= depth; ++k) {
        Slot& slot = mSlots[(mCurrent + k) % depth];
        if (slot.pending) out.push_back(*read(slot, true));
    }
    return out;
}

} // namespace sb
