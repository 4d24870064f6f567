#include "techniques/virtual/VirtualVulkan.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "core/Error.h"
#include "core/Strings.h"
#include "scenes/Motion.h"
#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/FlatLightFits.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/virtual/Virtual.h"
#include "techniques/vulkan/ScenePass.h"
#include "vk/LayerPasses.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
constexpr uint32_t kClearDepth = 0x3f800000u; // floatBitsToUint(1.0): nothing drawn, lit
/// std140 bytes of virtual/page_table.glsl's VirtualBlock: two mat4, an ivec4 and a vec4.
constexpr size_t kBlockBytes = 2 * 64 + 16 + 16;
constexpr VkImageSubresourceRange kColour{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkAccessFlags srcAccess,
                   VkPipelineStageFlags dst, VkAccessFlags dstAccess) {
    VkMemoryBarrier b{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, src, dst, 0, 1, &b, 0, nullptr, 0, nullptr);
}

void toGeneral(VkCommandBuffer cmd, VkImage image, uint32_t levels = 1) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, 1};
    b.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, 0,
                         nullptr, 0, nullptr, 1, &b);
}

VulkanImage r32ui(VulkanContext& context, int width, int height, VkImageUsageFlags usage) {
    VulkanImageDesc d;
    d.width = uint32_t(width);
    d.height = uint32_t(height);
    d.format = VK_FORMAT_R32_UINT;
    d.usage = usage;
    return VulkanImage(context, d);
}

void setViewport(VkCommandBuffer cmd, uint32_t width, uint32_t height) {
    const VkViewport viewport{0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
}

void setScissor(VkCommandBuffer cmd, int x, int y, int width, int height) {
    const VkRect2D scissor{{x, y}, {uint32_t(width), uint32_t(height)}};
    vkCmdSetScissor(cmd, 0, 1, &scissor);
}

} // namespace

VirtualVulkan::VirtualVulkan() : VulkanTechnique(Virtual::declaration()) {}

VirtualVulkan::~VirtualVulkan() {
    release();
}

void VirtualVulkan::release() {
    if (!mDevice) return;
    vkDestroyFramebuffer(mDevice, mMarkFramebuffer, nullptr);
    vkDestroyFramebuffer(mDevice, mPageFramebuffer, nullptr);
    vkDestroyRenderPass(mDevice, mMarkPass, nullptr);
    vkDestroyRenderPass(mDevice, mPagePass, nullptr);
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    vkDestroySampler(mDevice, mSampler, nullptr);
    mMarkFramebuffer = mPageFramebuffer = VK_NULL_HANDLE;
    mMarkPass = mPagePass = VK_NULL_HANDLE;
    mLayout = VK_NULL_HANDLE;
    mSampler = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    for (VulkanImage* image : {&mRequests, &mTable, &mAtlas, &mViewDepth}) *image = VulkanImage();
    for (VkImageView view : mLevelViews) vkDestroyImageView(mDevice, view, nullptr);
    mLevelViews.clear();
    vkDestroyImageView(mDevice, mSparseView, nullptr);
    vkDestroyImage(mDevice, mSparseImage, nullptr);
    vkFreeMemory(mDevice, mSparseMemory, nullptr);
    vkDestroyFence(mDevice, mBindFence, nullptr);
    mSparseView = VK_NULL_HANDLE;
    mSparseImage = VK_NULL_HANDLE;
    mSparseMemory = VK_NULL_HANDLE;
    mBindFence = VK_NULL_HANDLE;
    mBound.clear();
    for (VulkanBuffer* buffer : {&mMarks, &mTableWords, &mClearPage, &mBlock}) *buffer = VulkanBuffer();
    mDevice = VK_NULL_HANDLE;
}

