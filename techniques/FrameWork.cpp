#include "techniques/FrameWork.h"

namespace sb {

PassWork totalWork(const FrameWork& work) {
    PassWork total;
    for (const auto& [pass, w] : work) {
        total.submitted += w.submitted;
        if (!w.pipeline) continue;
        if (!total.pipeline) total.pipeline = PipelineCounts{};
        *total.pipeline += *w.pipeline;
    }
    return total;
}

} // namespace sb
