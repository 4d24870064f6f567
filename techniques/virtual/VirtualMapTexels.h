#pragma once
// Where `virtual`'s lighting pass (shaders/virtual/lighting.frag) looks a world point up
// (techniques/MapTexels.h): in the mapped light's virtual map at the level the pass picks for the
// sample, floor(log2 of level 0's texels per screen pixel + lod_bias) clamped to the levels
// (shaders/virtual/page_table.glsl's pageLod and pageLevel). The shader takes texels per pixel from the
// screen derivatives of the map position; this class takes them from the receiver's plane at the
// sample (ShadedPoint::normal) under the frame's camera: the map position's derivatives along the
// plane through the inverse of the screen's, the longer of the columns for screen x and y. Both forms
// hold one and set it each frame.
#include <cstddef>
#include <optional>

#include <glm/glm.hpp>

#include "techniques/MapTexels.h"
#include "techniques/virtual/PageGeometry.h"

namespace sb {

class VirtualMapTexels final : public MapTexels {
public:
    /// Light `light`'s map under `lightViewProj` (world -> map clip); a negative light: none is mapped.
    void setMap(int light, const glm::mat4& lightViewProj, const PageGeometry& geometry, float lodBias);
    /// The frame's camera (world -> clip) and its image in pixels.
    void setCamera(const glm::mat4& viewProj, glm::ivec2 size);

    std::optional<MapPoint> texel(size_t light, const ShadedPoint& at, const glm::dvec3& q) const override;
    /// The level the lighting pass reads for `at` (0 where `at` has no normal or is seen edge-on).
    int level(const ShadedPoint& at) const;

private:
    int mLight = -1;
    glm::mat4 mShadow{1.0f}; ///< bias * viewProj: world -> [0, 1] map coordinates
    PageGeometry mGeometry{128, 128, 1};
    float mLodBias = 0.0f;
    glm::mat4 mCamera{1.0f};
    glm::ivec2 mSize{1};
};

} // namespace sb
