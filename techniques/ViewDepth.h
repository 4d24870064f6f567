#pragma once
// The depth pre-pass of the camera's view, its API-neutral half. The harness renders nothing of the view
// before a technique's passes (the targets are bound and cleared, then execute), so a technique that needs
// the view's depth before its lighting pass draws it itself, once per frame, with the camera's matrices:
// `cascaded` fit=sdsm reduces it to the view's depth range (Lauritzen, Salvi and Lefohn 2011, Sample
// Distribution Shadow Maps, I3D; techniques/shadowmap/DepthRangeGL.h), and a lighting pass that marches
// the view's depth towards the light (contact shadows) reads it. One home for it on each API
// (techniques/gl/ViewDepthGL.h, techniques/vulkan/ViewDepthVulkan.h); what both share is here: the
// texture's format and size, what it draws, and how a window depth in it reads as a view depth.
//
// What is drawn: every instance (DrawSet::All: a non-receiver in front of a receiver hides its samples
// too), depth only, depth test LESS, cleared to 1 (the far plane: "no surface"), into a 32-bit float depth
// texture of the frame's size (GL_DEPTH_COMPONENT32F, VK_FORMAT_D32_SFLOAT: the same stored floats on both
// APIs, whose window depths mean the same: GL's default depth range, Vulkan's through the frame block's
// depthFromGl).
#include <cstdint>
#include <string>

#include <glm/glm.hpp>

namespace sb {

struct ViewDepth {
    /// The clear depth: a texel still holding it is covered by no surface.
    static constexpr float kClear = 1.0f;
    /// Bytes per texel (one 32-bit float).
    static constexpr uint64_t kTexelBytes = 4;

    /// The pre-pass texture's bytes at width x height (0 for a non-positive size).
    static uint64_t bytes(int width, int height);
    /// "WxH pixels x 4 B (<user>'s view depth pre-pass)": the resource estimate's words for it.
    static std::string describe(int width, int height, const std::string& user);

    /// The view depth (positive, along -z of the view) of window depth `window` in [0, 1] under `proj`
    /// (perspective: b / (z_ndc + a); orthographic: (b - z_ndc) / a; z_ndc = 2 window - 1, a = proj[2][2],
    /// b = proj[3][2]). Monotonic increasing in `window`: the min and max window depths of a set of
    /// samples are those of their view depths.
    static float viewDepth(float window, const glm::mat4& proj);
    /// Both ends of a window-depth interval (x, y) as view depths.
    static glm::vec2 viewDepths(glm::vec2 window, const glm::mat4& proj);
};

} // namespace sb
