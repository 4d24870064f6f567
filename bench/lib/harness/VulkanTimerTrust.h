#pragma once
// The GPU-timer trust check on Vulkan (bench/lib/harness/TimerTrust.h on GL, the same rules and thresholds):
// a fragment-bound fill (shaders/calibrate/fill.frag) into a 512^2 and a 1024^2 target, each draw in a
// frame of its own timed by vkCmdWriteTimestamp pairs and by the wall clock from submit to fence. The
// timestamps are trusted only if they grow with the pixels, like the wall clock, and cover the frame,
// in every round (TimerTrust::judge). Until then a Vulkan row shows no GPU time.
#include "bench/lib/harness/TimerTrust.h"

namespace sb {

class ShaderModuleCache;
class VulkanContext;

class VulkanTimerTrust {
public:
    static TimerVerdict calibrate(VulkanContext& context, ShaderModuleCache& shaders);
};

} // namespace sb
