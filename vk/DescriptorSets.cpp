#include "vk/DescriptorSets.h"

#include <map>
#include <string>
#include <utility>

#include "vk/VulkanContext.h"

namespace sb {

DescriptorSets::DescriptorSets(VkDevice device, const std::vector<Bindings>& layouts, const char* what)
    : mDevice(device) {
    const std::string name = std::string(" (") + what + ")";
    std::map<VkDescriptorType, uint32_t> counts;
    for (const Bindings& bindings : layouts) {
        VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
        info.bindingCount = uint32_t(bindings.size());
        info.pBindings = bindings.data();
        VkDescriptorSetLayout layout = VK_NULL_HANDLE;
        VulkanContext::check(vkCreateDescriptorSetLayout(device, &info, nullptr, &layout),
                             ("vkCreateDescriptorSetLayout" + name).c_str());
        mLayouts.push_back(layout);
        for (const VkDescriptorSetLayoutBinding& b : bindings) counts[b.descriptorType] += b.descriptorCount;
    }
    std::vector<VkDescriptorPoolSize> sizes;
    for (const auto& [type, count] : counts) sizes.push_back({type, count});
    VkDescriptorPoolCreateInfo pool{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool.maxSets = uint32_t(layouts.size());
    pool.poolSizeCount = uint32_t(sizes.size());
    pool.pPoolSizes = sizes.data();
    VulkanContext::check(vkCreateDescriptorPool(device, &pool, nullptr, &mPool),
                         ("vkCreateDescriptorPool" + name).c_str());
    mSets.resize(mLayouts.size());
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = mPool;
    alloc.descriptorSetCount = uint32_t(mLayouts.size());
    alloc.pSetLayouts = mLayouts.data();
    VulkanContext::check(vkAllocateDescriptorSets(device, &alloc, mSets.data()),
                         ("vkAllocateDescriptorSets" + name).c_str());
}

DescriptorSets::~DescriptorSets() {
    release();
}

DescriptorSets::DescriptorSets(DescriptorSets&& other) noexcept {
    *this = std::move(other);
}

DescriptorSets& DescriptorSets::operator=(DescriptorSets&& other) noexcept {
    if (this == &other) return *this;
    release();
    mDevice = std::exchange(other.mDevice, VK_NULL_HANDLE);
    mPool = std::exchange(other.mPool, VK_NULL_HANDLE);
    mLayouts = std::exchange(other.mLayouts, {});
    mSets = std::exchange(other.mSets, {});
    return *this;
}

void DescriptorSets::release() {
    if (!mDevice) return;
    vkDestroyDescriptorPool(mDevice, mPool, nullptr); // frees the sets
    for (VkDescriptorSetLayout l : mLayouts) vkDestroyDescriptorSetLayout(mDevice, l, nullptr);
    mPool = VK_NULL_HANDLE;
    mLayouts.clear();
    mSets.clear();
    mDevice = VK_NULL_HANDLE;
}

VkWriteDescriptorSet DescriptorSets::write(size_t i, uint32_t binding, VkDescriptorType type) const {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstSet = mSets[i];
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    return w;
}

void DescriptorSets::writeImageInfo(size_t i, uint32_t binding, VkDescriptorType type,
                                    const VkDescriptorImageInfo& info) const {
    VkWriteDescriptorSet w = write(i, binding, type);
    w.pImageInfo = &info;
    vkUpdateDescriptorSets(mDevice, 1, &w, 0, nullptr);
}

void DescriptorSets::writeBuffer(size_t i, uint32_t binding, VkDescriptorType type, VkBuffer buffer,
                                 VkDeviceSize range) const {
    const VkDescriptorBufferInfo info{buffer, 0, range};
    VkWriteDescriptorSet w = write(i, binding, type);
    w.pBufferInfo = &info;
    vkUpdateDescriptorSets(mDevice, 1, &w, 0, nullptr);
}

void DescriptorSets::writeImage(size_t i, uint32_t binding, VkSampler sampler, VkImageView view,
                                VkImageLayout layout) const {
    writeImageInfo(i, binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {sampler, view, layout});
}

void DescriptorSets::writeStorageImage(size_t i, uint32_t binding, VkImageView view) const {
    writeImageInfo(i, binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                   {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL});
}

void DescriptorSets::writeAccelerationStructure(size_t i, uint32_t binding,
                                                VkAccelerationStructureKHR structure) const {
    VkWriteDescriptorSetAccelerationStructureKHR info{
        VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET_ACCELERATION_STRUCTURE_KHR};
    info.accelerationStructureCount = 1;
    info.pAccelerationStructures = &structure;
    // The structure travels in the chain, not in an info pointer of the write.
    VkWriteDescriptorSet w = write(i, binding, VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR);
    w.pNext = &info;
    vkUpdateDescriptorSets(mDevice, 1, &w, 0, nullptr);
}

} // namespace sb
