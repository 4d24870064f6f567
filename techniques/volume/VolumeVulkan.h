#pragma once
// `volume` on Vulkan: VolumeGL's program (GPU Gems ch. 9, Listing 9-1) with the same declaration,
// properties and CPU logic (VolumePlanner: casters, light regions, per-light draw lists and statistics)
// and the same shaders (common/scene.vert, volume/ambient.frag, volume/light.frag, volume/extrude.vert,
// volume/stencil.frag and their `#ifdef VULKAN` blocks), recorded into the frame's command buffer.
//
// Passes. ambient: depth written, ambient colour, visibility 0 inside each light's region and 1 outside
// (the regions in a uniform block, set 1, GL's bottom-up rectangles). Per light whose region is on
// screen: mark (the stencil cleared inside the scissor rectangle with vkCmdClearAttachments, then every
// caster's volume counted with two-sided wrapping stencil operations, z-fail casters first; no colour,
// depth LESS without writes, no culling) and lighting (depth EQUAL, stencil EQUAL 0, colour ONE + ONE,
// visibility MAX). A light that casts no shadow skips mark and lights without the stencil test; with
// non-receivers in the scene, receivers are lit with the stencil test and non-receivers without, as on GL.
//
// Geometry. extrusion=cpu: each caster mesh's doubled vertex buffer (device-local) and one host-visible
// index stream per frame that holds every light's volumes (the frame's command buffer draws them all;
// the harness waits for each frame's fence, so the stream is rewritten in place). extrusion=vertex: the
// McGuire-Hughes mesh (positions with face planes, caps then sides) in device-local buffers. Per draw the
// push constants (common/push.glsl) carry the model matrix, the object-space light (vec) and the finite
// extrusion length (ints.y, as float bits).
//
// far=infinite draws every pass with the camera's projection at infinity (a frame-block slot of its own);
// far=depth_clamp needs the depthClamp feature (ExitCode::Unsupported without it). depth_bounds is GL's
// GL_EXT_depth_bounds_test: the mark and lighting pipelines test depth bounds, set per light with
// vkCmdSetDepthBounds; a device without the depthBounds feature refuses it (ExitCode::Unsupported,
// naming the device), as GL refuses it where the extension is missing.
// Counters: GL's. stencil_samples_passed is an occlusion query with VK_QUERY_CONTROL_PRECISE_BIT around
// each light's marking draws, as GL_SAMPLES_PASSED is on GL, in two slots read two frames late as on GL
// (VolumeGL::readStencilQuery); on a device without occlusionQueryPrecise a query only promises zero
// or non-zero, so the counter is left out rather than reported with another meaning.
#include <array>
#include <memory>
#include <vector>

#include "techniques/volume/GpuSilhouettesVulkan.h"
#include "techniques/volume/ShadowVolumeMesh.h"
#include "techniques/volume/VolumePlanner.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class VolumeVulkan final : public VulkanTechnique {
public:
    VolumeVulkan();
    ~VolumeVulkan() override;
    void setScene(const Scene& scene) override;
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    /// The GPU silhouette paths' volume_triangles is the device's count of the last frame.
    Counters counters() const override;
    /// extrusion=mesh needs VK_EXT_mesh_shader: one line naming it, the device and the driver entry
    /// that offers it (Mesa 25.0.7's lavapipe, --driver mesa-25.0.7).
    std::string checkCapabilities(const VulkanContext& context) const override;

private:
    struct MeshGpu {
        std::unique_ptr<ShadowVolumeMesh> mesh;   ///< null for meshes no caster uses
        std::unique_ptr<ExtrusionMesh> extrusion; ///< extrusion=vertex, until compile() uploads it
        VulkanBuffer doubled;                     ///< (x, y, z, 1) then (x, y, z, 0)
        VulkanBuffer extrusionVertices, extrusionIndices;
        uint32_t capIndices = 0, sideIndices = 0;
    };
    /// A light's draws in mDraws (first into the frame's stream already offset).
    struct LightDraws {
        size_t begin = 0, end = 0;
    };

    void release();
    void uploadMeshes(VulkanContext& context);
    void createDescriptors(VulkanContext& context);
    void buildPipelines(const VulkanCompileContext& ctx);
    /// extrusion=geometry and compute: refuses a device without what they need (ExitCode::Unsupported),
    /// then builds their inputs and, for geometry, the marking pipelines' layout.
    void createSilhouettes(const VulkanCompileContext& ctx);
    /// The marking pass's vertex input: the doubled buffer (CPU, compute), the McGuire-Hughes mesh
    /// (vertex) or the triangles with adjacency (geometry).
    void describeVolumeInput(GraphicsPipelineDesc& d) const;
    /// Per light the planner's draws, the CPU path's indices gathered into one frame stream.
    void collectFrame(const VulkanFrameContext& ctx, const VolumePlanner::View& view, int lights,
                      VolumePlanner::FrameStats& stats);
    void writeAmbientBlock(int lights, int height);
    VkRect2D scissorOf(const VolumePlanner::LightRegion& region, int width, int height) const;
    void renderAmbient(VulkanFrameContext& ctx, uint32_t frame);
    void markShadows(VulkanFrameContext& ctx, uint32_t frame, int light, const VkRect2D& scissor);
    void renderLight(VulkanFrameContext& ctx, uint32_t frame, int light, const VkRect2D& scissor);
    /// The light's depth bounds (all of [0, 1] where its region has none), with depth_bounds on.
    void setDepthBounds(VkCommandBuffer cmd, int light) const;
    /// Reads the slot of the stencil queries issued two frames ago and resets it for this frame
    /// (outside any render pass).
    void readStencilQueries(VkCommandBuffer cmd);

    VolumePlanner mPlanner;
    const Scene* mScene = nullptr;
    VulkanContext* mContext = nullptr;
    VkDevice mDevice = VK_NULL_HANDLE;
    std::vector<MeshGpu> mMeshes;
    bool mUploaded = false;

    VulkanBuffer mStream; ///< host-visible index stream of the CPU path, grown geometrically
    std::vector<uint32_t> mFrameStream;
    std::vector<VolumePlanner::Draw> mDraws;
    std::array<LightDraws, kMaxLights> mLightDraws{};
    std::array<VolumePlanner::LightRegion, kMaxLights> mRegions{};

    VulkanBuffer mAmbientBlock;                ///< ambient.frag's VolumeAmbient
    DescriptorSets mSets;                      ///< set 1: ambient.frag's block
    VkPipelineLayout mLayout = VK_NULL_HANDLE; ///< frame block, VolumeAmbient, push constants
    ScenePipeline mAmbient;
    ScenePipeline mLight[2];   ///< [stencil test]
    ScenePipeline mMark[2][2]; ///< [finite][zfail]
    GpuSilhouettesVulkan mSilhouettes;
    /// The GPU silhouette paths' marking pipelines: set 1 GpuSilhouettesVulkan::markLayout(), push
    /// constants also in the geometry stage for extrusion=geometry (mLayout for the others).
    VkPipelineLayout mMarkLayout = VK_NULL_HANDLE;
    VkShaderStageFlags mMarkPushStages = 0;
    bool mDepthBounds = false; ///< depth_bounds on a device with the depthBounds feature

    /// Occlusion queries of the marking passes: [slot * kMaxLights + light], two slots (null without
    /// occlusionQueryPrecise).
    VkQueryPool mSamples = VK_NULL_HANDLE;
    std::array<int, 2> mQueriesIssued{}; ///< per slot, the lights whose queries were issued
    uint64_t mQueryFrame = 0;
    double mStencilSamples = 0;
    Counters mCounters;
};

} // namespace sb
