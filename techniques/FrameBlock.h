#pragma once
// The per-frame uniform block every shader reads through shaders/common/frame.glsl, on both APIs: camera
// matrices and up to kMaxLights lights. Its contents are computed once here; techniques/gl/FrameUniforms
// uploads it to a GL buffer at binding 0, techniques/vulkan/VulkanFrameBlock to a Vulkan one at set 0
// (converting GL's clip space).
#include <glm/glm.hpp>

#include "scenes/Scene.h"
#include "shading/ShaderLimits.h"

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

/// What the block says of a light that no motion changes (scenes/Scene.h: motion moves lights, it does
/// not change them): colour x intensity (rgb) and range (w, 0 = unlimited); cos of the cone's outer and
/// inner half-angles (x, y; a directional or point light's are unused). One computation for the block and
/// for the compile-time constants the lit passes take instead (addLightKindDefines, techniques/Technique.h).
struct LightConstants {
    glm::vec4 colorRange;
    glm::vec2 coneCos;
};
LightConstants lightConstants(const Light& light);

/// The block from the camera matrices (GL conventions) and the scene's lights (at most kMaxLights).
FrameUniformData computeFrameUniforms(const Scene& scene, const glm::mat4& view, const glm::mat4& proj,
                                      const glm::vec3& eye);

} // namespace sb
