#pragma once
// The per-frame uniform block (techniques/FrameBlock.h) in a GL buffer at binding 0. Written once per
// frame by the harness, so its cost is the same for every technique and for the hand-written reference
// loop.
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "techniques/FrameBlock.h"

namespace sb {

class FrameUniforms {
public:
    FrameUniforms();
    ~FrameUniforms();
    FrameUniforms(const FrameUniforms&) = delete;
    FrameUniforms& operator=(const FrameUniforms&) = delete;
    /// Uploads and binds at binding 0.
    void upload(const FrameUniformData& data);
    /// Binds the block at binding 0 again (after a technique bound one of its own there).
    void bind() const;

private:
    GLuint mBuffer = 0;
};

} // namespace sb