std::string VirtualVulkan::sparseRefusal(const VulkanContext& context) const {
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(context.physicalDevice(), &features);
    std::vector<std::string> lacks;
    if (!features.sparseBinding) lacks.emplace_back("the feature sparseBinding");
    if (!features.sparseResidencyImage2D) lacks.emplace_back("the feature sparseResidencyImage2D");
    uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &families, nullptr);
    std::vector<VkQueueFamilyProperties> queues(families);
    vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice(), &families, queues.data());
    if (context.queueFamily() >= families ||
        !(queues[context.queueFamily()].queueFlags & VK_QUEUE_SPARSE_BINDING_BIT))
        lacks.emplace_back("VK_QUEUE_SPARSE_BINDING_BIT on the graphics queue");
    // The pages' format as a sparse storage image: the block must tile a page.
    uint32_t count = 0;
    const VkImageUsageFlags usage =
        VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    vkGetPhysicalDeviceSparseImageFormatProperties(context.physicalDevice(), VK_FORMAT_R32_UINT,
                                                   VK_IMAGE_TYPE_2D, VK_SAMPLE_COUNT_1_BIT, usage,
                                                   VK_IMAGE_TILING_OPTIMAL, &count, nullptr);
    std::vector<VkSparseImageFormatProperties> formats(count);
    vkGetPhysicalDeviceSparseImageFormatProperties(context.physicalDevice(), VK_FORMAT_R32_UINT,
                                                   VK_IMAGE_TYPE_2D, VK_SAMPLE_COUNT_1_BIT, usage,
                                                   VK_IMAGE_TILING_OPTIMAL, &count, formats.data());
    const uint32_t page = uint32_t(Virtual::geometry(properties()).pageSize());
    if (count == 0) {
        lacks.emplace_back("sparse R32_UINT storage images (no sparse format properties)");
    } else {
        const VkExtent3D block = formats[0].imageGranularity;
        if (page != block.width || page != block.height)
            lacks.push_back("a sparse block of page_size " + std::to_string(page) +
                            " texels a side (the device's is " + std::to_string(block.width) + "x" +
                            std::to_string(block.height) + ")");
    }
    if (lacks.empty() && !context.sparseResidency())
        lacks.emplace_back("a device created with sparseBinding and sparseResidencyImage2D");
    if (lacks.empty()) return "";
    return name() + ":path=sparse needs " + join(lacks, " and ") + " (not available on " +
           context.info().name + ", Vulkan " + context.info().apiVersion + "); path=atomic runs here";
}

std::string VirtualVulkan::checkCapabilities(const VulkanContext& context) const {
    std::string missing = VulkanTechnique::checkCapabilities(context);
    if (!missing.empty()) return missing;
    if (Virtual::sparse(properties())) return sparseRefusal(context);
    std::vector<std::string> lacks;
    if (!context.fragmentStoresAndAtomics()) lacks.emplace_back("the feature fragmentStoresAndAtomics");
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    const uint32_t side = uint32_t(Virtual::geometry(properties()).virtualResolution());
    if (limits.maxFramebufferWidth < side || limits.maxFramebufferHeight < side)
        lacks.push_back("maxFramebufferWidth and maxFramebufferHeight >= " + std::to_string(side) + " (has " +
                        std::to_string(limits.maxFramebufferWidth) + ")");
    if (limits.maxViewportDimensions[0] < side || limits.maxViewportDimensions[1] < side)
        lacks.push_back("maxViewportDimensions >= " + std::to_string(side) + " (has " +
                        std::to_string(limits.maxViewportDimensions[0]) + ")");
    if (lacks.empty()) return "";
    return name() + " needs " + join(lacks, " and ") + " (not available on " + context.info().name +
           ", Vulkan " + context.info().apiVersion + ")";
}

void VirtualVulkan::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), Virtual::declaration().passes);
}

void VirtualVulkan::setScene(const Scene& scene) {
    mMaps.setScene(scene, properties());
    mCulling.setScene(scene);
}

void VirtualVulkan::sceneChanged(const Scene& scene, uint32_t changes) {
    if (changes & kCastersMoved) mCulling.instancesMoved(scene);
    mMaps.sceneChanged(scene, changes);
}

