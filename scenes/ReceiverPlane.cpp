#include "scenes/ReceiverPlane.h"

#include <algorithm>
#include <cmath>

#include "scenes/Math.h"
#include "scenes/Scene.h"

namespace sb {

namespace {
/// The plane of an object-space mesh when every vertex lies on it: the normal is the mean of the
/// vertex normals (the side the mesh faces), the offset that of the first vertex.
bool meshPlane(const Mesh& mesh, float tolerance, glm::vec3& n, float& d) {
    if (mesh.positions.size() < 3 || mesh.normals.size() != mesh.positions.size()) return false;
    glm::vec3 sum(0.0f);
    for (const glm::vec3& v : mesh.normals) sum += v;
    const float len = glm::length(sum);
    if (!(len > 0.5f * float(mesh.normals.size()))) return false; // normals disagree: not one plane
    n = sum / len;
    d = -glm::dot(n, mesh.positions[0]);
    const float limit = tolerance * std::max(glm::length(mesh.computeBounds().extent()), 1e-6f);
    return std::all_of(mesh.positions.begin(), mesh.positions.end(),
                       [&](const glm::vec3& p) { return std::abs(glm::dot(n, p) + d) <= limit; });
}
} // namespace

std::pair<glm::vec3, glm::vec3> ReceiverPlane::basis(const glm::vec3& normal) {
    const glm::vec3 t = glm::normalize(glm::cross(anyPerpendicularUp(normal), normal));
    return {t, glm::cross(normal, t)};
}

glm::mat4 ReceiverPlane::projection(const glm::vec4& light) const {
    const glm::vec4 p = equation();
    // glm::outerProduct(c, r) is c r^T (column c, row r).
    return glm::dot(p, light) * glm::mat4(1.0f) - glm::outerProduct(light, p);
}

glm::vec4 ReceiverPlane::homogeneousLight(const Light& light) {
    if (light.type == LightType::Directional) return {-glm::normalize(light.direction), 0.0f};
    return {light.position, 1.0f};
}

std::vector<ReceiverPlane> ReceiverPlane::find(const Scene& scene, float tolerance) {
    std::vector<ReceiverPlane> out;
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        if (inst.castsShadow || !inst.receivesShadow) continue;
        const Mesh& mesh = scene.meshes[inst.mesh];
        glm::vec3 n;
        float d;
        if (!meshPlane(mesh, tolerance, n, d)) continue;
        // The rectangle spanned by the vertices in an in-plane basis (t, b, n right-handed, so the
        // corners run counter-clockwise seen from the front).
        const auto [t, b] = basis(n);
        glm::vec2 lo(INFINITY), hi(-INFINITY);
        for (const glm::vec3& p : mesh.positions) {
            const glm::vec2 q(glm::dot(p, t), glm::dot(p, b));
            lo = glm::min(lo, q);
            hi = glm::max(hi, q);
        }
        const glm::vec3 origin = -d * n;
        const glm::vec2 uv[4] = {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}};
        ReceiverPlane plane;
        plane.instance = i;
        for (int c = 0; c < 4; ++c)
            plane.corners[size_t(c)] =
                glm::vec3(inst.model * glm::vec4(origin + uv[c].x * t + uv[c].y * b, 1.0f));
        // Instances have uniform scale (Scene.h), so mat3(model) keeps the normal's direction.
        plane.normal = glm::normalize(glm::mat3(inst.model) * n);
        plane.d = -glm::dot(plane.normal, plane.corners[0]);
        plane.albedo = inst.color;
        out.push_back(plane);
    }
    return out;
}

} // namespace sb
