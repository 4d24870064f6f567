#pragma once
// `cubemap` on Vulkan: CubeMapGL's two passes with the same declaration, properties, light
// classification (OmniLightSet), cube faces (CubeFaces), caster culling (OmniCulling, InstanceCulling)
// and shaders (common/depth.vert, cube_depth.vert + cube_depth.geom, common/scene.vert,
// shadowmap/cube_lighting.frag with omni_lighting.glsl, their `#ifdef VULKAN` blocks), recorded into
// the frame's command buffer.
//
// Maps: the point lights' cubes in a cube-compatible depth image viewed as a cube array (layer-face
// 6 * cube + face; X8_D24 as ShadowMapVulkan's maps, so glPolygonOffset's factors mean the same bias)
// and the spot and directional lights' flat maps in a 2D depth array. A kind a scene does not have
// gets a 1 x 1 stand-in, so the lighting set is always complete (its lookups are compiled out).
//
// Depth pass: flat maps and six-pass faces each a render pass of their own over one layer (it clears
// that layer, as DepthLayers::beginLayer does), the light's or face's view-projection in a slot of a
// dynamic uniform buffer (common/depth.vert's LightPass). Layered (`layered` = true, where the
// device has geometry shaders): one render pass over every layer-face of the cube array (clearing all,
// as DepthLayers::beginLayered), per cube its slot (cube_depth.geom's CubePass: the six face matrices
// and the cube's first layer) and the casters within its range. Matrices are GL's times
// VulkanFrameBlock::depthFromGl() (z to [0, w], no flip: the cube faces' s and t run as on GL, and the
// lookup compares with GL's window depth). Lighting pass: one uniform block (CubeMapBlock: shadow
// matrices, map kind and layer, depth range per light) and both maps through a depth-compare sampler
// with bilinear filtering (Vulkan's cube sampling is always seamless, GL_TEXTURE_CUBE_MAP_SEAMLESS).
//
// The layered pass's geometry stage culls per triangle against GL's clip volume (z in [-w, w]) with
// Vulkan's matrices: a looser test behind the near plane only, which the rasteriser's clipping then
// does; the images are the same.
#include <vector>

#include <glm/glm.hpp>

#include "scenes/InstanceCulling.h"
#include "techniques/shadowmap/CubeFaces.h"
#include "techniques/shadowmap/CubeMap.h"
#include "techniques/shadowmap/OmniCulling.h"
#include "techniques/shadowmap/OmniLightSet.h"
#include "techniques/vulkan/ContactShadowsVulkan.h"
#include "techniques/vulkan/LitPipelines.h"
#include "techniques/vulkan/VulkanDepthMapSet.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class CubeMapVulkan final : public VulkanTechnique {
public:
    CubeMapVulkan();
    ~CubeMapVulkan() override;
    void setScene(const Scene& scene) override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mLights; }

private:
    ContactShadowsVulkan mContact; ///< contact=on: the view depth pre-pass and its set 2
    void release();
    void createMaps(VulkanContext& context);
    void createDescriptors(VulkanContext& context);
    void writeBlocks();
    void beginDepthPass(VulkanFrameContext& ctx, const VulkanDepthMapSet& maps, size_t framebuffer,
                        VkPipeline pipeline);
    void bindSlot(VulkanFrameContext& ctx, uint32_t slot);
    void renderDepth(VulkanFrameContext& ctx);
    void renderFlatMaps(VulkanFrameContext& ctx);
    void renderCubesLayered(VulkanFrameContext& ctx);
    void renderCubesSixPass(VulkanFrameContext& ctx);
    /// Slots of the depth passes' uniform buffer: flat maps, then six-pass faces, then layered cubes.
    uint32_t flatSlot(int index) const { return uint32_t(index); }
    uint32_t faceSlot(size_t cube, int face) const {
        return uint32_t(mFlatCount + CubeFaces::kFaces * int(cube) + face);
    }
    uint32_t layeredSlot(size_t cube) const {
        return uint32_t(mFlatCount + CubeFaces::kFaces * mCubeCount + int(cube));
    }

    VkDevice mDevice = VK_NULL_HANDLE;
    OmniLightSet mLights;
    std::vector<CubeMap::Cube> mCubeLights; ///< per point light with a map, in cube order
    InstanceCulling mCulling;
    OmniCulling mOmniCulling;
    std::vector<uint8_t> mKeep, mRange;
    bool mLayered = true; ///< what compile() chose (the property, where the device has geometry shaders)
    int mSize = 0, mCubeCount = 0, mFlatCount = 0; ///< as compiled (the maps' sizes)
    size_t mCulled = 0;
    int mFacesRendered = 0;

    /// The cubes: a framebuffer per layer-face (six-pass), or one over them all (layered).
    VulkanDepthMapSet mCubes;
    /// The flat maps, a framebuffer per layer, and every depth pass's CubePass-sized slots (LightPass
    /// reads the first matrix).
    VulkanDepthMapSet mFlat;
    VulkanBuffer mLightingBlock;                             ///< CubeMapBlock
    static constexpr size_t kDepthSet = 0, kLightingSet = 1; ///< in mSets
    DescriptorSets mSets;
    VkPipelineLayout mDepthLayout = VK_NULL_HANDLE, mLightingLayout = VK_NULL_HANDLE;
    VkPipeline mFaceDepthPipeline = VK_NULL_HANDLE, mLayeredDepthPipeline = VK_NULL_HANDLE;
    LitPipelines mLighting; ///< the lighting pass (non-receivers apart where they can be)
    Counters mCounters;
};

} // namespace sb
