#pragma once
// `virtual` on Vulkan, the atomic path (NOTES-virtual.md): VirtualGL's passes with the same
// declaration, VirtualMaps (the light, the cache, the CPU allocation, the runs) and shaders
// (shaders/virtual/, their `#ifdef VULKAN` blocks), recorded into the frame's command buffer.
//
// The marks must reach the CPU before the frame's pages can be chosen, and the frame's command buffer
// is submitted only after execute() returns: so the view's depth and the marks are drawn in a command
// buffer of their own, submitted and waited for at once (VulkanContext::submitNow; its GPU time is
// outside the frame's timestamps, its wall time inside pass "depth"), into a depth image of the
// targets' size and the request image, copied to a host-visible buffer. Then, in the frame's command
// buffer: the table copied from a host-visible buffer into its image, each drawn page's slot cleared by
// a copy of a page of 1.0 (vkCmdClearColorImage clears whole images only), the page pass (a render pass
// without attachments of virtual_resolution^2, the casters of each run under its scissor, each fragment
// an imageAtomicMin into the atlas), and the lighting pass. Every image stays in the general layout.
// Needs fragmentStoresAndAtomics and a framebuffer and viewport of virtual_resolution texels; a device
// without them is refused naming what is missing. path=sparse: the map one sparse-resident R32_UINT
// image (levels as mips) instead of the atlas, each page bound to its slot's block of one pool
// allocation by vkQueueBindSparse (the table's changes each frame), written and read at its own texels
// (shaders/virtual/*'s VIRTUAL_SPARSE); refused where the device lacks sparse residency (sparseRefusal).
#include <cstdint>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "scenes/InstanceCulling.h"
#include "techniques/virtual/VirtualMaps.h"
#include "techniques/vulkan/ContactShadowsVulkan.h"
#include "techniques/vulkan/LitPipelines.h"
#include "techniques/vulkan/VulkanTechnique.h"
#include "vk/DescriptorSets.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

class VirtualVulkan final : public VulkanTechnique {
public:
    VirtualVulkan();
    ~VirtualVulkan() override;
    std::string checkCapabilities(const VulkanContext& context) const override;
    void propertiesApplied() override; ///< contact=on's pass "view_depth"
    void setScene(const Scene& scene) override;
    void sceneChanged(const Scene& scene, uint32_t changes) override;
    void compile(const VulkanCompileContext& ctx) override;
    void execute(VulkanFrameContext& ctx) override;
    Counters counters() const override { return mCounters; }
    const MapTexels* mapTexels() const override { return &mMaps.texels(); }
    /// The last frame's page counts (also in counters()).
    const PageCounts& pageCounts() const { return mMaps.counts(); }

private:
    /// path=sparse: what the device lacks for sparse residency, each by name; "" where it has it all.
    std::string sparseRefusal(const VulkanContext& context) const;
    void release();
    /// path=sparse: the map as one sparse-resident R32_UINT image, its levels as mips, and the pool as one
    /// allocation of pool_pages blocks; a storage view per level, a sampled view of all.
    void createSparseMap(VulkanContext& context);
    /// path=sparse: the table's changes since the last frame as sparse binds (unbinds first), waited for.
    void bindPages();
    void createResources(const VulkanCompileContext& ctx);
    void createPipelines(const VulkanCompileContext& ctx);
    void writeBlock();
    /// The view's depth and the marks in a command buffer of their own, waited for; then allocation.
    void markAndAllocate(VulkanFrameContext& ctx);
    void recordPages(VulkanFrameContext& ctx);

    VulkanContext* mContext = nullptr;
    VkDevice mDevice = VK_NULL_HANDLE;
    VirtualMaps mMaps;
    InstanceCulling mCulling;
    std::vector<uint8_t> mKeep;
    std::vector<uint32_t> mWords;
    VulkanImage mRequests;    ///< R32UI, a texel per page (PageGeometry::tableRows rows): 1 where marked
    VulkanImage mTable;       ///< R32UI, the same layout: PageTable::packed
    VulkanImage mAtlas;       ///< R32UI, the pool's slots: depth bits
    VulkanImage mViewDepth;   ///< the marking pass's depth, the targets' size
    VulkanBuffer mMarks;      ///< host-visible: mRequests read back
    VulkanBuffer mTableWords; ///< host-visible: the table to copy into mTable
    VulkanBuffer mClearPage;  ///< a page of floatBitsToUint(1.0)
    VulkanBuffer mBlock;      ///< VirtualBlock: depthFromGl * viewProj, then bias * viewProj
    VkSampler mSampler = VK_NULL_HANDLE;
    DescriptorSets mSets;
    VkPipelineLayout mLayout = VK_NULL_HANDLE;
    VkRenderPass mMarkPass = VK_NULL_HANDLE, mPagePass = VK_NULL_HANDLE;
    VkFramebuffer mMarkFramebuffer = VK_NULL_HANDLE, mPageFramebuffer = VK_NULL_HANDLE;
    VkPipeline mMarkDepth = VK_NULL_HANDLE, mMarkEqual = VK_NULL_HANDLE, mPages = VK_NULL_HANDLE; ///< cached
    LitPipelines mLighting;
    ContactShadowsVulkan mContact; ///< contact=on: the view depth pre-pass and its set 2
    VkExtent2D mViewExtent{0, 0};
    bool mSparse = false;
    VkImage mSparseImage = VK_NULL_HANDLE;
    VkDeviceMemory mSparseMemory = VK_NULL_HANDLE;
    VkImageView mSparseView = VK_NULL_HANDLE;
    std::vector<VkImageView> mLevelViews;
    VkFence mBindFence = VK_NULL_HANDLE;
    VkDeviceSize mPageBytes = 0;
    std::vector<uint32_t> mBound; ///< per page: the slot whose memory is bound to it, or PageTable::kNoSlot
    Counters mCounters;
};

} // namespace sb
