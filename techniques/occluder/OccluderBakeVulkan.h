#pragma once
// The occluder-texture bake on Vulkan: what OccluderTextures::bake does on GL (techniques/occluder/
// OccluderTextures.h), with the same shaders (shaders/occluder/bake.vert, bake.frag; their `#ifdef
// VULKAN` block takes the plane as push constants) into an R8 image with a stencil attachment, submitted
// once and read back: the silhouette of the plane's parts, black on white; the cross-section (every
// triangle on the normal's side of the plane counted in the stencil, +1 one facing, -1 the other, then
// a full-screen fill where the count is not 0); then the same dilation on the CPU. Clip space: u and v
// map to x and y in [-1, 1] on both APIs and Vulkan's row 0 is at y = -1, so the rows read back are
// GL's (row 0 = v near 0) with no flip; the facing only changes the count's sign, which the non-zero
// test ignores. Needs shaderClipDistance (refused, exit 3, on a device without it).
#include <cstdint>
#include <vector>

#include "scenes/Mesh.h"
#include "scenes/ShadowPlane.h"
#include "techniques/occluder/OccluderTexels.h"
#include "vk/ShaderModuleCache.h"
#include "vk/VulkanContext.h"

namespace sb {

struct OccluderBakeVulkan {
    /// The texels of `plane`'s occluder texture from `mesh` at options.resolution (row 0 = v near 0),
    /// dilated as `options` asks. Throws sb::Error naming the plane for an invalid plane or options or
    /// an unknown part, ExitCode::Unsupported without shaderClipDistance.
    static std::vector<uint8_t> bake(VulkanContext& context, ShaderModuleCache& shaders, const Mesh& mesh,
                                     const ShadowPlane& plane, const OccluderBakeOptions& options);
};

} // namespace sb