void VirtualVulkan::createSparseMap(VulkanContext& context) {
    const PageGeometry& g = mMaps.geometry();
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.flags = VK_IMAGE_CREATE_SPARSE_BINDING_BIT | VK_IMAGE_CREATE_SPARSE_RESIDENCY_BIT;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = VK_FORMAT_R32_UINT;
    info.extent = {uint32_t(g.virtualResolution()), uint32_t(g.virtualResolution()), 1};
    info.mipLevels = uint32_t(g.levels());
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VulkanContext::check(vkCreateImage(mDevice, &info, nullptr, &mSparseImage),
                         "vkCreateImage (virtual sparse)");
    VkMemoryRequirements req{};
    vkGetImageMemoryRequirements(mDevice, mSparseImage, &req);
    // A page is one sparse block (sparseRefusal made sure): slot s's memory is block s of the pool.
    mPageBytes =
        std::max<VkDeviceSize>(req.alignment, VkDeviceSize(g.pageSize()) * VkDeviceSize(g.pageSize()) * 4);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = mPageBytes * VkDeviceSize(g.poolPages());
    alloc.memoryTypeIndex = context.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VulkanContext::check(vkAllocateMemory(mDevice, &alloc, nullptr, &mSparseMemory),
                         "vkAllocateMemory (virtual pool)");
    auto view = [&](uint32_t level, uint32_t count) {
        VkImageViewCreateInfo v{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        v.image = mSparseImage;
        v.viewType = VK_IMAGE_VIEW_TYPE_2D;
        v.format = VK_FORMAT_R32_UINT;
        v.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, count, 0, 1};
        VkImageView out = VK_NULL_HANDLE;
        VulkanContext::check(vkCreateImageView(mDevice, &v, nullptr, &out),
                             "vkCreateImageView (virtual sparse)");
        return out;
    };
    mSparseView = view(0, uint32_t(g.levels()));
    for (int l = 0; l < g.levels(); ++l) mLevelViews.push_back(view(uint32_t(l), 1));
    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VulkanContext::check(vkCreateFence(mDevice, &fence, nullptr, &mBindFence), "vkCreateFence (virtual)");
    mBound.assign(g.pageCount(), PageTable::kNoSlot);
}

void VirtualVulkan::bindPages() {
    const PageGeometry& g = mMaps.geometry();
    const PageTable& table = mMaps.cache().table();
    const uint32_t side = uint32_t(g.pageSize());
    // Unbinds first, then binds, each batch waited for: a slot handed from one page to another this
    // frame must leave the old page before it backs the new one (the image is not aliased).
    for (int pass = 0; pass < 2; ++pass) {
        std::vector<VkSparseImageMemoryBind> binds;
        for (uint32_t page = 0; page < g.pageCount(); ++page) {
            const uint32_t want = table.mapped(page) ? table.slot(page) : PageTable::kNoSlot;
            if (want == mBound[page]) continue;
            const bool unbind = mBound[page] != PageTable::kNoSlot;
            if ((pass == 0) != unbind) continue;
            const PageAddress a = g.address(page);
            VkSparseImageMemoryBind b{};
            b.subresource = {VK_IMAGE_ASPECT_COLOR_BIT, uint32_t(a.level), 0};
            b.offset = {a.page.x * int(side), a.page.y * int(side), 0};
            b.extent = {side, side, 1};
            if (pass == 0) {
                mBound[page] = PageTable::kNoSlot;
            } else {
                b.memory = mSparseMemory;
                b.memoryOffset = VkDeviceSize(want) * mPageBytes;
                mBound[page] = want;
            }
            binds.push_back(b);
        }
        if (binds.empty()) continue;
        const VkSparseImageMemoryBindInfo image{mSparseImage, uint32_t(binds.size()), binds.data()};
        VkBindSparseInfo info{VK_STRUCTURE_TYPE_BIND_SPARSE_INFO};
        info.imageBindCount = 1;
        info.pImageBinds = &image;
        VulkanContext::check(vkQueueBindSparse(mContext->queue(), 1, &info, mBindFence), "vkQueueBindSparse");
        VulkanContext::check(vkWaitForFences(mDevice, 1, &mBindFence, VK_TRUE, UINT64_MAX),
                             "vkWaitForFences");
        VulkanContext::check(vkResetFences(mDevice, 1, &mBindFence), "vkResetFences");
    }
}

