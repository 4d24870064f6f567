#pragma once
// Per-pass GPU timing from a ring of GL_TIMESTAMP queries read back frames later, never stalling
// (docs/ARCHITECTURE.md, "The timing contract"). Each frame: beginFrame(), then mark(passName) at each pass
// boundary, then endFrame(). Results of frame f become available from frame f + latency on; a frame whose
// queries are not yet available when its slot is reused is counted as dropped rather than waited for.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <epoxy/gl.h>

#include "core/PassTimes.h"

namespace sb {

class TimerQueryRing {
public:
    explicit TimerQueryRing(int depth = 4, int maxPassesPerFrame = 16);
    ~TimerQueryRing();
    TimerQueryRing(const TimerQueryRing&) = delete;
    TimerQueryRing& operator=(const TimerQueryRing&) = delete;

    void beginFrame();
    /// Starts pass `name` (ends the previous one). Names must stay valid (string literals / stable).
    void beginPass(const char* name);
    void endFrame();
    /// Collects every completed frame without waiting (GL_QUERY_RESULT_AVAILABLE), oldest first.
    std::vector<PassTimes> collect();
    /// Waits for all outstanding frames (only at the end of a run, outside timed frames).
    std::vector<PassTimes> drain();
    uint64_t droppedFrames() const { return mDropped; }

private:
    struct Slot {
        uint64_t frame = 0;
        bool pending = false;
        std::vector<GLuint> queries; ///< maxPasses + 1 timestamps
        std::vector<const char*> names;
        int used = 0;
    };
    std::optional<PassTimes> read(Slot& s, bool wait);
    std::vector<Slot> mSlots;
    int mCurrent = -1;
    uint64_t mFrame = 0;
    uint64_t mDropped = 0;
    int mMaxPasses;
    /// Added to the interface sketch: frames read in beginFrame() when their slot came round again while
    /// complete; handed out by the next collect()/drain() so no completed frame is lost.
    std::vector<PassTimes> mReady;
};

} // namespace sb
