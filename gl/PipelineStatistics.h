#pragma once
// Stage loads of one frame from GL_ARB_pipeline_statistics_query (core in GL 4.6): how many vertex shader
// invocations, primitives and fragment shader invocations the GPU (or llvmpipe) actually processed. The
// bottleneck study relates frame time to these loads (docs/ARCHITECTURE.md, "The timing contract").
//
// The queries are only ever wrapped around an UNTIMED census frame: a query is driver work, and the
// harness must not distort the frames it measures. Results are read back with a blocking
// glGetQueryObjectui64v, which is fine outside the measurement.
#include <array>
#include <cstdint>

#include <epoxy/gl.h>

#include "core/PipelineCounts.h"

namespace sb {

class PipelineStatistics {
public:
    /// Needs a current context exposing GL_ARB_pipeline_statistics_query (check available() first).
    PipelineStatistics();
    ~PipelineStatistics();
    PipelineStatistics(const PipelineStatistics&) = delete;
    PipelineStatistics& operator=(const PipelineStatistics&) = delete;

    /// True when the current context can count (GL 4.6 or the ARB extension).
    static bool available(int glMajor, int glMinor, bool hasArbExtension);
    void begin();
    /// Ends the queries and waits for their results.
    PipelineCounts end();

private:
    static constexpr std::array<GLenum, 4> kTargets = {
        GL_VERTEX_SHADER_INVOCATIONS_ARB, GL_PRIMITIVES_SUBMITTED_ARB, GL_CLIPPING_OUTPUT_PRIMITIVES_ARB,
        GL_FRAGMENT_SHADER_INVOCATIONS_ARB};
    std::array<GLuint, 4> mQueries{};
};

} // namespace sb
