#pragma once
// How much of a light's map its casters cover, counted on the CPU from the geometry (the same count on
// GL and Vulkan, and in every run: no readback, no driver in it): the light fit (scenes/LightFit.h)
// decides it, and with it both the shadow's resolution and the depth pass's fill.
#include <cstdint>

#include <glm/glm.hpp>

#include "scenes/Scene.h"

namespace sb {

struct MapCoverage {
    uint64_t covered = 0; ///< texels whose centre some caster triangle covers
    uint64_t texels = 0;  ///< texels of the maps counted

    /// covered / texels in percent (0 for no texels).
    double percent() const { return texels ? 100.0 * double(covered) / double(texels) : 0.0; }
    MapCoverage& operator+=(const MapCoverage& o) {
        covered += o.covered;
        texels += o.texels;
        return *this;
    }

    /// The texels of a `resolution` x `resolution` map rendered with `lightViewProj` (OpenGL clip
    /// conventions) whose centre lies inside a triangle of a casting instance of `scene`, as a
    /// rasteriser samples them: every caster, both faces, clipped to the near plane (and so to w > 0),
    /// texel (i, j) covered when its centre (i + 0.5, j + 0.5) in window coordinates lies inside or on
    /// a triangle. A centre exactly on a silhouette edge is counted where GL's top-left rule might not:
    /// a measure-zero difference. Depth beyond the far plane is not clipped: the fits put every
    /// instance inside their depth range. Untimed work: a byte per texel and one scan line per row a
    /// triangle spans (about 10 ms for a 7k-triangle model in a 2048^2 map).
    static MapCoverage count(const Scene& scene, const glm::mat4& lightViewProj, int resolution);
};

} // namespace sb
