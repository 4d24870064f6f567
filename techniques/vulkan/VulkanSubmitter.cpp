#include "techniques/vulkan/VulkanSubmitter.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/Error.h"
#include "vk/VulkanContext.h"

namespace sb {

VulkanSubmitter::VulkanSubmitter(VulkanContext& context, SubmitMode mode) : mContext(context), mMode(mode) {
    if (mode != SubmitMode::Retained && mode != SubmitMode::Instanced)
        throw Error(std::string("--submit ") + submitModeName(mode) +
                        " is GL-only (glBegin/glEnd and display lists have no Vulkan form); on Vulkan use "
                        "--submit retained or --submit instanced",
                    ExitCode::Unsupported);
    // Dynamic cull mode is core in 1.3; the device's version is "major.minor.patch".
    const std::string& v = context.info().apiVersion;
    const int major = std::atoi(v.c_str());
    const size_t dot = v.find('.');
    const int minor = dot == std::string::npos ? 0 : std::atoi(v.c_str() + dot + 1);
    mDynamicCull = major > 1 || (major == 1 && minor >= 3);
}

void VulkanSubmitter::upload(const Scene& scene) {
    mScene = &scene;
    mBackFaceCuller.setScene(scene, mDynamicCull ? mBackFaces : BackFaces::Draw);
    mMeshes.clear();
    for (const Mesh& mesh : scene.meshes) {
        const std::vector<glm::vec3> interleaved = interleavedVertices(mesh);
        MeshGpu g;
        g.vertices = VulkanBuffer(mContext, interleaved.size() * sizeof(glm::vec3),
                                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, interleaved.data());
        g.indices = VulkanBuffer(mContext, mesh.indices.size() * sizeof(uint32_t),
                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT, mesh.indices.data());
        g.indexCount = uint32_t(mesh.indices.size());
        mMeshes.push_back(std::move(g));
    }
    mOrder = instancesByMesh(scene);
    if (mMode != SubmitMode::Instanced) return;
    // As InstancedSubmitter: per draw set and mesh, that set's instances contiguously.
    mPlan = SubmissionPlan(scene);
    const std::vector<InstanceRecord>& records = mPlan.records();
    mInstances = VulkanBuffer(mContext, std::max<size_t>(1, records.size()) * sizeof(InstanceRecord),
                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    if (!records.empty())
        std::memcpy(mInstances.map(), records.data(), records.size() * sizeof(InstanceRecord));
}

void VulkanSubmitter::instancesMoved(const Scene& scene) {
    mBackFaceCuller.instancesMoved(scene);
    if (mMode != SubmitMode::Instanced) return;
    mPlan.instancesMoved(scene);
    const std::vector<InstanceRecord>& records = mPlan.records();
    if (!records.empty())
        std::memcpy(mInstances.map(), records.data(), records.size() * sizeof(InstanceRecord));
}

Defines VulkanSubmitter::defines() const {
    if (mMode == SubmitMode::Instanced) return {{"SB_INSTANCED", ""}};
    return {};
}

std::vector<VkVertexInputBindingDescription> VulkanSubmitter::bindings() const {
    std::vector<VkVertexInputBindingDescription> b{{0, kVertexStride, VK_VERTEX_INPUT_RATE_VERTEX}};
    if (mMode == SubmitMode::Instanced)
        b.push_back({1, sizeof(InstanceRecord), VK_VERTEX_INPUT_RATE_INSTANCE});
    return b;
}

std::vector<VkVertexInputAttributeDescription> VulkanSubmitter::attributes() const {
    std::vector<VkVertexInputAttributeDescription> a{{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                     {1, 0, VK_FORMAT_R32G32B32_SFLOAT, kNormalOffset}};
    if (mMode != SubmitMode::Instanced) return a;
    for (uint32_t c = 0; c < 4; ++c)
        a.push_back({4 + c, 1, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(c * sizeof(glm::vec4))});
    a.push_back({8, 1, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(InstanceRecord, colorId))});
    return a;
}

void VulkanSubmitter::bindMesh(VkCommandBuffer cmd, uint32_t mesh) {
    const VkDeviceSize zero = 0;
    const VkBuffer vb = mMeshes[mesh].vertices.buffer();
    vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &zero);
    vkCmdBindIndexBuffer(cmd, mMeshes[mesh].indices.buffer(), 0, VK_INDEX_TYPE_UINT32);
    mStats.glCalls += 2;
}

void VulkanSubmitter::draw(VkCommandBuffer cmd, VkPipelineLayout layout, DrawSet set, InstanceMask keep,
                           const VulkanPush& push) {
    if (!mScope.empty()) keep = narrowToScope(keep);
    const bool dynamic = mDynamicCull && mViewSet;
    if (dynamic) {
        // Dynamic state is lost when a pipeline without it was bound since: set it at every draw.
        vkCmdSetFrontFace(cmd, mBackFaceCuller.frontCounterClockwise() ? VK_FRONT_FACE_COUNTER_CLOCKWISE
                                                                       : VK_FRONT_FACE_CLOCKWISE);
        vkCmdSetCullMode(cmd, VK_CULL_MODE_NONE);
        mCullOn = false;
        mStats.glCalls += 2;
    }
    if (mMode == SubmitMode::Instanced)
        drawInstanced(cmd, layout, set, keep, push);
    else
        drawRetained(cmd, layout, set, keep, push);
}

void VulkanSubmitter::setCullView(const CullView* view, bool clipFlipsY) {
    // Vulkan counts winding with y running down the framebuffer; a y-flipped clip space undoes that.
    mBackFaceCuller.setView(view, !clipFlipsY);
    mViewSet = view && mDynamicCull;
}

void VulkanSubmitter::setCullMode(VkCommandBuffer cmd, bool cull) {
    if (cull == mCullOn) return;
    vkCmdSetCullMode(cmd, cull ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE);
    mCullOn = cull;
    mStats.glCalls += 1;
}

InstanceMask VulkanSubmitter::narrowToScope(InstanceMask keep) {
    mScoped.resize(mScope.size());
    for (size_t i = 0; i < mScope.size(); ++i) mScoped[i] = mScope[i] && keptBy(keep, i) ? 1 : 0;
    return mScoped;
}

void VulkanSubmitter::drawRetained(VkCommandBuffer cmd, VkPipelineLayout layout, DrawSet set,
                                   InstanceMask keep, VulkanPush push) {
    uint32_t bound = UINT32_MAX;
    for (uint32_t i : mOrder) {
        const Instance& inst = mScene->instances[i];
        if (!inDrawSet(inst, set) || !keptBy(keep, i)) continue;
        if (inst.mesh != bound) bindMesh(cmd, bound = inst.mesh);
        if (mViewSet) setCullMode(cmd, mBackFaceCuller.culls(i));
        push.model = inst.model;
        push.colorId = glm::vec4(inst.color, shadowSignedId(inst));
        vkCmdPushConstants(cmd, layout, kPushStages, 0, sizeof push, &push);
        const uint32_t count = mMeshes[inst.mesh].indexCount;
        vkCmdDrawIndexed(cmd, count, 1, 0, 0, 0);
        mStats.drawCalls += 1;
        mStats.triangles += count / 3;
        mStats.instances += 1;
        mStats.glCalls += 2;
    }
}

void VulkanSubmitter::drawInstanced(VkCommandBuffer cmd, VkPipelineLayout layout, DrawSet set,
                                    InstanceMask keep, const VulkanPush& push) {
    vkCmdPushConstants(cmd, layout, kPushStages, 0, sizeof push, &push);
    mStats.glCalls += 1;
    const VkDeviceSize zero = 0;
    const VkBuffer ib = mInstances.buffer();
    vkCmdBindVertexBuffers(cmd, 1, 1, &ib, &zero);
    for (const SubmissionPlan::Batch& b : mPlan.batches(set)) {
        bindMesh(cmd, b.mesh);
        const uint32_t count = mMeshes[b.mesh].indexCount;
        // Each run of consecutive kept records is one draw (firstInstance selects the run).
        // A run splits where the view's back-face decision changes.
        mPlan.forEachKeptRun(b, keep, mBackFaceCuller.decisions(),
                             [&](uint32_t first, uint32_t instances, bool cull) {
                                 if (mViewSet) setCullMode(cmd, cull);
                                 vkCmdDrawIndexed(cmd, count, instances, 0, 0, first);
                                 mStats.drawCalls += 1;
                                 mStats.triangles += uint64_t(count / 3) * instances;
                                 mStats.instances += instances;
                                 mStats.glCalls += 1;
                             });
    }
}

} // namespace sb
