#pragma once
// The technique contract on Vulkan (docs/ARCHITECTURE.md, "The technique contract" and "Vulkan"): the
// same declaration as the GL technique of the same name (TechniqueInfo: name, effects, passes,
// properties), the same calls in the same order (setScene, compile, execute per measured frame,
// sceneChanged for scenes in motion), recorded into the frame's command buffer instead of issued to a
// GL context. The registry (registry/TechniqueRegistry.h) says which techniques have one.
//
// What a frame may assume: the harness has begun the command buffer, the frame's timestamp slot and
// cleared the targets (VulkanTargets::recordClear); no render pass is open. Every pass a technique
// records calls ctx.passes.begin(name) first (outside a render pass: it writes a timestamp) and ends
// its render passes before returning.
#include <cstdint>
#include <string>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "scenes/Scene.h"
#include "techniques/Technique.h"
#include "techniques/vulkan/VulkanFrameBlock.h"
#include "techniques/vulkan/VulkanPassTimer.h"
#include "techniques/vulkan/VulkanPipelineCache.h"
#include "techniques/vulkan/VulkanSubmitter.h"
#include "vk/ShaderModuleCache.h"
#include "vk/VulkanContext.h"
#include "vk/VulkanTargets.h"

namespace sb {

struct VulkanCompileContext {
    VulkanContext& context;
    ShaderModuleCache& shaders;
    const Scene& scene;
    const VulkanSubmitter& submitter;
    VulkanTargets& targets;
    VulkanFrameBlock& frame;
    VulkanPipelineCache& pipelines;
    /// As the GL CompileContext's: the submitter's defines and the scene's shadow exceptions and
    /// light kinds (addSceneDefines).
    Defines defines() const;
};

struct VulkanFrameContext {
    const Scene& scene;
    glm::mat4 view{1.0f}, proj{1.0f}; ///< GL conventions (the frame block flips y for Vulkan)
    glm::vec3 eye{0.0f};
    VulkanTargets& targets;
    VulkanSubmitter& submitter;
    VulkanPassTimer& passes;
    VulkanFrameBlock& frame;
    uint32_t frameOffset = 0; ///< the harness's slot of the frame block (bind it as set 0)
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    uint64_t frameIndex = 0;
};

class VulkanTechnique : public Technique {
public:
    using Technique::Technique;
    Api api() const override { return Api::Vulkan; }

    /// "" when the device has every Vulkan capability the declaration lists, else one line naming every
    /// missing one, the device, and the capabilities' hints. A form that needs more than the declaration
    /// can say (a device feature) adds its own check.
    virtual std::string checkCapabilities(const VulkanContext& context) const;
    /// Shader modules and pipelines for the current properties, scene and targets (both visibility
    /// variants of the render pass: the harness switches between them).
    virtual void compile(const VulkanCompileContext& ctx) = 0;
    /// Records one frame into ctx.cmd.
    virtual void execute(VulkanFrameContext& ctx) = 0;
};

} // namespace sb
