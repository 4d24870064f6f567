#include "techniques/volume/GpuSilhouettesVulkan.h"

#include <algorithm>
#include <cstring>

#include "techniques/volume/SilhouetteInputs.h"
#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

namespace {
/// shaders/volume/silhouette.comp's SilhouettePush.
struct SilhouettePush {
    glm::vec4 light{0.0f};
    uint32_t flags = 0, faceCount = 0, draw = 0, vertexCount = 0, faceBase = 0, vertexBase = 0;
};
static_assert(sizeof(SilhouettePush) == 40, "silhouette.comp's push block");
// silhouette.comp's storage bindings (set 0), as on GL.
constexpr uint32_t kCountBinding = 0, kFacesBinding = 1, kVerticesBinding = 2, kCommandsBinding = 3;
// Set 1 of the marking pipelines: the geometry path's count, or volume/extrude.vert's (PULLED) entries,
// or volume/silhouette.mesh's count, faces, doubled entries and meshes.
constexpr uint32_t kMarkCountBinding = 0, kMarkVerticesBinding = 0, kMarkDoubledBinding = 1;
constexpr uint32_t kMeshCountBinding = 0, kMeshFacesBinding = 1, kMeshDoubledBinding = 2,
                   kMeshTableBinding = 3;
/// volume/silhouette.mesh's vertex slots and most triangles per face (its SLOTS).
constexpr uint32_t kMeshSlotsPerFace = 7;
constexpr uint32_t kLocalSize = 64;
constexpr size_t kCommandWords = 4; ///< VkDrawIndirectCommand
static_assert(sizeof(VkDrawIndirectCommand) == kCommandWords * sizeof(uint32_t));

DescriptorSets::Bindings storageBindings(uint32_t count, VkShaderStageFlags stages) {
    DescriptorSets::Bindings out;
    for (uint32_t i = 0; i < count; ++i)
        out.push_back(DescriptorSets::binding(i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, stages));
    return out;
}
} // namespace

Defines GpuSilhouettesVulkan::meshDefines() {
    return {{"FACES_PER_GROUP", std::to_string(kFacesPerGroup)}};
}

std::string GpuSilhouettesVulkan::meshShaderProblem(const VulkanContext& context, size_t maxFaces) {
    const std::string device = "'" + context.info().name + "'";
    if (!context.meshShader())
        return "the meshShader feature of VK_EXT_mesh_shader, which " + device + " does not offer";
    const VkPhysicalDeviceMeshShaderPropertiesEXT& p = context.meshShaderProperties();
    const uint32_t outputs = kMeshSlotsPerFace * kFacesPerGroup;
    const uint64_t groups = (maxFaces + kFacesPerGroup - 1) / kFacesPerGroup;
    const uint64_t columns = std::min<uint64_t>(groups, p.maxMeshWorkGroupCount[0]);
    const uint64_t rows = columns ? (groups + columns - 1) / columns : 0;
    auto need = [&](uint64_t needed, uint64_t offered, const char* limit) {
        return needed <= offered ? std::string()
                                 : std::string(limit) + " of at least " + std::to_string(needed) + " (" +
                                       device + " offers " + std::to_string(offered) + ")";
    };
    // The outputs: gl_Position per vertex and 3 indices per triangle, 16 bytes each at most.
    for (const std::string& problem :
         {need(outputs, p.maxMeshOutputVertices, "maxMeshOutputVertices"),
          need(outputs, p.maxMeshOutputPrimitives, "maxMeshOutputPrimitives"),
          need(kFacesPerGroup, p.maxMeshWorkGroupInvocations, "maxMeshWorkGroupInvocations"),
          need(kFacesPerGroup, p.maxMeshWorkGroupSize[0], "maxMeshWorkGroupSize[0]"),
          need(2ull * outputs * 16, p.maxMeshOutputMemorySize, "maxMeshOutputMemorySize"),
          need(rows, p.maxMeshWorkGroupCount[1], "maxMeshWorkGroupCount[1]"),
          need(groups, p.maxMeshWorkGroupTotalCount, "maxMeshWorkGroupTotalCount")})
        if (!problem.empty()) return problem;
    return "";
}

void GpuSilhouettesVulkan::release() {
    mPipeline = ComputePipeline();
    mSets = DescriptorSets();
    mMarkSets = DescriptorSets();
    mAdjacency.clear();
    mFaces = VulkanBuffer();
    mDoubled = VulkanBuffer();
    mVertices = VulkanBuffer();
    mCommands = VulkanBuffer();
    mCount = VulkanBuffer();
    mMeshTable = VulkanBuffer();
    mFaceBase.clear();
    mFaceCount.clear();
    mVertexBase.clear();
    mVertexCount.clear();
}

