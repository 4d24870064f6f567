#include "scenes/BackFaceCulling.h"

#include <algorithm>
#include <cmath>

namespace sb {

namespace {

/// 3x3 determinant of the columns a, b, c.
double det3(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    return glm::dot(a, glm::cross(b, c));
}

} // namespace

const char* backFacesName(BackFaces mode) {
    return mode == BackFaces::Cull ? "cull" : "draw";
}

std::optional<BackFaces> parseBackFaces(const std::string& text) {
    if (text == "cull") return BackFaces::Cull;
    if (text == "draw") return BackFaces::Draw;
    return std::nullopt;
}

bool projectionCentre(const glm::mat4& viewProj, glm::vec3& centre) {
    // The centre C solves rows x, y and w of M times (C, 1) = 0: the homogeneous null vector of those
    // three rows, their generalised cross product (signed 3x3 minors). glm is column-major: m[c][r].
    const glm::dmat4 m(viewProj);
    auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    const glm::dvec4 r0 = row(0), r1 = row(1), r3 = row(3);
    auto column = [&](int c) { return glm::dvec3(r0[c], r1[c], r3[c]); };
    const glm::dvec3 c0 = column(0), c1 = column(1), c2 = column(2), c3 = column(3);
    const double x = det3(c1, c2, c3), y = -det3(c0, c2, c3), z = det3(c0, c1, c3), w = -det3(c0, c1, c2);
    // Parallel: w vanishes against the other components (the centre lies at infinity).
    const double scale = std::max({std::abs(x), std::abs(y), std::abs(z)});
    if (std::abs(w) <= 1e-9 * scale || w == 0.0) return false;
    centre = glm::vec3(glm::dvec3(x, y, z) / w);
    return true;
}

bool mayCullBackFaces(const Aabb& box, const CullView& view) {
    glm::vec3 eye;
    const bool perspective = projectionCentre(view.viewProj, eye);
    return mayCullBackFaces(box, view, perspective ? &eye : nullptr);
}

bool mayCullBackFaces(const Aabb& box, const CullView& view, const glm::vec3* centre) {
    if (box.empty()) return false;
    if (centre) {
        const glm::vec3& eye = *centre;
        // Strictly outside, by a millionth of the corners' magnitudes: a centre on the box's face
        // may lie on the mesh itself.
        const glm::vec3 margin = 1e-6f * (glm::abs(box.min) + glm::abs(box.max)) + 1e-12f;
        const bool inside = glm::all(glm::greaterThanEqual(eye, box.min - margin)) &&
                            glm::all(glm::lessThanEqual(eye, box.max + margin));
        if (inside) return false;
    }
    if (view.clampsDepth) return true;
    // Every corner strictly in front of the near plane (clip z > -w) and of the projection centre.
    for (const glm::vec3& corner : box.corners()) {
        const glm::vec4 p = view.viewProj * glm::vec4(corner, 1.0f);
        if (!(p.w > 0.0f) || !(p.z > -p.w)) return false;
    }
    return true;
}

bool frontFaceCounterClockwise(const glm::mat4& viewProj, bool framebufferYDown) {
    // Not det(viewProj): a GL projection flips z (negative determinant) and keeps the winding. Instead,
    // a triangle counter-clockwise in normalised device coordinates (x right, y up) is taken back to
    // world space; it is a front face there when its normal points towards the viewpoint, i.e. along
    // the ray from deeper points towards the near plane.
    const glm::dmat4 inverse = glm::inverse(glm::dmat4(viewProj));
    auto unproject = [&](double x, double y, double z) {
        const glm::dvec4 p = inverse * glm::dvec4(x, y, z, 1.0);
        return glm::dvec3(p) / p.w;
    };
    const glm::dvec3 a = unproject(0.0, 0.0, 0.0), b = unproject(0.5, 0.0, 0.0), c = unproject(0.0, 0.5, 0.0);
    // From mid-depth to the near plane: finite also for an infinite far plane (volume's projection).
    const glm::dvec3 towardsViewpoint = unproject(0.0, 0.0, -1.0) - unproject(0.0, 0.0, 0.5);
    const bool ccwIsFront = glm::dot(glm::cross(b - a, c - a), towardsViewpoint) > 0.0;
    // Vulkan counts the winding in framebuffer coordinates, whose y runs down: the same triangle the
    // other way round.
    return ccwIsFront != framebufferYDown;
}

void BackFaceCuller::setScene(const Scene& scene, BackFaces mode) {
    mMode = mode;
    mBounds.setScene(scene);
    mClosed.clear();
    mCandidates.clear();
    mCulled.assign(scene.instances.size(), 0);
    mAny = false;
    if (mode == BackFaces::Draw) return;
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        if (inst.mesh < scene.meshes.size() && scene.meshes[inst.mesh].closed) mClosed.push_back(uint32_t(i));
    }
    findCandidates(scene);
}

void BackFaceCuller::instancesMoved(const Scene& scene) {
    if (mCulled.size() != scene.instances.size()) {
        setScene(scene, mMode);
        return;
    }
    mBounds.instancesMoved(scene);
    findCandidates(scene);
}

void BackFaceCuller::findCandidates(const Scene& scene) {
    for (uint32_t i : mCandidates) mCulled[i] = 0; // no stale decision for an instance that left the list
    mAny = false;
    mCandidates.clear(); // keeps its capacity: no allocation inside the timed frame
    for (uint32_t i : mClosed)
        if (glm::determinant(glm::mat3(scene.instances[i].model)) > 0.0f) // mirrored: fronts turn clockwise
            mCandidates.push_back(i);
}

size_t BackFaceCuller::setView(const CullView* view, bool framebufferYDown) {
    size_t culled = 0;
    if (mAny)
        for (uint32_t i : mCandidates) mCulled[i] = 0;
    mAny = false;
    if (!view) return 0;
    mFrontCcw = frontFaceCounterClockwise(view->viewProj, framebufferYDown);
    glm::vec3 eye;
    const glm::vec3* centre = projectionCentre(view->viewProj, eye) ? &eye : nullptr;
    for (uint32_t i : mCandidates) {
        const uint8_t cull = mayCullBackFaces(mBounds.bounds()[i], *view, centre) ? 1 : 0;
        mCulled[i] = cull;
        culled += cull;
    }
    mAny = culled > 0;
    return culled;
}

} // namespace sb
