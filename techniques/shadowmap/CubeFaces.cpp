#include "techniques/shadowmap/CubeFaces.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sb {

namespace {
// Axis and up of each face. With lookAt's right = forward x up, window x runs along the table's s
// axis and window y along its t axis (s = -z, t = -y for +X; s = x, t = z for +Y; ...).
struct FaceFrame {
    glm::vec3 forward, up;
};
constexpr FaceFrame kFrames[CubeFaces::kFaces] = {
    {{1, 0, 0}, {0, -1, 0}},  {{-1, 0, 0}, {0, -1, 0}}, {{0, 1, 0}, {0, 0, 1}},
    {{0, -1, 0}, {0, 0, -1}}, {{0, 0, 1}, {0, -1, 0}},  {{0, 0, -1}, {0, -1, 0}},
};
} // namespace

CubeFaces::CubeFaces(const glm::vec3& position, float nearZ, float farZ)
    : mProjection(glm::perspective(glm::radians(90.0f), 1.0f, nearZ, farZ)) {
    for (int f = 0; f < kFaces; ++f) {
        const FaceFrame& fr = kFrames[f];
        mView[size_t(f)] = glm::lookAt(position, position + fr.forward, fr.up);
        mViewProjection[size_t(f)] = mProjection * mView[size_t(f)];
    }
}

int CubeFaces::faceOf(const glm::vec3& d) {
    const glm::vec3 a = glm::abs(d);
    if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0f ? 0 : 1;
    if (a.y >= a.z) return d.y >= 0.0f ? 2 : 3;
    return d.z >= 0.0f ? 4 : 5;
}

float CubeFaces::windowDepth(float z, float nearZ, float farZ) {
    const float ndc = (farZ + nearZ) / (farZ - nearZ) - 2.0f * farZ * nearZ / ((farZ - nearZ) * z);
    return 0.5f * ndc + 0.5f;
}

} // namespace sb
