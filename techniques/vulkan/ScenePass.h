#pragma once
// What every pass that draws the scene through the submitter shares on Vulkan: the pipeline layout (set 0
// the frame block, then the technique's sets; common/push.glsl's push constants) and the description of
// a pipeline drawing the scene's meshes with GL's default state (depth LESS with writes, no culling,
// counter-clockwise front faces), which a pass then changes where its GL counterpart changes state.
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "scenes/BackFaceCulling.h"
#include "shading/Defines.h"
#include "techniques/vulkan/VulkanPipelineCache.h"
#include "vk/GraphicsPipeline.h"

namespace sb {

struct VulkanCompileContext;
struct VulkanFrameContext;

/// Set 0 = the frame block, then `sets`; push constants of VulkanPush. The caller owns the layout.
VkPipelineLayout createScenePipelineLayout(const VulkanCompileContext& ctx,
                                           const std::vector<VkDescriptorSetLayout>& sets = {});

/// A pipeline drawing the scene with `vertex`, `fragment` and an optional `geometry` stage (cull mode
/// and front face dynamic where the device allows: its draws must then be under a cull view,
/// VulkanSubmitter::setCullView; a pass drawn without one sets dynamicCull false) (files under
/// shaders/) compiled with `defines` (and dumped as one program under --dump-shaders), the submitter's
/// vertex input and `layout`. `key` gets the shader files and defines appended: the pipeline cache's key
/// for the shaders part.
GraphicsPipelineDesc scenePipeline(const VulkanCompileContext& ctx, const std::string& vertex,
                                   const std::string& fragment, const Defines& defines,
                                   VkPipelineLayout layout, std::string& key,
                                   const std::string& geometry = "");

/// The camera's view for back-face culling (VulkanSubmitter::setCullView, with clipFlipsY: the frame
/// block's clip space flips y): GL's matrix of the pass that draws the visible scene.
CullView cameraCullView(const VulkanFrameContext& ctx);

/// The lit pass over every mesh into the frame targets, as none's, shadowmap's and cubemap's lighting
/// passes draw it: begins the targets' render pass, binds `pipeline` (the variant for this frame's
/// targets), the frame block as set 0 and `set` as set 1 when given, draws DrawSet::All, ends the pass.
void drawLitScene(VulkanFrameContext& ctx, const ScenePipeline& pipeline, VkPipelineLayout layout,
                  VkDescriptorSet set = VK_NULL_HANDLE);

} // namespace sb
