#pragma once
// The six 90-degree perspective cameras of a cube shadow map at a point light (Gerasimov 2004,
// "Omnidirectional Shadow Mapping", GPU Gems ch. 12): one per face, in the face order and
// orientation of OpenGL cube maps (GL 4.5 core, section 8.13, table 8.19), so that face f of the image
// rendered with viewProjection(f) is exactly the face a lookup by direction selects. Shared by
// `cubemap` (its depth faces and their culling) and by the tests that check the faces against the GL's
// face selection.
#include <array>

#include <glm/glm.hpp>

namespace sb {

class CubeFaces {
public:
    static constexpr int kFaces = 6; ///< +X, -X, +Y, -Y, +Z, -Z (GL_TEXTURE_CUBE_MAP_POSITIVE_X + f)

    /// The faces of a light at `position` with depth range [nearZ, farZ] along each face's axis.
    CubeFaces(const glm::vec3& position, float nearZ, float farZ);

    /// World to face f's camera: looks along the face's axis with the face's "up" (-Y for the side
    /// faces, +Z for +Y, -Z for -Y), so that window x and y are the cube map's s and t of that face.
    const glm::mat4& view(int face) const { return mView[size_t(face)]; }
    /// The shared 90-degree, square perspective projection (OpenGL clip conventions).
    const glm::mat4& projection() const { return mProjection; }
    const glm::mat4& viewProjection(int face) const { return mViewProjection[size_t(face)]; }
    /// The six view-projections in face order (the layered pass's uniform array).
    const std::array<glm::mat4, kFaces>& viewProjections() const { return mViewProjection; }

    /// The face a direction from the light selects: the major axis, as the GL picks it (ties go to x,
    /// then y; the GL leaves ties to the implementation, and both faces hold the same texel there).
    static int faceOf(const glm::vec3& direction);
    /// Window depth in [0, 1] that face rendering stores for a point at major-axis distance `z`:
    /// the perspective depth (f + n) / (f - n) - 2fn / ((f - n) z), mapped from [-1, 1] to [0, 1].
    /// What the lookup compares with (shaders/shadowmap/cube_lighting.frag computes the same).
    static float windowDepth(float z, float nearZ, float farZ);

private:
    std::array<glm::mat4, kFaces> mView{};
    std::array<glm::mat4, kFaces> mViewProjection{};
    glm::mat4 mProjection{1.0f};
};

} // namespace sb