void VirtualVulkan::createResources(const VulkanCompileContext& ctx) {
    VulkanContext& context = ctx.context;
    const PageGeometry& g = mMaps.geometry();
    constexpr VkImageUsageFlags transfer = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    mRequests = r32ui(context, g.pagesPerSide(), g.tableRows(), VK_IMAGE_USAGE_STORAGE_BIT | transfer);
    mTable = r32ui(context, g.pagesPerSide(), g.tableRows(), VK_IMAGE_USAGE_SAMPLED_BIT | transfer);
    mSparse = Virtual::sparse(properties());
    if (mSparse)
        createSparseMap(context);
    else
        mAtlas = r32ui(context, g.atlasResolution(), g.atlasResolution(),
                       VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | transfer);
    VulkanImageDesc depth;
    mViewExtent = {uint32_t(ctx.targets.width()), uint32_t(ctx.targets.height())};
    depth.width = mViewExtent.width;
    depth.height = mViewExtent.height;
    depth.format = VK_FORMAT_D32_SFLOAT;
    depth.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    depth.aspect = VK_IMAGE_ASPECT_DEPTH_BIT;
    mViewDepth = VulkanImage(context, depth);
    context.submitNow([&](VkCommandBuffer cmd) {
        for (const VulkanImage* image : {&mRequests, &mTable}) toGeneral(cmd, image->image());
        toGeneral(cmd, mSparse ? mSparseImage : mAtlas.image(), mSparse ? uint32_t(g.levels()) : 1u);
        const VkClearColorValue zero{};
        vkCmdClearColorImage(cmd, mTable.image(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &kColour);
    });
    const size_t words = size_t(g.pagesPerSide()) * size_t(g.tableRows());
    mMarks = VulkanBuffer(context, words * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    mTableWords = VulkanBuffer(context, words * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    const std::vector<uint32_t> page(size_t(g.pageSize()) * size_t(g.pageSize()), kClearDepth);
    mClearPage = VulkanBuffer(context, page.size() * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, page.data());
    mBlock = VulkanBuffer(context, kBlockBytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);

    mSampler = LayerPasses::sampler(mDevice, {VK_FILTER_NEAREST, false, false}, "virtual");
    using D = DescriptorSets;
    constexpr VkShaderStageFlags both = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    constexpr VkShaderStageFlags fragment = VK_SHADER_STAGE_FRAGMENT_BIT;
    // One set on the atomic path; on the sparse path one per level, identical but for binding 2, the
    // level the page pass writes (a storage view is of one level).
    const DescriptorSets::Bindings bindings = {
        D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, both),
        D::binding(1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, fragment),
        D::binding(2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, fragment),
        D::binding(3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, fragment),
        D::binding(4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, fragment)};
    const size_t sets = mSparse ? size_t(g.levels()) : 1;
    mSets = DescriptorSets(mDevice, std::vector<DescriptorSets::Bindings>(sets, bindings), "virtual");
    for (size_t i = 0; i < sets; ++i) {
        mSets.writeBuffer(i, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mBlock.buffer(), mBlock.size());
        mSets.writeStorageImage(i, 1, mRequests.view());
        mSets.writeStorageImage(i, 2, mSparse ? mLevelViews[i] : mAtlas.view());
        mSets.writeImage(i, 3, mSampler, mSparse ? mSparseView : mAtlas.view(), VK_IMAGE_LAYOUT_GENERAL);
        mSets.writeImage(i, 4, mSampler, mTable.view(), VK_IMAGE_LAYOUT_GENERAL);
    }
    mContact.compile(properties(), ctx);
    mLayout = createScenePipelineLayout(ctx, mContact.lightingSets({mSets.layout(0)}));

    // The marking pass: the view's depth, then the marks' stores; after it the marks are copied out.
    LayerPasses::PassDesc mark;
    mark.depth = LayerPasses::Attachment{VK_FORMAT_D32_SFLOAT, VK_ATTACHMENT_LOAD_OP_CLEAR,
                                         VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                         VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    mark.before = {VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                   VK_ACCESS_TRANSFER_WRITE_BIT,
                   VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    mark.after = {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT};
    mMarkPass = LayerPasses::renderPass(mDevice, mark, "virtual marking");
    const VkImageView depthView = mViewDepth.view();
    mMarkFramebuffer =
        LayerPasses::framebuffer(mDevice, mMarkPass, {&depthView, 1}, mViewExtent, 1, "virtual marking");
    // The page pass: no attachment; the atlas's copies before it, the lighting pass's reads after it.
    LayerPasses::PassDesc pages;
    pages.before = {VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT};
    pages.after = {VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                   VK_ACCESS_SHADER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT};
    mPagePass = LayerPasses::renderPass(mDevice, pages, "virtual pages");
    const uint32_t side = uint32_t(mMaps.geometry().virtualResolution());
    mPageFramebuffer = LayerPasses::framebuffer(mDevice, mPagePass, {}, {side, side}, 1, "virtual pages");
}

void VirtualVulkan::createPipelines(const VulkanCompileContext& ctx) {
    const Defines mark = ctx.defines();
    std::string key = "virtual-mark|";
    GraphicsPipelineDesc d = scenePipeline(ctx, "common/scene.vert", "virtual/mark.frag", mark, mLayout, key);
    d.colourAttachments = 0;
    d.renderPass = mMarkPass;
    mMarkDepth = ctx.pipelines.get(key + "|less", d);
    d.depthCompare = VK_COMPARE_OP_EQUAL;
    d.depthWrite = false;
    mMarkEqual = ctx.pipelines.get(key + "|equal", d);
    Defines depth = ctx.submitter.defines();
    if (mSparse) depth["VIRTUAL_SPARSE"] = "";
    std::string pageKey = "virtual-pages|";
    GraphicsPipelineDesc p =
        scenePipeline(ctx, "common/depth.vert", "virtual/page_depth.frag", depth, mLayout, pageKey);
    p.colourAttachments = 0;
    p.depthTest = p.depthWrite = false;
    p.depthClamp = ctx.context.depthClamp(); // casters nearer the light than the fit still shadow
    p.renderPass = mPagePass;
    mPages = ctx.pipelines.get(pageKey + (p.depthClamp ? "|clamp" : ""), p);
    Defines lit = ctx.defines();
    if (mSparse) lit["VIRTUAL_SPARSE"] = "";
    ContactShadows::addDefines(properties(), lit);
    lit["LIGHT_COUNT"] = std::to_string(std::max<size_t>(1, ctx.scene.lights.size()));
    lit["MAPPED_LIGHT"] = std::to_string(mMaps.light());
    setPermutationKey(definesKey(mark) + "|" + definesKey(depth) + "|" +
                      mLighting.build(ctx, "common/scene.vert", "virtual/lighting.frag", lit, mLayout,
                                      "virtual-lighting|"));
}

void VirtualVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mContext = &ctx.context;
    mDevice = ctx.context.device();
    const std::string missing = checkCapabilities(ctx.context);
    if (!missing.empty()) throw Error(missing, ExitCode::Unsupported);
    createResources(ctx);
    createPipelines(ctx);
    writeBlock();
}

void VirtualVulkan::writeBlock() {
    const glm::mat4 m[2] = {VulkanFrameBlock::depthFromGl() * mMaps.lightViewProj(),
                            FlatLightFits::textureBias() * mMaps.lightViewProj()};
    const Virtual::PageUniforms u = Virtual::pageUniforms(properties());
    char* base = static_cast<char*>(mBlock.map());
    std::memcpy(base, m, sizeof m);
    std::memcpy(base + 128, &u.geometry, sizeof u.geometry);
    std::memcpy(base + 144, &u.lod, sizeof u.lod);
}

void VirtualVulkan::markAndAllocate(VulkanFrameContext& ctx) {
    const PageGeometry& g = mMaps.geometry();
    const VkDescriptorSet set = mSets.set(0);
    mContext->submitNow([&](VkCommandBuffer cmd) {
        const VkClearColorValue zero{};
        vkCmdClearColorImage(cmd, mRequests.image(), VK_IMAGE_LAYOUT_GENERAL, &zero, 1, &kColour);
        VkClearValue clear{};
        clear.depthStencil = {1.0f, 0};
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = mMarkPass;
        begin.framebuffer = mMarkFramebuffer;
        begin.renderArea = {{0, 0}, mViewExtent};
        begin.clearValueCount = 1;
        begin.pClearValues = &clear;
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        setViewport(cmd, mViewExtent.width, mViewExtent.height);
        setScissor(cmd, 0, 0, int(mViewExtent.width), int(mViewExtent.height));
        // The receivers' depth, then the same draws where the depth is equal: only the visible
        // fragment of each pixel marks (mark.frag's early fragment tests), as on GL.
        VulkanPush push;
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mMarkDepth);
        ctx.frame.bind(cmd, mLayout, ctx.frameOffset);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, 1, 1, &set, 0, nullptr);
        ctx.submitter.drawCulled(cmd, mLayout, DrawSet::Receivers, cameraCullView(ctx), true, {}, push);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mMarkEqual);
        push.ints.y = 1;
        ctx.submitter.drawCulled(cmd, mLayout, DrawSet::Receivers, cameraCullView(ctx), true, {}, push);
        vkCmdEndRenderPass(cmd);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {uint32_t(g.pagesPerSide()), uint32_t(g.tableRows()), 1};
        vkCmdCopyImageToBuffer(cmd, mRequests.image(), VK_IMAGE_LAYOUT_GENERAL, mMarks.buffer(), 1, &copy);
        memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                      VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
    });
    mMaps.allocate(static_cast<const uint32_t*>(mMarks.map()), properties().getBool(Virtual::kCache), mWords);
    std::memcpy(mTableWords.map(), mWords.data(), mWords.size() * 4);
    if (mSparse) bindPages();
}

