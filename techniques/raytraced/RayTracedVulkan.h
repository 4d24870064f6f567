#pragma once
// `raytraced` on Vulkan (techniques/vulkan/VulkanTechnique.h; the declaration is
// techniques/raytraced/RayTraced.h). Its only form: GL has no ray queries.
//
// Passes of one frame:
//   structures  a scene whose casters move: the top-level acceleration structure rebuilt over their new
//               model matrices, recorded into the frame's command buffer (AccelerationStructures.h);
//               skipped, with its reason, where nothing moved: the structures built before the first
//               frame hold
//   lighting    the scene drawn once through common/scene.vert and raytraced/lighting.frag, which
//               traces each fragment's shadow rays with rayQueryEXT (terminate on first hit, opaque)
//               and shades as common/lit.frag does, each light's term times its visibility
// Set 1: binding 0 the top level, binding 1 the frame's state (a host-visible buffer: the ray counter the
// frame's recording zeroes and the fragments add to, one atomic add per fragment that traced; the frame's
// index and the frames the history holds), binding 2 under temporal=true the history (RGBA32F, two
// layers of the frame's size, general layout: a fragment reads the last frame's layer and writes this
// frame's). A pixel's history is written by each fragment that passes the early depth test there, the
// visible surface's last in primitive order; lavapipe shades a pixel's fragments in that order (a device
// that does not would need a depth pre-pass or fragment-shader interlock for the same guarantee).
//
// Self-intersection: a ray leaves the surface at the interpolated position moved along the geometric
// normal of the side the camera sees by max(1e-4, 32 sum_i |n_i| spacing(p_i)), the float spacing of each
// coordinate weighed by the normal's share of it (Waechter and Binder's principle, "A Fast and Robust
// Method for Avoiding Self-Intersection", Ray Tracing Gems, ch. 6, as one distance along the normal; the
// Embree reference's rule): shaders/raytraced/rays.glsl, offsetRayOrigin, says why and what it measured.
// The geometric normal is the plane of the position's screen-space derivatives, so the offset is the
// triangle's, not the interpolated shading normal's. Rays to point and spot lights stop 2^-12 of the
// distance short of the light, as the Embree reference's do.
//
// The device needs VK_KHR_acceleration_structure and VK_KHR_ray_query (the declaration) with the features
// VulkanContext enables for them (VulkanContext::rayQuery), and fragmentStoresAndAtomics for the counter.
//
// Counters: RayTraced::counters (structures_built, structure_bytes, rays_traced of the last frame) and
// RayTraced::buildTimes (bottom_levels_build_ms, top_level_build_ms: the builds before the first frame).
//
// mode=guided (techniques/raytraced/GuidedRays.h): a pass "depth" between the two renders a depth map per
// light (GuideMapsVulkan), which the lighting pass reads through set 2 to trace only the unsure rays;
// GuidedRays::counters follow raytraced's.
#include <memory>

#include "techniques/raytraced/AccelerationStructures.h"
#include "techniques/raytraced/GuideMapsVulkan.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

class RayTracedVulkan final : public VulkanTechnique {
public:
    RayTracedVulkan();
    ~RayTracedVulkan() override;
    /// The passes and effects of the mode the properties chose (RayTraced::passes, RayTraced::effects:
    /// soft_shadows in `soft` only).
    void propertiesApplied() override;
    /// The declaration's extensions, then the features VulkanContext enables with them and
    /// fragmentStoresAndAtomics: one line naming every one missing.
    std::string checkCapabilities(const VulkanContext& context) const override;
    /// Forgets the structures of a previous scene; compile() builds this one's.
    void setScene(const Scene& scene) override;
    /// Moving casters: their matrices go into the instance buffer now, and the frame rebuilds the top
    /// level. Lights and the camera need nothing: the shader reads them from the frame block (guided
    /// refits its maps to whatever moved). Under temporal=true any change restarts the history.
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override;

private:
    /// mode=guided: the pass "depth" (skipped where the scene needs no shadow), and the count zeroed.
    void recordGuide(VulkanFrameContext& ctx);
    /// temporal=true: the history image at the targets' size, in the general layout, bound at set 1
    /// binding 2.
    void createHistory(const VulkanCompileContext& ctx);
    /// temporal=true, before the lighting pass: the frame's index and history count into the frame state
    /// (the count restarts under a new camera), and the barrier after the last frame's history writes.
    void recordHistoryFrame(VulkanFrameContext& ctx);

    VkDevice mDevice = VK_NULL_HANDLE;
    std::unique_ptr<AccelerationStructures> mStructures;
    bool mRebuild = false;      ///< the casters moved since the last frame
    uint32_t mBuiltInFrame = 0; ///< structures built in the last frame
    /// The frame's state, host-visible: the ray counter, the frame's index, the frames the history holds
    /// (lighting.frag's FrameState).
    VulkanBuffer mFrameState;
    /// temporal=true: the history, the frame counter, the frames accumulated since the last restart and
    /// the camera they were accumulated under (a new one restarts the history).
    bool mTemporal = false;
    VulkanImage mHistory;
    uint32_t mFrame = 0, mHistoryFrames = 0;
    glm::mat4 mHistoryViewProj{0.0f};
    DescriptorSets mSets;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    ScenePipeline mPipeline;
    bool mGuided = false; ///< mode=guided
    GuideMapsVulkan mGuide;
};

} // namespace sb
