#pragma once
// The device side of `volume`'s GPU silhouette paths on Vulkan (extrusion=geometry and compute), the
// counterpart of GpuSilhouettesGL.h with the same shaders (shaders/volume/silhouette.geom and
// silhouette.comp under VULKAN) and the same inputs (SilhouetteInputs.h):
//  - the frame's volume triangle count, one uint in a host-visible buffer the geometry or compute shader
//    adds to: zeroed by the host when the frame is recorded (the harness waited for the previous frame's
//    fence) and read when the counters are asked for, after the frame's fence: the last frame's, exactly;
//  - extrusion=geometry: per caster mesh its triangles with adjacency in a vertex buffer, and set 1 of
//    the marking pipelines' layout (the count, seen by the geometry stage);
//  - extrusion=compute: every mesh's faces in one storage buffer and its doubled entries in another
//    (each mesh from its own base), a compute pipeline (vk/ComputePipeline.h), and per frame, before any
//    render pass, one dispatch per draw of every light, each writing the doubled entries of its caster's
//    volume's vertices into its own region of one buffer and their number into its
//    VkDrawIndirectCommand; the marking passes then draw each with vkCmdDrawIndirect, the vertex shader
//    fetching each vertex's entry (set 1; no indices: the order the device builds in changes no count).
#include <vector>

#include "techniques/volume/VolumePlanner.h"
#include "vk/ComputePipeline.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

struct VulkanCompileContext;
class VulkanContext;

class GpuSilhouettesVulkan {
public:
    /// Builds the inputs of `meshes` (by scene mesh index, null for a mesh no caster uses) for the
    /// geometry path, or with `compute` for the compute path (and its pipeline), and the count.
    void create(const VulkanCompileContext& ctx, const std::vector<const ShadowVolumeMesh*>& meshes,
                bool compute);
    void release();

    /// Set 1 of the marking pipelines: extrusion=geometry the count (binding 0, geometry stage),
    /// extrusion=compute the extracted entries and every mesh's doubled entries (bindings 0 and 1,
    /// vertex stage; volume/extrude.vert under PULLED).
    VkDescriptorSetLayout markLayout() const { return mMarkSets.layout(0); }
    VkDescriptorSet markSet() const { return mMarkSets.set(0); }
    /// extrusion=geometry: mesh `mesh`'s triangles with adjacency (SilhouetteInputs::adjacencyVertices).
    VkBuffer adjacency(size_t mesh) const { return mAdjacency[mesh].buffer(); }

    /// Zeroes the count for the frame being recorded (the previous frame has finished).
    void beginFrame();
    /// extrusion=compute: records, outside any render pass, every draw's volume (`draws`: the frame's,
    /// every light's) and the barrier that orders the vertices and counts before the draws read them.
    void extract(VkCommandBuffer cmd, const std::vector<VolumePlanner::Draw>& draws);
    /// extrusion=compute: draw `i` of the last extract(), with markSet() bound.
    void drawIndirect(VkCommandBuffer cmd, size_t i) const;
    /// After the frame's last pass, outside any render pass: the count's additions made visible to the
    /// host, which reads it after the frame's fence.
    void endFrame(VkCommandBuffer cmd) const;
    /// The last finished frame's volume triangles.
    double readTriangles() const;

private:
    /// Grows the compute path's output and command buffers to hold `vertices` and `commands` words
    /// and points the sets' bindings at them.
    void reserve(size_t vertices, size_t commands);

    VulkanContext* mContext = nullptr;
    bool mCompute = false;
    VulkanBuffer mCount;
    DescriptorSets mSets;     ///< compute: count, faces, output, commands
    DescriptorSets mMarkSets; ///< set 1 of the marking pipelines (markLayout())
    std::vector<VulkanBuffer> mAdjacency;
    // extrusion=compute
    VulkanBuffer mFaces, mDoubled, mVertices, mCommands;
    std::vector<uint32_t> mFaceBase, mFaceCount, mVertexBase, mVertexCount; ///< per scene mesh
    ComputePipeline mPipeline;
};

} // namespace sb
