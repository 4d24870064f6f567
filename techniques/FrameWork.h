#pragma once
// The exact work of one frame, pass by pass, on either API: what the application submitted (its
// submitter's counts) and, where the driver counts them, what the pipeline processed (pipeline-statistics
// queries). The census frame of each API's harness fills it; the rows' work_* and load_* columns and the
// perf gate's layer A read it.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/PipelineCounts.h"
#include "techniques/Submission.h"

namespace sb {

struct PassWork {
    SubmitStats submitted;
    std::optional<PipelineCounts> pipeline; ///< empty where the driver cannot count the pipeline
};

/// Per pass, in the order the passes first ran (a pass entered several times is summed).
using FrameWork = std::vector<std::pair<std::string, PassWork>>;
/// Passes a technique left out of the frame and why (the pass timer's skip), in the order it said so.
using SkippedPasses = std::vector<std::pair<std::string, std::string>>;

/// Sums the passes (the whole frame's work).
PassWork totalWork(const FrameWork& work);

/// The loads of one untimed census frame: what the application submitted and, where the driver can count
/// them, what the pipeline processed, in total and pass by pass. The bottleneck study relates frame time
/// to these.
struct FrameLoads {
    SubmitStats submitted;
    std::optional<PipelineCounts> pipeline;
    FrameWork passes;      ///< the same, pass by pass (they sum to the above)
    SkippedPasses skipped; ///< passes the technique left out, with its reasons
};

} // namespace sb
