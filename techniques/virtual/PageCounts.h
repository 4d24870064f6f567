#pragma once
// `virtual`'s counters of a frame (NOTES-virtual.md, "Counters"): exact counts of pages, the same on
// both APIs because the CPU allocates (VirtualPageCache) from the GPU's marks. pages_rendered is the
// depth pass's work, what the perf gate's work layer compares.
#include <cstdint>

#include "techniques/TechniqueInfo.h"

namespace sb {

struct PageCounts {
    uint32_t needed = 0;      ///< pages the view's receivers read (PageMarking)
    uint32_t allocated = 0;   ///< pages given a slot this frame (they had none)
    uint32_t rendered = 0;    ///< pages the depth pass drew: allocated, or mapped but no longer valid
    uint32_t reused = 0;      ///< needed pages whose cached content was valid: not drawn
    uint32_t invalidated = 0; ///< valid pages whose content motion made stale (light or casters)
    uint32_t evicted = 0;     ///< cached pages dropped to make room for needed ones
    uint32_t dropped = 0;     ///< needed pages left without a slot: the pool was full (the lookup says lit)
    uint32_t resident = 0;    ///< pages holding a slot after the frame, needed or cached

    /// As the technique reports them: "pages_needed", "pages_allocated", ... in the order above.
    Counters toCounters() const;
};

} // namespace sb