void VirtualVulkan::recordPages(VulkanFrameContext& ctx) {
    const PageGeometry& g = mMaps.geometry();
    VkCommandBuffer cmd = ctx.cmd;
    // The last frame's lighting read the table and the atlas: their copies wait for it.
    memoryBarrier(cmd, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy table{};
    table.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    table.imageExtent = {uint32_t(g.pagesPerSide()), uint32_t(g.tableRows()), 1};
    vkCmdCopyBufferToImage(cmd, mTableWords.buffer(), mTable.image(), VK_IMAGE_LAYOUT_GENERAL, 1, &table);
    std::vector<VkBufferImageCopy> clears;
    for (uint32_t page : mMaps.cache().renderList()) {
        // The atomic path clears the page's slot in the atlas; the sparse path the page itself, at its
        // level of the map (its slot's memory bound there).
        const PageAddress a = g.address(page);
        const glm::ivec2 o =
            mSparse ? a.page * g.pageSize() : g.atlasOrigin(mMaps.cache().table().slot(page));
        VkBufferImageCopy c{};
        c.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, mSparse ? uint32_t(a.level) : 0u, 0, 1};
        c.imageOffset = {o.x, o.y, 0};
        c.imageExtent = {uint32_t(g.pageSize()), uint32_t(g.pageSize()), 1};
        clears.push_back(c);
    }
    if (!clears.empty())
        vkCmdCopyBufferToImage(cmd, mClearPage.buffer(), mSparse ? mSparseImage : mAtlas.image(),
                               VK_IMAGE_LAYOUT_GENERAL, uint32_t(clears.size()), clears.data());
    memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                  VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    VulkanPush push;
    push.vec = glm::vec4(float(properties().getFloat(P::kBiasConstant)),
                         float(properties().getFloat(P::kBiasSlope)), 0.0f, 0.0f);
    for (const PageRun& run : mMaps.runs()) {
        const VkDescriptorSet set = mSets.set(mSparse ? size_t(run.level) : 0); // sparse: the level's view
        // A render pass per run whose render area is the run: lavapipe works over the render area, and a
        // pass over the whole 16k^2 framebuffer cost seconds a frame with many draws.
        const VkRect2D area{{run.first.x * g.pageSize(), run.first.y * g.pageSize()},
                            {uint32_t(run.count * g.pageSize()), uint32_t(g.pageSize())}};
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = mPagePass;
        begin.framebuffer = mPageFramebuffer;
        begin.renderArea = area;
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPages);
        ctx.frame.bind(cmd, mLayout, ctx.frameOffset);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, 1, 1, &set, 0, nullptr);
        setViewport(cmd, uint32_t(g.levelResolution(run.level)), uint32_t(g.levelResolution(run.level)));
        setScissor(cmd, area.offset.x, area.offset.y, int(area.extent.width), int(area.extent.height));
        push.ints.y = run.level;
        mCulling.cull(run.crop(g) * mMaps.lightViewProj(), DrawSet::Casters, CullPlanes::SidesAndFar, mKeep);
        ctx.submitter.drawCulled(cmd, mLayout, DrawSet::Casters, {mMaps.lightViewProj(), true}, false, mKeep,
                                 push);
        vkCmdEndRenderPass(cmd);
    }
    mMaps.rendered();
}

void VirtualVulkan::execute(VulkanFrameContext& ctx) {
    mMaps.texels().setCamera(ctx.proj * ctx.view, {ctx.targets.width(), ctx.targets.height()});
    writeBlock();
    const SubmitStats s = DepthLightingFrame::run(
        ctx,
        [&] {
            if (mMaps.light() < 0) return;
            markAndAllocate(ctx);
            recordPages(ctx);
        },
        [&] {
            mContact.bind(ctx.cmd, mLayout);
            mLighting.draw(ctx, mLayout, mSets.set(0));
        },
        mContact.prePass(ctx), ContactShadows::kPass);
    mCounters = mMaps.counters(s);
}

} // namespace sb
