#pragma once
// A shadow plane of the occluder-texture technique (Coleman, "Fast Self-Shadowing Using Occluder
// Textures", sections 4.1 and 4.3): a rectangle in a mesh's object space that stands for a flat
// shadow-casting part (wings, a tail fin), with an occluder texture holding the part's silhouette
// (black = occluder) on it.
//
// A receiving point p0 is shadowed by the plane when the ray towards the light, p(s) = p0 + s L
// (equation 2), meets the plane (equations 3-6)
//     s_I = n . (o - p0) / (n . L)
// on the light's side of p0 (s_I > 0: the appendix's false-shadow test) inside a black texel. The
// texture coordinate of the hit (equation 8) is taken, as the appendix's shaders do, from the texture's
// corner o:
//     uv = (right . (p(s_I) - o) / width, up . (p(s_I) - o) / height)
// (equation 8 writes o - p(s_I): the same with right and up pointing the other way).
//
// This is the CPU form of what shaders/occluder/ computes per vertex; the technique uses it for the
// per-instance light and the tests use it as the independent answer.
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace sb {

/// Where a receiving point projects onto a shadow plane along the light.
struct ShadowCoord {
    glm::vec2 uv{0.0f}; ///< texture coordinates, unclamped (the fragment stage clamps, Appendix B)
    /// The ray parameter s_I of equation 6: > 0 when the plane lies between the point and the light
    /// (only then may it shadow), <= 0 for a plane behind the point (a false shadow if used).
    float s = 0.0f;
};

struct ShadowPlane {
    std::string name;          ///< e.g. "wings", "fin_left"
    glm::vec3 origin{0.0f};    ///< the texture's (0, 0) corner, object space
    glm::vec3 normal{0, 0, 1}; ///< unit
    glm::vec3 right{1, 0, 0};  ///< unit, in the plane: texture u
    glm::vec3 up{0, 1, 0};     ///< unit, in the plane: texture v
    float width = 1.0f, height = 1.0f;
    /// Solid occluder (the thesis's teapot handle): every uv in [0, 1]^2 is shadow, no texture fetch.
    bool solid = false;
    /// Mesh parts whose geometry the plane stands for: the automatic occluder texture renders these
    /// (all of the mesh when empty).
    std::vector<std::string> parts;
    /// Mesh parts that receive the plane's shadow (all of the mesh when empty): the thesis's receiver
    /// sections (section 5: "the front of the teapot can only receive shadows from the spout. The back
    /// of the teapot can only receive shadows from the handle. The top of the teapot can only receive
    /// shadows from the top", so the teapot was cut into three objects, each considering only its own
    /// planes). A vertex shared by several parts receives the plane only if all of them do.
    std::vector<std::string> receivers;
    /// Where the occluder texture comes from when not solid: "auto" bakes it from `parts` at the
    /// technique's resolution (the thesis's future work); anything else is a PNG file read with
    /// core/PngFile (the scene loader makes it absolute, relative to the scene file). Image convention:
    /// dark = occluder, the image's bottom-left corner is uv (0, 0).
    std::string texture = "auto";
    /// Non-empty: use the texture of the named plane of the same mesh (the thesis's two tail fins
    /// share one); the two planes' frames must map the shared silhouette alike.
    std::string textureOf;
    /// Bake the plane's cross-section with the solid only, not the parts' orthographic silhouette: for
    /// a plane standing for the part of a solid it cuts (the teapot knob's widest ring, whose lid dome
    /// below would fill the silhouette).
    bool sectionOnly = false;

    /// Below this |n . L| (unit vectors: the cosine between the light and the plane, ~6e-5 degrees
    /// from parallel) the denominator of equation 6 is held at +-kMinCosine: s_I stays finite (huge),
    /// the coordinates clamp to the border, and n . L = 0 exactly gives no NaN (0 / 0).
    static constexpr float kMinCosine = 1e-6f;

    /// Equations 6 and 8 for a point p0 and a unit vector L towards the light (object space).
    ShadowCoord project(const glm::vec3& p0, const glm::vec3& towardLight) const;
    /// For a directional light (unit `towardLight`, object space) u, v and s_I are affine in p0: the
    /// rows (u, v, s) of the 3x4 "texture matrix" with (u, v, s_I) = rows . (p0, 1), the projection the
    /// thesis names as future work. Same guard as project().
    std::array<glm::vec4, 3> textureMatrix(const glm::vec3& towardLight) const;
    /// True when the plane shadows p0 for a solid occluder: s_I > 0 and uv in [0, 1]^2.
    bool solidShadows(const glm::vec3& p0, const glm::vec3& towardLight) const;

    /// Throws sb::Error naming `where` when the frame is not orthonormal (1e-3) or a size is not
    /// positive and finite.
    void validate(const std::string& where) const;
};

} // namespace sb
