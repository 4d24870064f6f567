#include "techniques/vulkan/VulkanReceiverStencil.h"

#include <algorithm>

#include "techniques/vulkan/VulkanTechnique.h"

namespace sb {

void VulkanReceiverStencil::setPlanes(const std::vector<ReceiverPlane>& planes) {
    mCorners.clear();
    for (const ReceiverPlane& p : planes) mCorners.insert(mCorners.end(), p.corners.begin(), p.corners.end());
    mVertices = VulkanBuffer();
}

VkStencilOpState VulkanReceiverStencil::stencilOps(VkCompareOp compare, VkStencilOp passOp) {
    VkStencilOpState s{};
    s.failOp = VK_STENCIL_OP_KEEP;
    s.passOp = passOp;
    s.depthFailOp = VK_STENCIL_OP_KEEP;
    s.compareOp = compare;
    s.compareMask = 0xff;
    s.writeMask = 0xff;
    return s;
}

void VulkanReceiverStencil::compile(const VulkanCompileContext& ctx, VkPipelineLayout layout) {
    if (!mVertices) {
        const std::vector<glm::vec3> one(1, glm::vec3(0.0f)); // a buffer needs a size
        const std::vector<glm::vec3>& v = mCorners.empty() ? one : mCorners;
        mVertices = VulkanBuffer(ctx.context, v.size() * sizeof(glm::vec3), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT,
                                 v.data());
    }
    mLayout = layout;
    GraphicsPipelineDesc d;
    const ShaderModules modules =
        ctx.shaders.get(ShaderSources{"common/receiver.vert", "common/receiver.frag", ""}, {});
    d.vertex = modules.vertex;
    d.fragment = modules.fragment;
    d.bindings = {{0, sizeof(glm::vec3), VK_VERTEX_INPUT_RATE_VERTEX}};
    d.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}};
    d.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_FAN;
    d.layout = layout;
    d.depthBias = true;
    d.depthBiasSlope = kOffsetFactor;
    d.depthBiasConstant = kOffsetUnits;
    d.depthWrite = false;
    d.depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
    d.colourWrite = 0;
    d.visibilityWrite = false;
    d.stencilTest = true;
    d.stencilFront = d.stencilBack = stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_REPLACE);
    d.dynamicStencilReference = true;
    mPipeline.build(ctx.pipelines, "receiver-mark|common/receiver.vert+common/receiver.frag", d, ctx.targets);
}

void VulkanReceiverStencil::mark(VulkanFrameContext& ctx, size_t plane, uint32_t ref) const {
    vkCmdSetStencilReference(ctx.cmd, VK_STENCIL_FACE_FRONT_AND_BACK, ref);
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mPipeline.get(ctx.targets));
    const VkDeviceSize zero = 0;
    const VkBuffer vb = mVertices.buffer();
    vkCmdBindVertexBuffers(ctx.cmd, 0, 1, &vb, &zero);
    vkCmdDraw(ctx.cmd, 4, 1, uint32_t(plane * 4), 0);
}

void VulkanReceiverStencil::darkenState(GraphicsPipelineDesc& d, VkStencilOp passOp) {
    d.depthBias = true; // GL leaves the offset on; without a depth test it changes nothing
    d.depthBiasSlope = kOffsetFactor;
    d.depthBiasConstant = kOffsetUnits;
    d.depthTest = false;
    d.depthWrite = false;
    d.stencilTest = true;
    d.stencilFront = d.stencilBack = stencilOps(VK_COMPARE_OP_EQUAL, passOp);
    d.dynamicStencilReference = true;
    d.subtractColour = true;
    d.multiplyVisibility = true;
}

} // namespace sb
