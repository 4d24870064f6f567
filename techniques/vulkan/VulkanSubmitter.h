#pragma once
// Submission on Vulkan (techniques/gl/Submitter.h on GL): the scene's meshes in device-local vertex
// and index buffers, drawn into the frame's command buffer by the technique's bound pipeline. Two of GL's
// four modes have a Vulkan form:
//   retained   one vkCmdDrawIndexed per instance, the instance in push constants (common/push.glsl):
//              the per-instance command stream, recorded every frame as an application's render loop
//              records it;
//   instanced  one vkCmdDrawIndexed per mesh and run of kept instances, per-instance vertex attributes
//              from an instance buffer (common/instance.glsl, SB_INSTANCED).
// immediate and displaylist are GL's own (glBegin/glEnd, display lists): create() refuses them with
// ExitCode::Unsupported and says so.
// Vertex attributes as on GL: binding 0 interleaved position (location 0) and normal (1); instanced
// binding 1: model matrix (4..7) and colour with signed id (8). The vertex stream, the instance records,
// their batches and runs and the retained draw order are GL's too: techniques/SubmissionPlan.h.
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include "scenes/BackFaceCulling.h"
#include "scenes/Scene.h"
#include "shading/Defines.h"
#include "techniques/Submission.h"
#include "techniques/SubmissionPlan.h"
#include "vk/VulkanBuffer.h"

namespace sb {

class VulkanContext;

/// common/push.glsl's block. Per-instance draws fill model and colorId; a technique may fill the rest.
struct VulkanPush {
    glm::mat4 model{1.0f};
    glm::vec4 colorId{0.0f};
    glm::ivec4 ints{0};
    glm::vec4 vec{0.0f};
};
/// Stage flags of every vkCmdPushConstants and of the push range of every pipeline layout.
constexpr VkShaderStageFlags kPushStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

class VulkanSubmitter {
public:
    /// Throws sb::Error(Unsupported) for the GL-only modes.
    VulkanSubmitter(VulkanContext& context, SubmitMode mode);
    SubmitMode mode() const { return mMode; }
    /// Untimed: buffers for the scene's meshes and, instanced, its instance records; the back-face
    /// candidates (scenes/BackFaceCulling.h).
    void upload(const Scene& scene);
    /// The run's --back-faces, before upload: Draw never culls.
    void setBackFaces(BackFaces mode) { mBackFaces = mode; }
    /// Whether scene pipelines take cull mode and front face as dynamic state (the device has Vulkan
    /// 1.3, as lavapipe of Mesa 22.3.6 and 25.0.7 have); without it nothing is culled.
    bool dynamicCull() const { return mDynamicCull; }
    /// As Submitter::setCullView on GL: the view of the pass that draws next; each instance of a closed
    /// mesh it cannot see inside is drawn with VK_CULL_MODE_BACK_BIT. `clipFlipsY`: the pass's clip
    /// space is GL's with y flipped (the camera's frame block, VulkanFrameBlock::clipFromGl), else
    /// GL's y as is (the maps' depthFromGl); with Vulkan's y-down framebuffer that decides the front
    /// face. `view` holds GL's matrix. nullptr: both faces. Dynamic cull commands are recorded only
    /// while a view is set, so every pipeline drawn under a view must take them dynamically (the scene
    /// pipelines, ScenePass.h) and every one drawn without must not (VUID-vkCmdDrawIndexed-None-02859).
    void setCullView(const CullView* view, bool clipFlipsY);
    /// draw() under `view`, then none again.
    void drawCulled(VkCommandBuffer cmd, VkPipelineLayout layout, DrawSet set, const CullView& view,
                    bool clipFlipsY, InstanceMask keep = {}, const VulkanPush& push = {}) {
        setCullView(&view, clipFlipsY);
        draw(cmd, layout, set, keep, push);
        setCullView(nullptr, clipFlipsY);
    }
    /// A scene in motion moved instances: instanced mode rewrites its records (host-visible, in place).
    void instancesMoved(const Scene& scene);
    /// SB_INSTANCED for instanced.
    Defines defines() const;
    /// Vertex input of scene-drawing pipelines (position, normal and, instanced, the instance).
    std::vector<VkVertexInputBindingDescription> bindings() const;
    std::vector<VkVertexInputAttributeDescription> attributes() const;

    /// Records the draws of the instances of `set` that `keep` keeps (empty: all) with the bound
    /// pipeline of `layout`; `push` (a technique's per-pass values) is pushed with each instance's.
    /// Inside a view scope (setViewScope) only the scope's instances are drawn.
    void draw(VkCommandBuffer cmd, VkPipelineLayout layout, DrawSet set, InstanceMask keep = {},
              const VulkanPush& push = {});
    /// As Submitter::setViewScope on GL: restricts every draw to the instances `scope` keeps until it is
    /// cleared with an empty mask (a hybrid technique's part drawing the visible scene). The mask must
    /// outlive the scope.
    void setViewScope(InstanceMask scope) { mScope = scope; }
    InstanceMask viewScope() const { return mScope; }
    const SubmitStats& stats() const { return mStats; }
    void resetStats() {
        mLifetime += mStats;
        mStats = {};
    }
    SubmitStats lifetimeStats() const { return mLifetime + mStats; }

private:
    struct MeshGpu {
        VulkanBuffer vertices, indices;
        uint32_t indexCount = 0;
    };
    void drawRetained(VkCommandBuffer cmd, VkPipelineLayout layout, DrawSet set, InstanceMask keep,
                      VulkanPush push);
    void drawInstanced(VkCommandBuffer cmd, VkPipelineLayout layout, DrawSet set, InstanceMask keep,
                       const VulkanPush& push);
    void bindMesh(VkCommandBuffer cmd, uint32_t mesh);
    /// Cull mode for the next draws (a command only on a change since the draw began).
    void setCullMode(VkCommandBuffer cmd, bool cull);
    /// `keep` narrowed to the view scope (in mScoped).
    InstanceMask narrowToScope(InstanceMask keep);

    VulkanContext& mContext;
    SubmitMode mMode;
    const Scene* mScene = nullptr;
    std::vector<MeshGpu> mMeshes;
    std::vector<uint32_t> mOrder; ///< retained: instances by mesh (instancesByMesh)
    SubmissionPlan mPlan;         ///< instanced: the records in mInstances and their batches
    VulkanBuffer mInstances;      ///< host-visible
    SubmitStats mStats, mLifetime;
    InstanceMask mScope;          ///< empty: no view scope
    std::vector<uint8_t> mScoped; ///< the last narrowed mask
    BackFaces mBackFaces = BackFaces::Cull;
    BackFaceCuller mBackFaceCuller;
    bool mDynamicCull = false;
    bool mCullOn = false;  ///< the cull mode last recorded in this draw
    bool mViewSet = false; ///< a cull view is set: the bound pipeline takes cull mode dynamically
};

} // namespace sb
