#pragma once
// A planar shadow receiver (the `planar` and `blob` techniques; Crawfis, "Ad-hoc shadows": "shadows for
// large planar receivers: ground plane, walls"). A scene declares one by placing a planar mesh (a
// ground, a wall) that receives shadows and casts none: every such instance is a receiver plane. Its
// rectangle is the mesh's extent in the plane, so the stencil can keep shadows on the receiver.
//
// projection() is the slides' matrix: for a plane n.x + d = 0 and a light L (homogeneous: (l, 1) for a
// point or spot light, (-direction, 0) for a directional one), with P = (n, d),
//     M = (P.L) I - L P^T,      M v = (P.L) v - (P.v) L,
// which for v = (v, 1), L = (l, 1) is v' = l - (d + n.l) / (n.(v - l)) (v - l) after the division by w,
// and for the xz plane at y = 0 is the slides' 4x4 matrix row for row.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace sb {

struct Scene;
struct Light;

struct ReceiverPlane {
    uint32_t instance = 0;              ///< index into Scene::instances
    glm::vec3 normal{0.0f, 1.0f, 0.0f}; ///< unit, towards the receiver's front (the side its normals face)
    float d = 0.0f;                     ///< n.x + d = 0 on the plane
    std::array<glm::vec3, 4> corners{}; ///< world rectangle, counter-clockwise seen from the front
    glm::vec3 albedo{0.8f};             ///< the instance's colour (a technique removes albedo * light)

    glm::vec4 equation() const { return {normal, d}; }
    /// Signed distance of `p` from the plane (positive on the front side).
    float distance(const glm::vec3& p) const { return glm::dot(normal, p) + d; }
    /// P.L: positive when the light is in front of the plane (it can shadow the front), 0 when the light
    /// lies in the plane, negative behind it.
    float lightSide(const glm::vec4& light) const { return glm::dot(equation(), light); }
    /// Unit in-plane axes (t, b) with t x b = normal: the rectangle's and the blobs' 2D coordinates.
    static std::pair<glm::vec3, glm::vec3> basis(const glm::vec3& normal);
    /// The slides' flattening matrix towards `light` (homogeneous, see above).
    glm::mat4 projection(const glm::vec4& light) const;

    /// Every instance of `scene` that receives shadows, casts none and whose mesh is planar (all vertices
    /// within 1e-5 of its extent from one plane), in instance order. `tolerance` is relative to the
    /// mesh's bounding-box diagonal.
    static std::vector<ReceiverPlane> find(const Scene& scene, float tolerance = 1e-5f);
    /// The light as a homogeneous point: (position, 1) for point and spot lights, (-direction, 0) for
    /// directional ones (a point at infinity in the direction the light comes from).
    static glm::vec4 homogeneousLight(const Light& light);
};

} // namespace sb
