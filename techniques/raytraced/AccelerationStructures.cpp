#include "techniques/raytraced/AccelerationStructures.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <functional>

#include "scenes/Math.h"
#include "scenes/MortonOrder.h"

namespace sb {

namespace {

constexpr VkBufferUsageFlags kBuildInput =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;
constexpr VkBufferUsageFlags kScratch =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

VkDeviceSize scratchAlignment(const VulkanContext& context) {
    VkPhysicalDeviceAccelerationStructurePropertiesKHR structures{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_ACCELERATION_STRUCTURE_PROPERTIES_KHR};
    VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties.pNext = &structures;
    vkGetPhysicalDeviceProperties2(context.physicalDevice(), &properties);
    return std::max<VkDeviceSize>(1, structures.minAccelerationStructureScratchOffsetAlignment);
}

/// A mesh's triangles as the build reads them: positions (float3, object space) and 32-bit indices.
VkAccelerationStructureGeometryKHR triangles(const Mesh& mesh, const VulkanBuffer& positions,
                                             const VulkanBuffer& indices) {
    VkAccelerationStructureGeometryKHR g{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    g.geometryType = VK_GEOMETRY_TYPE_TRIANGLES_KHR;
    g.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
    VkAccelerationStructureGeometryTrianglesDataKHR& t = g.geometry.triangles;
    t.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_TRIANGLES_DATA_KHR;
    t.vertexFormat = VK_FORMAT_R32G32B32_SFLOAT;
    t.vertexData.deviceAddress = positions.address();
    t.vertexStride = sizeof(glm::vec3);
    t.maxVertex = uint32_t(mesh.positions.size() - 1);
    t.indexType = VK_INDEX_TYPE_UINT32;
    t.indexData.deviceAddress = indices.address();
    return g;
}

VkAccelerationStructureBuildGeometryInfoKHR buildInfo(VkAccelerationStructureTypeKHR type,
                                                      const VkAccelerationStructureGeometryKHR* geometry) {
    VkAccelerationStructureBuildGeometryInfoKHR info{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_GEOMETRY_INFO_KHR};
    info.type = type;
    info.flags = VK_BUILD_ACCELERATION_STRUCTURE_PREFER_FAST_TRACE_BIT_KHR;
    info.mode = VK_BUILD_ACCELERATION_STRUCTURE_MODE_BUILD_KHR;
    info.geometryCount = 1;
    info.pGeometries = geometry;
    return info;
}

VkAccelerationStructureBuildSizesInfoKHR buildSizes(const VulkanContext& context,
                                                    const VkAccelerationStructureBuildGeometryInfoKHR& info,
                                                    uint32_t primitives) {
    VkAccelerationStructureBuildSizesInfoKHR sizes{
        VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_BUILD_SIZES_INFO_KHR};
    context.rayQueryFunctions().getBuildSizes(
        context.device(), VK_ACCELERATION_STRUCTURE_BUILD_TYPE_DEVICE_KHR, &info, &primitives, &sizes);
    return sizes;
}

/// Between two builds in one command buffer: the first's writes before the second's reads.
void buildToBuildBarrier(VkCommandBuffer cmd) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                         VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR, 0, 1, &barrier, 0, nullptr,
                         0, nullptr);
}

/// VkTransformMatrixKHR is the first three rows of the model matrix, row-major; glm is column-major.
VkTransformMatrixKHR rowMajor3x4(const glm::mat4& m) {
    VkTransformMatrixKHR t{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) t.matrix[r][c] = m[c][r];
    return t;
}

/// context.submitNow(record), returning its host wall time in ms (recording to the fence).
double timedSubmit(VulkanContext& context, const std::function<void(VkCommandBuffer)>& record) {
    const auto t0 = std::chrono::steady_clock::now();
    context.submitNow(record);
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

} // namespace

AccelerationStructures::AccelerationStructures(VulkanContext& context, const Scene& scene)
    : mContext(context), mScratchAlignment(scratchAlignment(context)) {
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        if (inst.castsShadow && inst.mesh < scene.meshes.size() &&
            scene.meshes[inst.mesh].triangleCount() > 0)
            mCasters.push_back(i);
    }
    orderCastersInSpace(scene);
    // One record at least: a scene without casters still builds a (empty) top level over a valid buffer.
    mInstances = VulkanBuffer(
        context, std::max<size_t>(1, mCasters.size()) * sizeof(VkAccelerationStructureInstanceKHR),
        kBuildInput);
    std::memset(mInstances.map(), 0, size_t(mInstances.size()));
    buildBottomLevels(scene);
    writeInstances(scene);
    createTopLevel();
    mTopLevelBuildMs = timedSubmit(context, [&](VkCommandBuffer cmd) { recordTopLevelBuild(cmd); });
}

