#pragma once
// What the pipeline processed in a frame or a pass, as either API's pipeline-statistics queries count it
// (gl/PipelineStatistics, the Vulkan census's query pool): the bottleneck study's loads and the perf
// gate's exact work.
#include <cstdint>

namespace sb {

struct PipelineCounts {
    uint64_t vertexShaderInvocations = 0;
    uint64_t primitivesSubmitted = 0; ///< primitives assembled from the draws (before clipping)
    uint64_t clippingOutputPrimitives = 0;
    uint64_t fragmentShaderInvocations = 0;

    PipelineCounts& operator+=(const PipelineCounts& o) {
        vertexShaderInvocations += o.vertexShaderInvocations;
        primitivesSubmitted += o.primitivesSubmitted;
        clippingOutputPrimitives += o.clippingOutputPrimitives;
        fragmentShaderInvocations += o.fragmentShaderInvocations;
        return *this;
    }
};

} // namespace sb
