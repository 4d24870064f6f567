#include "techniques/gl/FrameUniforms.h"

namespace sb {

FrameUniforms::FrameUniforms() {
    glCreateBuffers(1, &mBuffer);
    glNamedBufferStorage(mBuffer, sizeof(FrameUniformData), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

FrameUniforms::~FrameUniforms() {
    glDeleteBuffers(1, &mBuffer);
}

void FrameUniforms::upload(const FrameUniformData& data) {
    glNamedBufferSubData(mBuffer, 0, sizeof(FrameUniformData), &data);
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, mBuffer);
}

void FrameUniforms::bind() const {
    glBindBufferBase(GL_UNIFORM_BUFFER, 0, mBuffer);
}

} // namespace sb
