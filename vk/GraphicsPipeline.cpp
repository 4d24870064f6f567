#include "vk/GraphicsPipeline.h"

#include "vk/PipelineLayout.h"
#include "vk/VulkanContext.h"

namespace sb {

VkPipeline createGraphicsPipeline(VulkanContext& context, const GraphicsPipelineDesc& desc) {
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    auto addStage = [&](VkShaderStageFlagBits stage, VkShaderModule module) {
        if (!module) return;
        VkPipelineShaderStageCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
        info.stage = stage;
        info.module = module;
        info.pName = "main";
        stages.push_back(info);
    };
    addStage(VK_SHADER_STAGE_VERTEX_BIT, desc.vertex);
    addStage(VK_SHADER_STAGE_GEOMETRY_BIT, desc.geometry);
    addStage(VK_SHADER_STAGE_MESH_BIT_EXT, desc.mesh);
    addStage(VK_SHADER_STAGE_FRAGMENT_BIT, desc.fragment);

    VkPipelineVertexInputStateCreateInfo vertexInput{
        VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertexInput.vertexBindingDescriptionCount = static_cast<uint32_t>(desc.bindings.size());
    vertexInput.pVertexBindingDescriptions = desc.bindings.data();
    vertexInput.vertexAttributeDescriptionCount = static_cast<uint32_t>(desc.attributes.size());
    vertexInput.pVertexAttributeDescriptions = desc.attributes.data();

    VkPipelineInputAssemblyStateCreateInfo assembly{
        VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = desc.topology;

    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1; // dynamic: set per pass
    viewport.scissorCount = 1;

    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.depthClampEnable = desc.depthClamp ? VK_TRUE : VK_FALSE;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = desc.cull;
    raster.frontFace = desc.frontFace;
    raster.depthBiasEnable = desc.depthBias ? VK_TRUE : VK_FALSE;
    raster.depthBiasConstantFactor = desc.depthBiasConstant;
    raster.depthBiasSlopeFactor = desc.depthBiasSlope;
    raster.lineWidth = 1.0f;

    VkPipelineMultisampleStateCreateInfo multisample{
        VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = desc.depthTest ? VK_TRUE : VK_FALSE;
    depth.depthWriteEnable = desc.depthWrite ? VK_TRUE : VK_FALSE;
    depth.depthCompareOp = desc.depthCompare;
    depth.stencilTestEnable = desc.stencilTest ? VK_TRUE : VK_FALSE;
    depth.front = desc.stencilFront;
    depth.back = desc.stencilBack;
    depth.depthBoundsTestEnable = desc.depthBounds ? VK_TRUE : VK_FALSE;
    depth.minDepthBounds = 0.0f;
    depth.maxDepthBounds = 1.0f;

    std::vector<VkPipelineColorBlendAttachmentState> blends(desc.colourAttachments);
    for (uint32_t i = 0; i < desc.colourAttachments; ++i) {
        VkPipelineColorBlendAttachmentState& blend = blends[i];
        blend.colorWriteMask = i == 0   ? desc.colourWrite
                               : i == 1 ? (desc.visibilityWrite ? VkColorComponentFlags(0xF) : 0)
                                        : VkColorComponentFlags(0xF);
        if (i == 0 && desc.additive) { // ONE + ONE (light passes)
            blend.blendEnable = VK_TRUE;
            blend.srcColorBlendFactor = blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.dstColorBlendFactor = blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.colorBlendOp = blend.alphaBlendOp = VK_BLEND_OP_ADD;
        } else if (i == 0 && desc.subtractColour) { // dst - src: a light's term removed (planar, blob)
            blend.blendEnable = VK_TRUE;
            blend.srcColorBlendFactor = blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.dstColorBlendFactor = blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.colorBlendOp = blend.alphaBlendOp = VK_BLEND_OP_REVERSE_SUBTRACT;
        } else if (i == 1 && desc.multiplyVisibility) { // dst * src: src * DST_COLOR + dst * ZERO
            blend.blendEnable = VK_TRUE;
            blend.srcColorBlendFactor = VK_BLEND_FACTOR_DST_COLOR;
            blend.dstColorBlendFactor = VK_BLEND_FACTOR_ZERO;
            blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_DST_ALPHA;
            blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ZERO;
            blend.colorBlendOp = blend.alphaBlendOp = VK_BLEND_OP_ADD;
        } else if (i == 1 && desc.maxVisibility) { // max(src, dst): MAX ignores the factors
            blend.blendEnable = VK_TRUE;
            blend.srcColorBlendFactor = blend.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.dstColorBlendFactor = blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
            blend.colorBlendOp = blend.alphaBlendOp = VK_BLEND_OP_MAX;
        }
    }
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = desc.colourAttachments;
    blend.pAttachments = blends.data();

    // Dynamic state: viewport and scissor always; the stencil reference and the depth bounds where the
    // pipeline asks for them.
    std::vector<VkDynamicState> dynamics = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    if (desc.dynamicStencilReference) dynamics.push_back(VK_DYNAMIC_STATE_STENCIL_REFERENCE);
    if (desc.depthBounds) dynamics.push_back(VK_DYNAMIC_STATE_DEPTH_BOUNDS);
    if (desc.dynamicCull) {
        dynamics.push_back(VK_DYNAMIC_STATE_CULL_MODE);
        dynamics.push_back(VK_DYNAMIC_STATE_FRONT_FACE);
    }
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = uint32_t(dynamics.size());
    dynamic.pDynamicStates = dynamics.data();

    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.stageCount = static_cast<uint32_t>(stages.size());
    info.pStages = stages.data();
    // A mesh pipeline has neither state (the spec ignores them; null says so).
    info.pVertexInputState = desc.mesh ? nullptr : &vertexInput;
    info.pInputAssemblyState = desc.mesh ? nullptr : &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = desc.layout;
    info.renderPass = desc.renderPass;
    info.subpass = 0;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VulkanContext::check(
        vkCreateGraphicsPipelines(context.device(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
        "vkCreateGraphicsPipelines");
    return pipeline;
}

VkPipelineLayout createPipelineLayout(VulkanContext& context, const std::vector<VkDescriptorSetLayout>& sets,
                                      uint32_t pushBytes) {
    return createPipelineLayout(context, sets, pushBytes, kPushConstantStages);
}

} // namespace sb
