#pragma once
// The bits of a GPU silhouette draw (VolumePlanner::Draw::gpuFlags): what ShadowVolumeMesh::buildVolume's
// VolumeRequest asks of the CPU, for the shaders that build the same volume on the device
// (shaders/volume/silhouette.glsl mirrors these values).
#include <cstdint>

namespace sb {

namespace GpuVolumeFlags {
constexpr uint32_t kLightCap = 1u;    ///< light-facing faces as they are (z-fail, not culled)
constexpr uint32_t kDarkCap = 2u;     ///< back faces at infinity (z-fail, not culled, not directional)
constexpr uint32_t kSides = 4u;       ///< silhouette sides (not culled)
constexpr uint32_t kDirectional = 8u; ///< sides as one triangle to the point at infinity (9.5.1)
} // namespace GpuVolumeFlags

} // namespace sb
