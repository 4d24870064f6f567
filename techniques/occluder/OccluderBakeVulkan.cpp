#include "techniques/occluder/OccluderBakeVulkan.h"

#include <array>
#include <cstring>

#include <glm/glm.hpp>

#include "core/Error.h"
#include "vk/GraphicsPipeline.h"
#include "vk/LayerPasses.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanImage.h"

namespace sb {

namespace {

const ShaderSources kBakeSources{"occluder/bake.vert", "occluder/bake.frag", ""};

/// bake.vert's BakePush (std430: each vec3 takes 16 bytes).
struct BakePush {
    glm::vec4 origin, right, up, normal;
};

VkStencilOpState stencilOps(VkCompareOp compare, VkStencilOp pass) {
    VkStencilOpState s{};
    s.failOp = s.depthFailOp = VK_STENCIL_OP_KEEP;
    s.passOp = pass;
    s.compareOp = compare;
    s.compareMask = s.writeMask = 0xff;
    return s;
}

/// Colour R8 (cleared white, then copied out) and a stencil (cleared 0) in one subpass.
VkRenderPass createRenderPass(VkDevice device, VkFormat stencil) {
    std::array<VkAttachmentDescription, 2> a{};
    a[0].format = VK_FORMAT_R8_UNORM;
    a[0].samples = VK_SAMPLE_COUNT_1_BIT;
    a[0].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    a[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    a[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    a[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a[0].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    a[0].finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    a[1].format = stencil;
    a[1].samples = VK_SAMPLE_COUNT_1_BIT;
    a[1].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    a[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a[1].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    a[1].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    a[1].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    a[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    const VkAttachmentReference colour{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference depth{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription sub{};
    sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    sub.colorAttachmentCount = 1;
    sub.pColorAttachments = &colour;
    sub.pDepthStencilAttachment = &depth;
    // The copy after the pass waits for the colour writes.
    VkSubpassDependency dep{};
    dep.srcSubpass = 0;
    dep.dstSubpass = VK_SUBPASS_EXTERNAL;
    dep.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dep.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dep.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dep.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    info.attachmentCount = uint32_t(a.size());
    info.pAttachments = a.data();
    info.subpassCount = 1;
    info.pSubpasses = &sub;
    info.dependencyCount = 1;
    info.pDependencies = &dep;
    VkRenderPass pass = VK_NULL_HANDLE;
    VulkanContext::check(vkCreateRenderPass(device, &info, nullptr, &pass),
                         "vkCreateRenderPass (occluder bake)");
    return pass;
}

/// The three pipelines of the bake, as OccluderTextures::bake sets GL's state for each draw.
struct BakePipelines {
    VkPipeline draw = VK_NULL_HANDLE, clipped = VK_NULL_HANDLE, fill = VK_NULL_HANDLE;
};

BakePipelines createPipelines(VulkanContext& context, ShaderModuleCache& shaders, VkRenderPass pass,
                              VkPipelineLayout layout) {
    GraphicsPipelineDesc base;
    base.depthTest = base.depthWrite = false;
    base.colourAttachments = 1;
    base.renderPass = pass;
    base.layout = layout;
    base.bindings = {{0, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX}};
    base.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}};
    BakePipelines p;
    // The silhouette: both facings, black on white.
    GraphicsPipelineDesc draw = base;
    const ShaderModules plain = shaders.get(kBakeSources, {});
    draw.vertex = plain.vertex;
    draw.fragment = plain.fragment;
    p.draw = createGraphicsPipeline(context, draw);
    // The cross-section's marking: clipped to the normal's side, no colour, two-sided wrapping counts.
    GraphicsPipelineDesc clipped = base;
    const ShaderModules clip = shaders.get(kBakeSources, {{"BAKE_CLIP", ""}});
    clipped.vertex = clip.vertex;
    clipped.fragment = clip.fragment;
    clipped.colourWrite = 0;
    clipped.stencilTest = true;
    clipped.stencilFront = stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_INCREMENT_AND_WRAP);
    clipped.stencilBack = stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_DECREMENT_AND_WRAP);
    p.clipped = createGraphicsPipeline(context, clipped);
    // The fill: a full-screen triangle where the count is not 0.
    GraphicsPipelineDesc fill = base;
    const ShaderModules full = shaders.get(kBakeSources, {{"BAKE_FULLSCREEN", ""}});
    fill.vertex = full.vertex;
    fill.fragment = full.fragment;
    fill.bindings.clear();
    fill.attributes.clear();
    fill.stencilTest = true;
    fill.stencilFront = fill.stencilBack = stencilOps(VK_COMPARE_OP_NOT_EQUAL, VK_STENCIL_OP_KEEP);
    p.fill = createGraphicsPipeline(context, fill);
    return p;
}

} // namespace

std::vector<uint8_t> OccluderBakeVulkan::bake(VulkanContext& context, ShaderModuleCache& shaders,
                                              const Mesh& mesh, const ShadowPlane& plane,
                                              const OccluderBakeOptions& options) {
    OccluderTexels::validate(mesh, plane, options);
    const std::vector<MeshPart> parts = OccluderTexels::parts(mesh, plane);
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(context.physicalDevice(), &features);
    if (options.crossSection && !features.shaderClipDistance)
        throw Error("occluder: the texture bake's cross-section needs shaderClipDistance, which '" +
                        context.info().name + "' lacks",
                    ExitCode::Unsupported);
    const VkDevice device = context.device();
    const uint32_t n = uint32_t(options.resolution);
    const VkFormat stencilFormat = context.depthStencilFormat();
    VulkanImageDesc colourDesc;
    colourDesc.width = colourDesc.height = n;
    colourDesc.format = VK_FORMAT_R8_UNORM;
    colourDesc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    VulkanImage colour(context, colourDesc);
    VulkanImageDesc stencilDesc = colourDesc;
    stencilDesc.format = stencilFormat;
    stencilDesc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    stencilDesc.aspect = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    VulkanImage stencil(context, stencilDesc);

    const VkRenderPass pass = createRenderPass(device, stencilFormat);
    const std::array<VkImageView, 2> views{colour.view(), stencil.view()};
    const VkFramebuffer framebuffer =
        LayerPasses::framebuffer(device, pass, views, {n, n}, 1, "occluder bake");
    const VkPipelineLayout layout = createPipelineLayout(context, {}, sizeof(BakePush));
    const BakePipelines pipelines = createPipelines(context, shaders, pass, layout);

    // Storage of at least one element: a zero-size buffer is invalid.
    const glm::vec3 nowhere(0.0f);
    const uint32_t noIndex = 0;
    VulkanBuffer vertices(context, std::max<size_t>(1, mesh.positions.size()) * sizeof(glm::vec3),
                          VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                          mesh.positions.empty() ? &nowhere : mesh.positions.data());
    VulkanBuffer indices(context, std::max<size_t>(1, mesh.indices.size()) * sizeof(uint32_t),
                         VK_BUFFER_USAGE_INDEX_BUFFER_BIT,
                         mesh.indices.empty() ? &noIndex : mesh.indices.data());
    VulkanBuffer readBack(context, VkDeviceSize(n) * n, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    const BakePush push{glm::vec4(plane.origin, 0.0f), glm::vec4(plane.right / plane.width, 0.0f),
                        glm::vec4(plane.up / plane.height, 0.0f), glm::vec4(plane.normal, 0.0f)};

    context.submitNow([&](VkCommandBuffer cmd) {
        std::array<VkClearValue, 2> clear{};
        clear[0].color = {{1.0f, 1.0f, 1.0f, 1.0f}};
        clear[1].depthStencil = {1.0f, 0};
        VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
        begin.renderPass = pass;
        begin.framebuffer = framebuffer;
        begin.renderArea.extent = {n, n};
        begin.clearValueCount = uint32_t(clear.size());
        begin.pClearValues = clear.data();
        vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
        const VkViewport viewport{0.0f, 0.0f, float(n), float(n), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, {n, n}};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        vkCmdPushConstants(cmd, layout, kPushConstantStages, 0, sizeof push, &push);
        const VkDeviceSize zero = 0;
        const VkBuffer vb = vertices.buffer();
        vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &zero);
        vkCmdBindIndexBuffer(cmd, indices.buffer(), 0, VK_INDEX_TYPE_UINT32);
        if (options.silhouette) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.draw);
            for (const MeshPart& part : parts)
                if (part.indexCount > 0) vkCmdDrawIndexed(cmd, part.indexCount, 1, part.firstIndex, 0, 0);
        }
        if (options.crossSection) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.clipped);
            if (!mesh.indices.empty()) vkCmdDrawIndexed(cmd, uint32_t(mesh.indices.size()), 1, 0, 0, 0);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.fill);
            vkCmdDraw(cmd, 3, 1, 0, 0);
        }
        vkCmdEndRenderPass(cmd);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
        copy.imageExtent = {n, n, 1};
        vkCmdCopyImageToBuffer(cmd, colour.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readBack.buffer(),
                               1, &copy);
        VkMemoryBarrier host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
        host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
        host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
        vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0,
                             nullptr, 0, nullptr);
    });
    std::vector<uint8_t> texels(size_t(n) * n);
    std::memcpy(texels.data(), readBack.map(), texels.size());

    vkDestroyPipeline(device, pipelines.draw, nullptr);
    vkDestroyPipeline(device, pipelines.clipped, nullptr);
    vkDestroyPipeline(device, pipelines.fill, nullptr);
    vkDestroyPipelineLayout(device, layout, nullptr);
    vkDestroyFramebuffer(device, framebuffer, nullptr);
    vkDestroyRenderPass(device, pass, nullptr);
    return OccluderTexels::dilate(texels, int(n), int(n), options.dilate);
}

} // namespace sb
