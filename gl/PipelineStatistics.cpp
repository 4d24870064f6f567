#include "gl/PipelineStatistics.h"

namespace sb {

PipelineStatistics::PipelineStatistics() {
    // glGenQueries, not glCreateQueries: Mesa 22.3 rejects the ARB statistics targets there
    // (GL_INVALID_ENUM) while accepting them in glBeginQuery, which creates the objects.
    glGenQueries(GLsizei(mQueries.size()), mQueries.data());
}

PipelineStatistics::~PipelineStatistics() {
    glDeleteQueries(GLsizei(mQueries.size()), mQueries.data());
}

bool PipelineStatistics::available(int glMajor, int glMinor, bool hasArbExtension) {
    return hasArbExtension || glMajor > 4 || (glMajor == 4 && glMinor >= 6);
}

void PipelineStatistics::begin() {
    for (size_t i = 0; i < kTargets.size(); ++i) glBeginQuery(kTargets[i], mQueries[i]);
}

PipelineCounts PipelineStatistics::end() {
    for (GLenum target : kTargets) glEndQuery(target);
    std::array<GLuint64, 4> v{};
    // GL_QUERY_RESULT waits: this frame is not timed (see the header).
    for (size_t i = 0; i < kTargets.size(); ++i) glGetQueryObjectui64v(mQueries[i], GL_QUERY_RESULT, &v[i]);
    return {v[0], v[1], v[2], v[3]};
}

} // namespace sb
