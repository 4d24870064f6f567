#pragma once
// What a Vulkan technique calls at each pass (techniques/gl/PassTimer.h on GL): a timestamp into the frame's
// slot of the ring where timestamps are on and, in the census frame, what each pass submitted (the
// submitter's counts between one pass's begin and the next's) and the passes left out with their
// reasons.
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "techniques/PassClock.h"
#include "techniques/PassRouter.h"
#include "techniques/Submission.h"
#include "vk/TimestampRing.h"

namespace sb {

class VulkanSubmitter;

class VulkanPassTimer {
public:
    /// nullptr: no timestamps (the verdict is untrusted, or the device writes none).
    void setRing(TimestampRing* ring) { mRing = ring; }
    void setCommandBuffer(VkCommandBuffer cmd) { mCmd = cmd; }
    /// nullptr: none. The harness sets one to take each pass's CPU begin (techniques/PassClock.h).
    void setClock(PassClock* clock) { mClock = clock; }
    /// nullptr: none. A hybrid technique sets one while each of its parts runs, so the part's passes are
    /// recorded under the role's names (techniques/PassRouter.h), as PassTimer does on GL.
    void setRouter(PassRouter* router) { mRouter = router; }
    PassRouter* router() const { return mRouter; }
    /// Starts `pass` (outside a render pass). `pass` must outlive the frame (a literal).
    void begin(const char* pass);
    /// The technique leaves out declared pass `pass` this frame because of `reason` (literals).
    void skip(const char* pass, const char* reason);

    /// The census: from now on, per-pass submitted work of `submitter` and the skipped passes and, with
    /// a pipeline-statistics pool (kStatistics, at least kMaxCensusPasses queries), one query per pass
    /// begun outside the render passes and ended at the next pass or endCensusFrame().
    void startCensus(const VulkanSubmitter& submitter, VkQueryPool statistics = VK_NULL_HANDLE);
    /// Ends the last pass's query (before the command buffer ends).
    void endCensusFrame();
    /// After the census frame's fence: per query, the pass it counted (in order).
    const std::vector<std::string>& queriedPasses() const { return mQueried; }
    static constexpr uint32_t kMaxCensusPasses = 64;
    /// The statistics each query counts, in the order vkGetQueryPoolResults returns them (bit order):
    /// input-assembly primitives, vertex-shader invocations, clipping primitives, fragment invocations.
    static constexpr VkQueryPipelineStatisticFlags kStatistics =
        VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT |
        VK_QUERY_PIPELINE_STATISTIC_VERTEX_SHADER_INVOCATIONS_BIT |
        VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT |
        VK_QUERY_PIPELINE_STATISTIC_FRAGMENT_SHADER_INVOCATIONS_BIT;
    /// Ends the census: the work per pass (in the order the passes first ran; a pass entered several
    /// times is summed) and the passes skipped.
    std::vector<std::pair<std::string, SubmitStats>> finishCensus();
    std::vector<std::pair<std::string, std::string>> takeSkipped() { return std::exchange(mSkipped, {}); }

private:
    void closeInterval();
    TimestampRing* mRing = nullptr;
    PassClock* mClock = nullptr;
    PassRouter* mRouter = nullptr;
    VkCommandBuffer mCmd = VK_NULL_HANDLE;
    const VulkanSubmitter* mCensus = nullptr;
    VkQueryPool mStatistics = VK_NULL_HANDLE;
    bool mQueryOpen = false;
    std::vector<std::string> mQueried;
    std::string mOpen;
    SubmitStats mStart;
    std::vector<std::pair<std::string, SubmitStats>> mWork;
    std::vector<std::pair<std::string, std::string>> mSkipped;
};

} // namespace sb
