#pragma once
// The view- and light-dependent geometry of stencil shadow volumes (GPU Gems ch. 9), free of GL so
// it is unit-tested against hand-computed answers:
//  - the infinite perspective projection of Listing 9-2, with the epsilon guard of Everitt and Kilgard
//    (2002) that keeps points at infinity inside the clip volume despite rounding;
//  - the occlusion pyramid of section 9.5.4 (z-pass is safe for a caster whose bounds miss it);
//  - view-frustum culling of light cap, dark cap and sides (section 9.5.3) with homogeneous points;
//  - light range culling of casters (section 9.5.2);
//  - the scissor rectangle of a light's range (section 9.6.2);
//  - the depth bounds of a light's range (section 9.6.3).
#include <array>
#include <optional>

#include <glm/glm.hpp>

#include "scenes/Mesh.h"
#include "scenes/Scene.h"

namespace sb {

/// A plane n.x + d >= 0 is inside. Applied to homogeneous points as dot(vec4(n, d), p).
using Plane = glm::vec4;

struct VolumeGeometry {
    /// Listing 9-2 with far at infinity, as a glm (column-major, right-handed, clip z in [-w, w])
    /// matrix: the limit of glm::perspective as far -> infinity, with z row scaled by (1 - epsilon)
    /// (c = epsilon - 1, d = (epsilon - 2) * near) so w = 0 points land at z/w = 1 - epsilon.
    static glm::mat4 infinitePerspective(float fovYRadians, float aspect, float nearZ, float epsilon = 1e-6f);

    /// The 4 side planes and the near plane of the view frustum of `viewProj` (the far plane is left
    /// out: with an infinite projection there is none), normals pointing inside, in world space.
    static std::array<Plane, 5> frustumPlanes(const glm::mat4& viewProj);
    /// True if every homogeneous point is strictly outside one of the planes (conservative cull).
    static bool outsideAny(const std::array<Plane, 5>& planes, const glm::vec4* points, int count);

    /// The 8 corners of a world-space box, w = 1.
    static std::array<glm::vec4, 8> corners(const Aabb& box);
    /// The corners sent to infinity away from the light (x * L.w - L.xyz, 0) (section 9.5.3).
    static std::array<glm::vec4, 8> cornersAtInfinity(const Aabb& box, const glm::vec4& light);

    /// Section 9.5.3, per caster (world-space bounds, world-space light as in VolumeRequest::light).
    struct CapCull {
        bool lightCap = false; ///< true = culled
        bool darkCap = false;
        bool sides = false;
    };
    static CapCull cullVolume(const std::array<Plane, 5>& frustum, const Aabb& casterBounds,
                              const glm::vec4& light);

    /// Section 9.5.4: may the caster's volume cover part of the near-plane rectangle? The occlusion
    /// pyramid is the convex hull of the light (a point, or a direction for w = 0) and the near-plane
    /// rectangle (its 4 world-space corners, in order around the rectangle). Conservative: true when
    /// unsure (degenerate pyramid, light in the near plane). False means z-pass is exact for it.
    static bool mayShadowViewport(const std::array<glm::vec3, 4>& nearRect, const glm::vec4& light,
                                  const Aabb& casterBounds);
    /// The 4 world-space corners of the near-plane rectangle of `viewProj` (inverse of NDC corners at
    /// z = -1), in order around the rectangle.
    static std::array<glm::vec3, 4> nearRectangle(const glm::mat4& viewProj);

    /// Section 9.5.2: false when a point/spot light of finite range cannot reach the box (box outside
    /// the range sphere; for spot lights also outside the cone's bounding cone). Directional lights and
    /// range 0 reach everything.
    static bool lightReaches(const Light& light, const Aabb& worldBounds);

    /// Past section 9.6.1 (finite volumes, there for ranged point lights): a directional light's volume
    /// need only reach past the scene. The extrusion length D along the unit direction `dir` (the
    /// way the light travels) such that extruding the caster by D keeps every point of its infinite
    /// volume that lies in `scene`: with X in the caster's box and P = X + t dir inside the convex
    /// scene box, t is at most the ray's exit distance min_i (bound_i - X_i) / dir_i, and each term is
    /// affine in X, so min_i max_corners bounds it. The dark cap then lies beyond every receiver.
    /// `margin` (relative, plus 1e-4 of the scene's diagonal) keeps that cap off receivers lying
    /// exactly on the box. 0 if dir is zero.
    static float boundedExtrusion(const Aabb& scene, const Aabb& caster, const glm::vec3& dir,
                                  float margin = 0.01f);

    /// Section 9.6.2: pixel rectangle {x, y, width, height} covering the light's range cube (centre
    /// light.position, half extent light.range) clipped to the near plane and projected with
    /// `viewProj` onto a viewport of `width` x `height`; nullopt when the cube is entirely outside the
    /// view (nothing to light) and the full viewport when the light has no range.
    static std::optional<glm::ivec4> scissorRect(const Light& light, const glm::mat4& viewProj, int width,
                                                 int height);
    /// Section 9.6.3: window-space depth range [min, max] in [0, 1] of the light's range sphere seen
    /// through `proj` * `view` (the chapter's z bounds, from the box's corners), nullopt without range.
    static std::optional<glm::vec2> depthBounds(const Light& light, const glm::mat4& view,
                                                const glm::mat4& proj);
};

} // namespace sb
