#pragma once
// Small math helpers on top of GLM used by the harness and techniques (unit-tested in MathTest).
#include <glm/glm.hpp>

#include "scenes/Mesh.h"
#include "scenes/Scene.h"

namespace sb {

/// Model matrix T * Rx * Ry * Rz * S for an instance.
glm::mat4 composeTransform(const glm::vec3& position, const glm::vec3& rotationDeg, float scale);
/// World-space AABB of a transformed box (the 8 corners, transformed).
Aabb transformBounds(const Aabb& b, const glm::mat4& m);
/// Perspective projection (OpenGL clip conventions, z in [-1,1]) for a camera preset and aspect.
glm::mat4 cameraProjection(const CameraPreset& c, float aspect);
glm::mat4 cameraView(const CameraPreset& c);
/// A unit up vector not parallel to `dir` (for lookAt from a light direction, any direction works).
glm::vec3 anyPerpendicularUp(const glm::vec3& dir);

} // namespace sb
