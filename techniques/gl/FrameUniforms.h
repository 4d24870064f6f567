#pragma once
// The per-frame uniform block (binding 0) every shader reads through shaders/common/frame.glsl:
// camera matrices and up to kMaxLights lights. Written once per frame by the harness, so its cost is
// the same for every technique and for the hand-written reference loop.
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include "gl/FrameTargets.h"
#include "scenes/Scene.h"

namespace sb {

/// std140 layout of `uniform Frame` (keep in sync with shaders/common/frame.glsl).
struct FrameUniformData {
    glm::mat4 view, proj, viewProj;
    glm::vec4 eye;
    glm::vec4 ambient; ///< w = light count
    glm::vec4 lightPos[kMaxLights];
    glm::vec4 lightDir[kMaxLights];
    glm::vec4 lightColor[kMaxLights];
    glm::vec4 lightParams[kMaxLights];
};

class FrameUniforms {
public:
    FrameUniforms();
    ~FrameUniforms();
    FrameUniforms(const FrameUniforms&) = delete;
    FrameUniforms& operator=(const FrameUniforms&) = delete;
    /// Fills the block from the camera matrices and the scene's lights (at most kMaxLights).
    static FrameUniformData compute(const Scene& scene, const glm::mat4& view, const glm::mat4& proj,
                                    const glm::vec3& eye);
    /// Uploads and binds at binding 0.
    void upload(const FrameUniformData& data);
    /// Binds the block at binding 0 again (after a technique bound one of its own there).
    void bind() const;

private:
    GLuint mBuffer = 0;
};

} // namespace sb
