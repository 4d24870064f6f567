#pragma once
// A technique's descriptor sets in one object: the set layouts it declares, one pool sized for exactly
// those, and one set of each, allocated at construction and released together. What set 1 (and beyond)
// of a pipeline layout holds: a pass's uniform blocks, a shadow map and its sampler, a ray query's scene.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace sb {

class DescriptorSets {
public:
    using Bindings = std::vector<VkDescriptorSetLayoutBinding>;
    DescriptorSets() = default;
    /// One layout and one set per entry of `layouts`. `what` names them in errors ("shadowmap").
    DescriptorSets(VkDevice device, const std::vector<Bindings>& layouts, const char* what);
    ~DescriptorSets();
    DescriptorSets(DescriptorSets&& other) noexcept;
    DescriptorSets& operator=(DescriptorSets&& other) noexcept;
    DescriptorSets(const DescriptorSets&) = delete;
    DescriptorSets& operator=(const DescriptorSets&) = delete;

    VkDescriptorSetLayout layout(size_t i) const { return mLayouts[i]; }
    VkDescriptorSet set(size_t i) const { return mSets[i]; }

    /// Points binding `binding` of set `i` at `range` bytes of `buffer` (a uniform buffer, dynamic or not).
    void writeBuffer(size_t i, uint32_t binding, VkDescriptorType type, VkBuffer buffer,
                     VkDeviceSize range) const;
    /// Points binding `binding` of set `i` at `view` through `sampler`, read in `layout`.
    void writeImage(size_t i, uint32_t binding, VkSampler sampler, VkImageView view,
                    VkImageLayout layout) const;

    /// Points binding `binding` of set `i` at the storage image `view`, in the general layout (a shader's
    /// imageLoad and imageStore).
    void writeStorageImage(size_t i, uint32_t binding, VkImageView view) const;
    /// Points binding `binding` of set `i` at acceleration structure `structure` (a ray query's scene).
    void writeAccelerationStructure(size_t i, uint32_t binding, VkAccelerationStructureKHR structure) const;

    /// One binding of `count` descriptors of `type`, seen by `stages`.
    static VkDescriptorSetLayoutBinding binding(uint32_t binding, VkDescriptorType type,
                                                VkShaderStageFlags stages, uint32_t count = 1) {
        return {binding, type, count, stages, nullptr};
    }

private:
    void release();
    /// The write of one descriptor of `type` at binding `binding` of set `i`, pointing at nothing yet:
    /// each public write adds what it points at (an image, a buffer, a chained structure).
    VkWriteDescriptorSet write(size_t i, uint32_t binding, VkDescriptorType type) const;
    /// Writes `info` (a sampler and view, or a storage view, with its layout) as one descriptor of `type`.
    void writeImageInfo(size_t i, uint32_t binding, VkDescriptorType type,
                        const VkDescriptorImageInfo& info) const;
    VkDevice mDevice = VK_NULL_HANDLE;
    VkDescriptorPool mPool = VK_NULL_HANDLE;
    std::vector<VkDescriptorSetLayout> mLayouts;
    std::vector<VkDescriptorSet> mSets;
};

} // namespace sb
