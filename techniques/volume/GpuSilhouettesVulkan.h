#pragma once
// The device side of `volume`'s GPU silhouette paths on Vulkan (extrusion=geometry, compute and mesh),
// the counterpart of GpuSilhouettesGL.h with the same shaders (shaders/volume/silhouette.geom and
// silhouette.comp under VULKAN; silhouette.mesh is Vulkan's alone) and the same inputs
// (SilhouetteInputs.h):
//  - the frame's volume triangle count, one uint in a host-visible buffer the geometry, compute or mesh
//    shader adds to: zeroed by the host when the frame is recorded (the harness waited for the previous
//    frame's fence) and read when the counters are asked for, after the frame's fence: the last frame's,
//    exactly;
//  - extrusion=geometry: per caster mesh its triangles with adjacency in a vertex buffer, and set 1 of
//    the marking pipelines' layout (the count, seen by the geometry stage);
//  - extrusion=compute: every mesh's faces in one storage buffer and its doubled entries in another
//    (each mesh from its own base), a compute pipeline (vk/ComputePipeline.h), and per frame, before any
//    render pass, one dispatch per draw of every light, each writing the doubled entries of its caster's
//    volume's vertices into its own region of one buffer and their number into its
//    VkDrawIndirectCommand; the marking passes then draw each with vkCmdDrawIndirect, the vertex shader
//    fetching each vertex's entry (set 1; no indices: the order the device builds in changes no count);
//  - extrusion=mesh (VK_EXT_mesh_shader): the compute path's faces and doubled entries and a table of
//    each scene mesh's bases, all in set 1 of the marking pipelines with the count (mesh stage); each
//    draw is vkCmdDrawMeshTasksEXT with one workgroup per kFacesPerGroup faces of its caster's mesh
//    (volume/silhouette.mesh builds and rasterises the volume in one step; nothing is extracted).
#include <string>
#include <vector>

#include "shading/Defines.h"
#include "techniques/volume/VolumePlanner.h"
#include "vk/ComputePipeline.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"

namespace sb {

struct VulkanCompileContext;
class VulkanContext;

class GpuSilhouettesVulkan {
public:
    /// Faces per workgroup of volume/silhouette.mesh: at most 7 vertices and 7 triangles each, so 56 of
    /// each per workgroup (lavapipe of Mesa 25.0.7 offers 256). 8 (one invocation per lane of
    /// llvmpipe's 256-bit vectors) was the fastest tried there, side by side on aircraft x40 at 160x160:
    /// wall time 56 ms at 8 faces, 64 at 16, 71 at 4, 76 at 32 (one run each, noisy shared machine).
    static constexpr uint32_t kFacesPerGroup = 8;
    /// The defines volume/silhouette.mesh is built with (FACES_PER_GROUP).
    static Defines meshDefines();
    /// What the mesh path needs of `context` that it lacks (the meshShader feature, its output and
    /// workgroup limits for kFacesPerGroup and `maxFaces` faces in one draw); "" when it has all.
    static std::string meshShaderProblem(const VulkanContext& context, size_t maxFaces);

    /// Builds the inputs of `meshes` (by scene mesh index, null for a mesh no caster uses) for
    /// `extrusion` (Geometry, Compute with its pipeline, or Mesh), and the count.
    void create(const VulkanCompileContext& ctx, const std::vector<const ShadowVolumeMesh*>& meshes,
                VolumePlanner::Extrusion extrusion);
    void release();

    /// Set 1 of the marking pipelines: extrusion=geometry the count (binding 0, geometry stage),
    /// extrusion=compute the extracted entries and every mesh's doubled entries (bindings 0 and 1,
    /// vertex stage; volume/extrude.vert under PULLED), extrusion=mesh the count, the faces, the
    /// doubled entries and the meshes' bases (bindings 0-3, mesh stage; volume/silhouette.mesh).
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
    /// extrusion=mesh: the volume of a caster of scene mesh `mesh` (its index in the push constants'
    /// ints.w, the light and flags as for every volume draw), with markSet() bound.
    void drawMesh(VkCommandBuffer cmd, uint32_t mesh) const;
    /// After the frame's last pass, outside any render pass: the count's additions made visible to the
    /// host, which reads it after the frame's fence.
    void endFrame(VkCommandBuffer cmd) const;
    /// The last finished frame's volume triangles.
    double readTriangles() const;

private:
    /// Grows the compute path's output and command buffers to hold `vertices` and `commands` words
    /// and points the sets' bindings at them.
    void reserve(size_t vertices, size_t commands);

    /// The faces and doubled entries of every mesh (compute and mesh paths), each mesh from its base.
    void uploadFaces(const VulkanCompileContext& ctx, const std::vector<const ShadowVolumeMesh*>& meshes);

    VulkanContext* mContext = nullptr;
    VolumePlanner::Extrusion mExtrusion = VolumePlanner::Extrusion::Geometry;
    VulkanBuffer mCount;
    DescriptorSets mSets;     ///< compute: count, faces, output, commands
    DescriptorSets mMarkSets; ///< set 1 of the marking pipelines (markLayout())
    std::vector<VulkanBuffer> mAdjacency;
    // extrusion=compute and mesh
    VulkanBuffer mFaces, mDoubled, mVertices, mCommands;
    VulkanBuffer mMeshTable; ///< extrusion=mesh: per scene mesh (first face, faces, first entry, n)
    std::vector<uint32_t> mFaceBase, mFaceCount, mVertexBase, mVertexCount; ///< per scene mesh
    ComputePipeline mPipeline;
};

} // namespace sb
