#pragma once
// One graphics pipeline from a plain description: the fixed-function state a technique sets on GL with
// glEnable/glDepthFunc/glStencilOp..., written down once per pass. Viewport and scissor are dynamic (a
// pass sets them to its target: the frame or a shadow map), so one pipeline serves any size.
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

namespace sb {

class VulkanContext;

struct GraphicsPipelineDesc {
    VkShaderModule vertex = VK_NULL_HANDLE;
    VkShaderModule fragment = VK_NULL_HANDLE; ///< VK_NULL_HANDLE: depth only
    VkShaderModule geometry = VK_NULL_HANDLE;
    /// A mesh pipeline (VK_EXT_mesh_shader, the meshShader feature): this stage instead of vertex and
    /// geometry (both left null); bindings, attributes and topology are then ignored (no vertex input
    /// or input assembly state: the mesh shader makes its primitives).
    VkShaderModule mesh = VK_NULL_HANDLE;
    std::vector<VkVertexInputBindingDescription> bindings;
    std::vector<VkVertexInputAttributeDescription> attributes;
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkCullModeFlags cull = VK_CULL_MODE_NONE;
    VkFrontFace frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    bool depthClamp = false;
    bool depthBias = false; ///< slope and constant factors below (glPolygonOffset(slope, constant))
    float depthBiasSlope = 0.0f, depthBiasConstant = 0.0f;
    bool depthTest = true, depthWrite = true;
    /// The depth bounds test with dynamic bounds (vkCmdSetDepthBounds); needs the depthBounds feature.
    bool depthBounds = false;
    VkCompareOp depthCompare = VK_COMPARE_OP_LESS;
    bool stencilTest = false;
    VkStencilOpState stencilFront{}, stencilBack{}; ///< two-sided stencil: each face its own ops
    uint32_t colourAttachments = 1;                 ///< as many as the render pass has
    VkColorComponentFlags colourWrite = 0xF;        ///< applied to attachment 0; 0 masks colour off
    bool visibilityWrite = true;                    ///< attachment 1's write mask (when it exists)
    bool additive = false;                          ///< blend ONE + ONE on attachment 0 (light passes)
    bool multiplyVisibility = false;                ///< blend attachment 1 as dst * src (volumes per light)
    bool maxVisibility = false;  ///< blend attachment 1 as max(src, dst) (glBlendEquationi(1, GL_MAX))
    bool subtractColour = false; ///< blend attachment 0 as dst - src (GL_FUNC_REVERSE_SUBTRACT, ONE, ONE)
    /// The stencil reference is dynamic (vkCmdSetStencilReference before each draw): a pass that marks
    /// with a fresh value per draw, as glStencilFunc(..., ref, ...) does between draws on GL.
    bool dynamicStencilReference = false;
    /// Cull mode and front face are dynamic (vkCmdSetCullMode, vkCmdSetFrontFace; core in Vulkan 1.3):
    /// the scene pipelines, whose draws the submitter culls per instance (scenes/BackFaceCulling.h).
    /// `cull` and `frontFace` above are then ignored; whoever draws must set both.
    bool dynamicCull = false;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
};

/// The stage flags of createPipelineLayout's push-constant range (vertex and fragment; a geometry stage
/// reads no push constants), for vkCmdPushConstants.
constexpr VkShaderStageFlags kPushConstantStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

/// Creates the pipeline (throws sb::Error(Failure) naming the VkResult). The caller owns it.
VkPipeline createGraphicsPipeline(VulkanContext& context, const GraphicsPipelineDesc& desc);

/// A pipeline layout of `sets` and one push-constant range of `pushBytes` bytes (0 = none). The range's
/// stages are kPushConstantStages (vertex and fragment): every vkCmdPushConstants into this layout must
/// pass exactly those flags. The caller owns it.
VkPipelineLayout createPipelineLayout(VulkanContext& context, const std::vector<VkDescriptorSetLayout>& sets,
                                      uint32_t pushBytes);

} // namespace sb