void GpuSilhouettesVulkan::create(const VulkanCompileContext& ctx,
                                  const std::vector<const ShadowVolumeMesh*>& meshes,
                                  VolumePlanner::Extrusion extrusion) {
    using Extrusion = VolumePlanner::Extrusion;
    release();
    mContext = &ctx.context;
    mExtrusion = extrusion;
    const VkDevice device = ctx.context.device();
    mCount = VulkanBuffer(ctx.context, sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    std::memset(mCount.map(), 0, sizeof(uint32_t));
    if (extrusion == Extrusion::Geometry) {
        mMarkSets =
            DescriptorSets(device, {storageBindings(1, VK_SHADER_STAGE_GEOMETRY_BIT)}, "volume silhouettes");
        mMarkSets.writeBuffer(0, kMarkCountBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mCount.buffer(),
                              mCount.size());
        mAdjacency.resize(meshes.size());
        for (size_t m = 0; m < meshes.size(); ++m) {
            if (!meshes[m]) continue;
            const std::vector<glm::vec4> v = SilhouetteInputs::adjacencyVertices(*meshes[m]);
            mAdjacency[m] = VulkanBuffer(ctx.context, std::max<size_t>(1, v.size()) * sizeof(glm::vec4),
                                         VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, v.empty() ? nullptr : v.data());
        }
        return;
    }
    uploadFaces(ctx, meshes);
    if (extrusion == Extrusion::Mesh) {
        std::vector<glm::uvec4> table(std::max<size_t>(1, meshes.size()), glm::uvec4(0u));
        for (size_t m = 0; m < meshes.size(); ++m)
            table[m] = {mFaceBase[m], mFaceCount[m], mVertexBase[m], mVertexCount[m]};
        mMeshTable = VulkanBuffer(ctx.context, table.size() * sizeof(glm::uvec4),
                                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, table.data());
        mMarkSets =
            DescriptorSets(device, {storageBindings(4, VK_SHADER_STAGE_MESH_BIT_EXT)}, "volume silhouettes");
        mMarkSets.writeBuffer(0, kMeshCountBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mCount.buffer(),
                              mCount.size());
        mMarkSets.writeBuffer(0, kMeshFacesBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mFaces.buffer(),
                              mFaces.size());
        mMarkSets.writeBuffer(0, kMeshDoubledBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mDoubled.buffer(),
                              mDoubled.size());
        mMarkSets.writeBuffer(0, kMeshTableBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mMeshTable.buffer(),
                              mMeshTable.size());
        return;
    }
    mSets = DescriptorSets(device, {storageBindings(4, VK_SHADER_STAGE_COMPUTE_BIT)}, "volume silhouettes");
    mSets.writeBuffer(0, kCountBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mCount.buffer(), mCount.size());
    mSets.writeBuffer(0, kFacesBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mFaces.buffer(), mFaces.size());
    mMarkSets =
        DescriptorSets(device, {storageBindings(2, VK_SHADER_STAGE_VERTEX_BIT)}, "volume silhouettes");
    mMarkSets.writeBuffer(0, kMarkDoubledBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mDoubled.buffer(),
                          mDoubled.size());
    reserve(1, kCommandWords);
    mPipeline =
        ComputePipeline(ctx.context, ctx.shaders.get("volume/silhouette.comp", {}, ShaderStage::Compute),
                        {mSets.layout(0)}, sizeof(SilhouettePush));
}

void GpuSilhouettesVulkan::uploadFaces(const VulkanCompileContext& ctx,
                                       const std::vector<const ShadowVolumeMesh*>& meshes) {
    // Every mesh's faces in one buffer and its doubled entries in another, each mesh from its own base.
    std::vector<SilhouetteFace> faces;
    std::vector<glm::vec4> doubled;
    mFaceBase.assign(meshes.size(), 0);
    mFaceCount.assign(meshes.size(), 0);
    mVertexBase.assign(meshes.size(), 0);
    mVertexCount.assign(meshes.size(), 0);
    for (size_t m = 0; m < meshes.size(); ++m) {
        if (!meshes[m]) continue;
        const std::vector<SilhouetteFace> f = SilhouetteInputs::faces(*meshes[m]);
        mFaceBase[m] = uint32_t(faces.size());
        mFaceCount[m] = uint32_t(f.size());
        faces.insert(faces.end(), f.begin(), f.end());
        const std::vector<glm::vec4> d = meshes[m]->doubledVertices();
        mVertexBase[m] = uint32_t(doubled.size());
        mVertexCount[m] = meshes[m]->vertexCount();
        doubled.insert(doubled.end(), d.begin(), d.end());
    }
    if (faces.empty()) faces.resize(1);
    if (doubled.empty()) doubled.resize(1, glm::vec4(0.0f));
    mFaces = VulkanBuffer(ctx.context, faces.size() * sizeof(SilhouetteFace),
                          VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, faces.data());
    mDoubled = VulkanBuffer(ctx.context, doubled.size() * sizeof(glm::vec4),
                            VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, doubled.data());
}

void GpuSilhouettesVulkan::reserve(size_t vertices, size_t commands) {
    // Geometric growth: a frame with a few more casters in range does not reallocate. The last frame
    // that used the old buffers has finished (the harness waited for its fence).
    const VkDeviceSize vertexBytes = vertices * sizeof(uint32_t), commandBytes = commands * sizeof(uint32_t);
    if (vertexBytes > mVertices.size()) {
        mVertices = VulkanBuffer(*mContext, std::max(vertexBytes, 2 * mVertices.size()),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, nullptr);
        mSets.writeBuffer(0, kVerticesBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mVertices.buffer(),
                          mVertices.size());
        mMarkSets.writeBuffer(0, kMarkVerticesBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mVertices.buffer(),
                              mVertices.size());
    }
    if (commandBytes > mCommands.size()) {
        mCommands = VulkanBuffer(*mContext, std::max(commandBytes, 2 * mCommands.size()),
                                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
        mSets.writeBuffer(0, kCommandsBinding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, mCommands.buffer(),
                          mCommands.size());
    }
}

void GpuSilhouettesVulkan::beginFrame() {
    std::memset(mCount.map(), 0, sizeof(uint32_t));
}

void GpuSilhouettesVulkan::extract(VkCommandBuffer cmd, const std::vector<VolumePlanner::Draw>& draws) {
    // Each draw's region holds the most its caster's faces can build; its command starts with none.
    size_t first = 0;
    for (const VolumePlanner::Draw& d : draws)
        first += SilhouetteInputs::kMaxVerticesPerFace * mFaceCount[d.caster->mesh];
    reserve(std::max<size_t>(1, first), std::max<size_t>(1, draws.size()) * kCommandWords);
    auto* commands = static_cast<VkDrawIndirectCommand*>(mCommands.map());
    first = 0;
    for (size_t i = 0; i < draws.size(); ++i) {
        commands[i] = {0u, 1u, uint32_t(first), 0u};
        first += SilhouetteInputs::kMaxVerticesPerFace * mFaceCount[draws[i].caster->mesh];
    }
    mPipeline.bind(cmd, {mSets.set(0)});
    for (size_t i = 0; i < draws.size(); ++i) {
        const VolumePlanner::Draw& d = draws[i];
        const uint32_t mesh = d.caster->mesh;
        if (!mFaceCount[mesh]) continue;
        const SilhouettePush push{d.lightObject,      d.gpuFlags,      mFaceCount[mesh], uint32_t(i),
                                  mVertexCount[mesh], mFaceBase[mesh], mVertexBase[mesh]};
        mPipeline.push(cmd, &push);
        vkCmdDispatch(cmd, (mFaceCount[mesh] + kLocalSize - 1) / kLocalSize, 1, 1);
    }
    // The vertex shader reads the entries, the indirect draws the counts.
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
}

void GpuSilhouettesVulkan::drawIndirect(VkCommandBuffer cmd, size_t i) const {
    vkCmdDrawIndirect(cmd, mCommands.buffer(), i * sizeof(VkDrawIndirectCommand), 1,
                      sizeof(VkDrawIndirectCommand));
}

void GpuSilhouettesVulkan::drawMesh(VkCommandBuffer cmd, uint32_t mesh) const {
    // Rows of at most maxMeshWorkGroupCount[0] groups (meshShaderProblem checked the rows); the
    // shader numbers its group y * width + x and leaves the faces past the mesh's last alone.
    const uint32_t groups = (mFaceCount[mesh] + kFacesPerGroup - 1) / kFacesPerGroup;
    if (!groups) return;
    const uint32_t columns = std::min(groups, mContext->meshShaderProperties().maxMeshWorkGroupCount[0]);
    mContext->cmdDrawMeshTasks()(cmd, columns, (groups + columns - 1) / columns, 1);
}

void GpuSilhouettesVulkan::endFrame(VkCommandBuffer cmd) const {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    const VkPipelineStageFlags writer =
        mExtrusion == VolumePlanner::Extrusion::Compute ? VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT
        : mExtrusion == VolumePlanner::Extrusion::Mesh  ? VK_PIPELINE_STAGE_MESH_SHADER_BIT_EXT
                                                        : VK_PIPELINE_STAGE_GEOMETRY_SHADER_BIT;
    vkCmdPipelineBarrier(cmd, writer, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

double GpuSilhouettesVulkan::readTriangles() const {
    if (!mCount) return 0;
    uint32_t value = 0;
    std::memcpy(&value, mCount.map(), sizeof value);
    return double(value);
}

} // namespace sb
