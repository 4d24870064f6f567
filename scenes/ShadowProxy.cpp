#include "scenes/ShadowProxy.h"

#include "scenes/Mesh.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace sb {

namespace {

constexpr Named<ShadowProxy::Shape> kShapeNames[] = {
    {ShadowProxy::Shape::Sphere, "sphere"},
    {ShadowProxy::Shape::Box, "box"},
    {ShadowProxy::Shape::Cylinder, "cylinder"},
};
constexpr NameTable kShapes{kShapeNames};

/// Listing 1.1 in the proxy's local frame.
glm::vec3 localClosest(ShadowProxy::Shape shape, const glm::vec3& local) {
    const glm::vec3 sgn(local.x < 0.0f ? -1.0f : 1.0f, local.y < 0.0f ? -1.0f : 1.0f,
                        local.z < 0.0f ? -1.0f : 1.0f); // sign() with 0 -> +1: a point on a plane of
                                                        // symmetry still lands on the surface
    glm::vec3 a = glm::abs(local);
    switch (shape) {
    case ShadowProxy::Shape::Sphere: {
        const float len = glm::length(a);
        a = len > 0.0f ? a / len : glm::vec3(0.0f, 0.0f, 1.0f);
        break;
    }
    case ShadowProxy::Shape::Box:
        a = glm::min(a, glm::vec3(1.0f));
        break;
    case ShadowProxy::Shape::Cylinder: {
        const float r = glm::length(glm::vec2(a));
        if (r > 1.0f) a.x /= r, a.y /= r;
        a.z = std::min(a.z, 1.0f);
        break;
    }
    }
    return sgn * a;
}
} // namespace

glm::vec3 ShadowProxy::closestPoint(const glm::vec3& p) const {
    const glm::vec3 local(glm::inverse(frame) * glm::vec4(p, 1.0f));
    return glm::vec3(frame * glm::vec4(localClosest(shape, local), 1.0f));
}

glm::vec3 ShadowProxy::surfaceNormal(const glm::vec3& p) const {
    const glm::mat4 inv = glm::inverse(frame);
    const glm::vec3 local(inv * glm::vec4(p, 1.0f));
    const glm::vec3 c = localClosest(shape, local);
    glm::vec3 n(0.0f);
    switch (shape) {
    case Shape::Sphere:
        n = c;
        break;
    case Shape::Box: {
        // The face the point is pushed onto: the axis with the largest |local| / 1 (inside: nearest face).
        const glm::vec3 a = glm::abs(local);
        const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
        n[axis] = c[axis] < 0.0f ? -1.0f : 1.0f;
        break;
    }
    case Shape::Cylinder: {
        const float radial = glm::length(glm::vec2(local)), height = std::abs(local.z);
        if (height >= 1.0f && radial <= 1.0f)
            n = glm::vec3(0.0f, 0.0f, local.z < 0.0f ? -1.0f : 1.0f); // cap
        else if (radial > 0.0f)
            n = glm::vec3(local.x / radial, local.y / radial, 0.0f); // side
        else
            n = glm::vec3(0.0f, 0.0f, local.z < 0.0f ? -1.0f : 1.0f);
        break;
    }
    }
    return glm::normalize(glm::transpose(glm::mat3(inv)) * n);
}

float ShadowProxy::volume() const {
    const float det = std::abs(glm::determinant(glm::mat3(frame)));
    switch (shape) {
    case Shape::Sphere:
        return 4.0f / 3.0f * glm::pi<float>() * det;
    case Shape::Box:
        return 8.0f * det;
    case Shape::Cylinder:
        return 2.0f * glm::pi<float>() * det;
    }
    return 0.0f;
}

const NameTable<Named<ShadowProxy::Shape>>& ShadowProxy::shapeNames() {
    return kShapes;
}

const char* ShadowProxy::shapeName(Shape s) {
    return kShapes.name(s);
}

ShadowProxy ShadowProxy::fit(const Mesh& mesh, const glm::mat4& model) {
    const Aabb b = mesh.computeBounds();
    const glm::vec3 centre = b.center(), half = 0.5f * b.extent();
    // Sphere: the farthest vertex from the bounds' centre.
    float radius = 0.0f;
    for (const glm::vec3& p : mesh.positions) radius = std::max(radius, glm::length(p - centre));
    // Cylinder around the longest axis: the farthest vertex from that axis, the half length along it.
    const int axis = half.x >= half.y && half.x >= half.z ? 0 : (half.y >= half.z ? 1 : 2);
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    float radial = 0.0f;
    for (const glm::vec3& p : mesh.positions)
        radial = std::max(radial, glm::length(glm::vec2(p[u] - centre[u], p[v] - centre[v])));
    // Degenerate extents (a flat mesh) keep a tiny positive size so the frame stays invertible.
    const float tiny = 1e-6f * std::max(1.0f, glm::length(b.extent()));
    auto at = [&](const glm::mat4& local) { return model * glm::translate(glm::mat4(1.0f), centre) * local; };
    ShadowProxy sphere, box, cylinder;
    sphere.shape = Shape::Sphere;
    sphere.frame = at(glm::scale(glm::mat4(1.0f), glm::vec3(std::max(radius, tiny))));
    box.shape = Shape::Box;
    box.frame = at(glm::scale(glm::mat4(1.0f), glm::max(half, glm::vec3(tiny))));
    cylinder.shape = Shape::Cylinder;
    // Local z is the cylinder's axis: columns (u, v, axis) of the mesh frame, scaled.
    glm::mat4 basis(0.0f);
    basis[0][u] = std::max(radial, tiny);
    basis[1][v] = std::max(radial, tiny);
    basis[2][axis] = std::max(half[axis], tiny);
    basis[3][3] = 1.0f;
    cylinder.frame = at(basis);
    ShadowProxy best = sphere;
    for (const ShadowProxy* c : {&box, &cylinder})
        if (c->volume() < best.volume()) best = *c;
    return best;
}

float proxyShadow(float distance, float proxyOffset, float shadowFactor, float falloffExponent) {
    float shadow = 0.0f;
    if (proxyOffset > 0.0f)
        shadow = 1.0f - std::clamp(std::min(distance / proxyOffset, 1.0f), 0.0f, 1.0f);
    else
        shadow = distance <= 0.0f ? 1.0f : 0.0f;
    return shadow * std::pow(shadowFactor, falloffExponent);
}

} // namespace sb
