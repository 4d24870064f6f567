#pragma once
#include <string>

namespace sb {

/// One pass of one measured frame on the CPU (techniques/PassClock.h): from the moment the technique
/// began the pass to the moment it began the next one, or, for the frame's last pass, to the end of the
/// frame's submission (GL: the last call before glFinish; Vulkan: vkQueueSubmit returned). Both
/// readings are real clock readings; the time before the first pass (scene motion, frame block, clear)
/// belongs to no pass, so a frame's spans sum to at most its CPU submit time.
struct CpuPassSpan {
    std::string pass;
    double startMs = 0.0;    ///< from the frame's start (FrameSample::startMs)
    double durationMs = 0.0; ///< measured, never estimated
};

} // namespace sb