void AccelerationStructures::orderCastersInSpace(const Scene& scene) {
    std::vector<glm::vec3> centres;
    centres.reserve(mCasters.size());
    for (size_t i : mCasters) {
        const Instance& inst = scene.instances[i];
        centres.push_back(transformBounds(scene.meshBoundsOf(inst.mesh), inst.model).center());
    }
    std::vector<size_t> ordered;
    ordered.reserve(mCasters.size());
    for (size_t k : mortonOrder(centres)) ordered.push_back(mCasters[k]);
    mCasters = std::move(ordered);
}

void AccelerationStructures::buildBottomLevels(const Scene& scene) {
    mBottomLevels.resize(scene.meshes.size());
    std::vector<VulkanBuffer> inputs; // positions and indices of each built mesh, in pairs
    std::vector<VkAccelerationStructureGeometryKHR> geometries;
    std::vector<VkAccelerationStructureBuildGeometryInfoKHR> infos;
    std::vector<VkAccelerationStructureBuildRangeInfoKHR> ranges;
    std::vector<VkDeviceSize> scratchOffsets;
    VkDeviceSize scratchBytes = 0;
    geometries.reserve(scene.meshes.size()); // the infos point into it
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const Mesh& mesh = scene.meshes[m];
        const uint32_t count = uint32_t(mesh.triangleCount());
        if (count == 0) continue;
        inputs.emplace_back(mContext, mesh.positions.size() * sizeof(glm::vec3), kBuildInput,
                            mesh.positions.data());
        inputs.emplace_back(mContext, count * 3 * sizeof(uint32_t), kBuildInput, mesh.indices.data());
        geometries.push_back(triangles(mesh, inputs[inputs.size() - 2], inputs.back()));
        VkAccelerationStructureBuildGeometryInfoKHR info =
            buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR, &geometries.back());
        const VkAccelerationStructureBuildSizesInfoKHR sizes = buildSizes(mContext, info, count);
        mBottomLevels[m] = AccelerationStructure(mContext, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM_LEVEL_KHR,
                                                 sizes.accelerationStructureSize);
        info.dstAccelerationStructure = mBottomLevels[m].handle();
        infos.push_back(info);
        ranges.push_back({count, 0, 0, 0});
        scratchOffsets.push_back(scratchBytes);
        scratchBytes += alignUp(sizes.buildScratchSize, mScratchAlignment);
    }
    if (infos.empty()) return;
    // One scratch buffer, a disjoint aligned region per build, so that all of them go in one command.
    const VulkanBuffer scratch(mContext, scratchBytes + mScratchAlignment, kScratch, nullptr);
    const VkDeviceAddress base = alignUp(scratch.address(), mScratchAlignment);
    std::vector<const VkAccelerationStructureBuildRangeInfoKHR*> rangePointers;
    for (size_t i = 0; i < infos.size(); ++i) {
        infos[i].scratchData.deviceAddress = base + scratchOffsets[i];
        rangePointers.push_back(&ranges[i]);
    }
    mBottomLevelsBuildMs = timedSubmit(mContext, [&](VkCommandBuffer cmd) {
        mContext.rayQueryFunctions().cmdBuild(cmd, uint32_t(infos.size()), infos.data(),
                                              rangePointers.data());
        buildToBuildBarrier(cmd);
    });
}

