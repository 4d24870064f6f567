#include "scenes/Math.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sb {

glm::mat4 composeTransform(const glm::vec3& position, const glm::vec3& rotationDeg, float scale) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
    m = glm::rotate(m, glm::radians(rotationDeg.x), glm::vec3(1, 0, 0));
    m = glm::rotate(m, glm::radians(rotationDeg.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotationDeg.z), glm::vec3(0, 0, 1));
    return glm::scale(m, glm::vec3(scale));
}

Aabb transformBounds(const Aabb& b, const glm::mat4& m) {
    Aabb out;
    if (b.empty()) return out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                          (corner & 4) ? b.max.z : b.min.z);
        out.extend(glm::vec3(m * glm::vec4(p, 1.0f)));
    }
    return out;
}

glm::mat4 cameraProjection(const CameraPreset& c, float aspect) {
    return glm::perspective(glm::radians(c.fovYDeg), aspect, c.nearZ, c.farZ);
}

glm::mat4 cameraView(const CameraPreset& c) {
    return glm::lookAt(c.eye, c.target, c.up);
}

glm::vec3 anyPerpendicularUp(const glm::vec3& dir) {
    // World up unless the direction is (nearly) vertical; then +Z, which is then far from parallel.
    const glm::vec3 d = glm::normalize(dir);
    return std::abs(d.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
}

} // namespace sb
