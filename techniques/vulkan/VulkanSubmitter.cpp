#include "techniques/vulkan/VulkanSubmitter.h"

#include <algorithm>
#include <cstring>
#include <numeric>

#include "core/Error.h"
#include "vk/VulkanContext.h"

namespace sb {

namespace {
constexpr DrawSet kSets[kDrawSetCount] = {DrawSet::All, DrawSet::Casters, DrawSet::Receivers,
                                          DrawSet::NonCasters, DrawSet::NonReceivers};
} // namespace

VulkanSubmitter::VulkanSubmitter(VulkanContext& context, SubmitMode mode) : mContext(context), mMode(mode) {
    if (mode != SubmitMode::Retained && mode != SubmitMode::Instanced)
        throw Error(std::string("--submit ") + submitModeName(mode) +
                        " is GL-only (glBegin/glEnd and display lists have no Vulkan form); on Vulkan use "
                        "--submit retained or --submit instanced",
                    ExitCode::Unsupported);
}

void VulkanSubmitter::upload(const Scene& scene) {
    mScene = &scene;
    mMeshes.clear();
    for (const Mesh& mesh : scene.meshes) {
        std::vector<glm::vec3> interleaved;
        interleaved.reserve(mesh.positions.size() * 2);
        for (size_t i = 0; i < mesh.positions.size(); ++i) {
            interleaved.push_back(mesh.positions[i]);
            interleaved.push_back(mesh.normals[i]);
        }
        MeshGpu g;
        g.vertices = VulkanBuffer(mContext, interleaved.size() * sizeof(glm::vec3),
                                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, interleaved.data());
        g.indices = VulkanBuffer(mContext, mesh.indices.size() * sizeof(uint32_t),
                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT, mesh.indices.data());
        g.indexCount = uint32_t(mesh.indices.size());
        mMeshes.push_back(std::move(g));
    }
    mOrder.resize(scene.instances.size());
    std::iota(mOrder.begin(), mOrder.end(), 0u);
    std::stable_sort(mOrder.begin(), mOrder.end(), [&](uint32_t a, uint32_t b) {
        return scene.instances[a].mesh < scene.instances[b].mesh;
    });
    if (mMode != SubmitMode::Instanced) return;
    // As InstancedSubmitter: per draw set and mesh, that set's instances contiguously.
    mRecords.clear();
    mRecordInstance.clear();
    for (size_t s = 0; s < kDrawSetCount; ++s) {
        mBatches[s].clear();
        for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
            Batch b{m, uint32_t(mRecords.size()), 0};
            for (uint32_t i = 0; i < scene.instances.size(); ++i) {
                const Instance& inst = scene.instances[i];
                if (inst.mesh != m || !inDrawSet(inst, kSets[s])) continue;
                mRecords.push_back({inst.model, glm::vec4(inst.color, shadowSignedId(inst))});
                mRecordInstance.push_back(i);
                ++b.count;
            }
            if (b.count) mBatches[s].push_back(b);
        }
    }
    mInstances = VulkanBuffer(mContext, std::max<size_t>(1, mRecords.size()) * sizeof(InstanceRecord),
                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    if (!mRecords.empty())
        std::memcpy(mInstances.map(), mRecords.data(), mRecords.size() * sizeof(InstanceRecord));
}

void VulkanSubmitter::instancesMoved(const Scene& scene) {
    if (mMode != SubmitMode::Instanced) return;
    for (size_t r = 0; r < mRecords.size(); ++r)
        mRecords[r].model = scene.instances[mRecordInstance[r]].model;
    if (!mRecords.empty())
        std::memcpy(mInstances.map(), mRecords.data(), mRecords.size() * sizeof(InstanceRecord));
}

Defines VulkanSubmitter::defines() const {
    if (mMode == SubmitMode::Instanced) return {{"SB_INSTANCED", ""}};
    return {};
}

std::vector<VkVertexInputBindingDescription> VulkanSubmitter::bindings() const {
    std::vector<VkVertexInputBindingDescription> b{{0, 2 * sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX}};
    if (mMode == SubmitMode::Instanced)
        b.push_back({1, sizeof(InstanceRecord), VK_VERTEX_INPUT_RATE_INSTANCE});
    return b;
}

std::vector<VkVertexInputAttributeDescription> VulkanSubmitter::attributes() const {
    std::vector<VkVertexInputAttributeDescription> a{{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
                                                     {1, 0, VK_FORMAT_R32G32B32_SFLOAT, sizeof(glm::vec3)}};
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
    if (mMode == SubmitMode::Instanced)
        drawInstanced(cmd, layout, set, keep, push);
    else
        drawRetained(cmd, layout, set, keep, push);
}

void VulkanSubmitter::drawRetained(VkCommandBuffer cmd, VkPipelineLayout layout, DrawSet set,
                                   InstanceMask keep, VulkanPush push) {
    uint32_t bound = UINT32_MAX;
    for (uint32_t i : mOrder) {
        const Instance& inst = mScene->instances[i];
        if (!inDrawSet(inst, set) || !keptBy(keep, i)) continue;
        if (inst.mesh != bound) bindMesh(cmd, bound = inst.mesh);
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
    for (const Batch& b : mBatches[size_t(set)]) {
        bindMesh(cmd, b.mesh);
        const uint32_t count = mMeshes[b.mesh].indexCount;
        // Each run of consecutive kept records is one draw (firstInstance selects the run).
        for (uint32_t r = 0; r < b.count;) {
            if (!keptBy(keep, mRecordInstance[b.first + r])) {
                ++r;
                continue;
            }
            uint32_t end = r;
            while (end < b.count && keptBy(keep, mRecordInstance[b.first + end])) ++end;
            vkCmdDrawIndexed(cmd, count, end - r, 0, 0, b.first + r);
            mStats.drawCalls += 1;
            mStats.triangles += uint64_t(count / 3) * (end - r);
            mStats.instances += end - r;
            mStats.glCalls += 1;
            r = end;
        }
    }
}

} // namespace sb