void AccelerationStructures::writeInstances(const Scene& scene) {
    auto* records = static_cast<VkAccelerationStructureInstanceKHR*>(mInstances.map());
    for (size_t k = 0; k < mCasters.size(); ++k) {
        const Instance& inst = scene.instances[mCasters[k]];
        VkAccelerationStructureInstanceKHR& r = records[k];
        r.transform = rowMajor3x4(inst.model);
        r.instanceCustomIndex = uint32_t(mCasters[k]) & 0xFFFFFFu;
        r.mask = 0xFF;
        r.instanceShaderBindingTableRecordOffset = 0;
        r.flags = VK_GEOMETRY_INSTANCE_TRIANGLE_FACING_CULL_DISABLE_BIT_KHR |
                  VK_GEOMETRY_INSTANCE_FORCE_OPAQUE_BIT_KHR;
        r.accelerationStructureReference = mBottomLevels[inst.mesh].address();
    }
}

namespace {

VkAccelerationStructureGeometryKHR instances(const VulkanBuffer& buffer) {
    VkAccelerationStructureGeometryKHR g{VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_KHR};
    g.geometryType = VK_GEOMETRY_TYPE_INSTANCES_KHR;
    g.flags = VK_GEOMETRY_OPAQUE_BIT_KHR;
    g.geometry.instances.sType = VK_STRUCTURE_TYPE_ACCELERATION_STRUCTURE_GEOMETRY_INSTANCES_DATA_KHR;
    g.geometry.instances.arrayOfPointers = VK_FALSE;
    g.geometry.instances.data.deviceAddress = buffer.address();
    return g;
}

} // namespace

void AccelerationStructures::createTopLevel() {
    const VkAccelerationStructureGeometryKHR geometry = instances(mInstances);
    const VkAccelerationStructureBuildGeometryInfoKHR info =
        buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, &geometry);
    const VkAccelerationStructureBuildSizesInfoKHR sizes = buildSizes(mContext, info, instanceCount());
    mTopLevel = AccelerationStructure(mContext, VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR,
                                      sizes.accelerationStructureSize);
    mTopLevelScratch = VulkanBuffer(mContext, sizes.buildScratchSize + mScratchAlignment, kScratch, nullptr);
}

void AccelerationStructures::recordTopLevelBuild(VkCommandBuffer cmd) {
    const VkAccelerationStructureGeometryKHR geometry = instances(mInstances);
    VkAccelerationStructureBuildGeometryInfoKHR info =
        buildInfo(VK_ACCELERATION_STRUCTURE_TYPE_TOP_LEVEL_KHR, &geometry);
    info.dstAccelerationStructure = mTopLevel.handle();
    info.scratchData.deviceAddress = alignUp(mTopLevelScratch.address(), mScratchAlignment);
    const VkAccelerationStructureBuildRangeInfoKHR range{instanceCount(), 0, 0, 0};
    const VkAccelerationStructureBuildRangeInfoKHR* ranges = &range;
    mContext.rayQueryFunctions().cmdBuild(cmd, 1, &info, &ranges);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_WRITE_BIT_KHR;
    barrier.dstAccessMask = VK_ACCESS_ACCELERATION_STRUCTURE_READ_BIT_KHR;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ACCELERATION_STRUCTURE_BUILD_BIT_KHR,
                         VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

uint64_t AccelerationStructures::bytes() const {
    uint64_t total = mTopLevel.bytes();
    for (const AccelerationStructure& s : mBottomLevels) total += s.bytes();
    return total;
}

size_t AccelerationStructures::bottomLevelCount() const {
    return size_t(std::count_if(mBottomLevels.begin(), mBottomLevels.end(),
                                [](const AccelerationStructure& s) { return bool(s); }));
}

} // namespace sb
