#pragma once
// The scene as a ray query sees it (VK_KHR_acceleration_structure): one bottom-level structure per mesh,
// built once from the mesh's object-space vertices and indices, and one top-level structure over the
// instances that cast a shadow, each placed by its model matrix. Which instances are in it follows the
// Embree reference (reference/EmbreeScene.cpp): an instance with casts_shadow false stops no ray, so it
// is left out of the top level; every other instance of a mesh with triangles is in it. Both faces of
// every triangle stop rays (TRIANGLE_FACING_CULL_DISABLE, as Embree's default build), and every geometry
// is opaque (no any-hit work).
//
// Built in the constructor (untimed for the frames, VulkanContext::submitNow): the bottom levels, then the
// top level, each submission timed on the host from recording to its fence (bottomLevelsBuildMs,
// topLevelBuildMs): on lavapipe the builds run on the CPU inside that wait, so the time is the build's
// plus one submission's overhead. The harness's setup_ms holds them among the pipelines' compilation.
// A scene in motion moves its casters: writeInstances() puts their model matrices into the instance
// buffer and recordTopLevelBuild() records the top level's rebuild into the frame's command buffer,
// followed by the barrier that makes it visible to the fragment stage's ray queries, so the frame pays
// for its structure as the other techniques pay for their maps. The bottom levels never change: motion
// moves instances, not vertices (scenes/Motion.h).
//
// The casters are listed in the instance buffer along the Morton code of their world-space bounds
// centres at construction (scenes/MortonOrder.h; the idea is the ordering step of Lauterbach et al.,
// "Fast BVH Construction on GPUs", Eurographics 2009), not in scene order, and keep that order for
// good: motion rewrites each slot's matrix in place (mCasters maps slot -> scene instance). The reason
// is lavapipe's top-level builder (Mesa 25.0.7), which keeps the locality of the order it is given:
// results/raytraced/README.md ("The top level and the order of instances") measured a grid of
// instances listed in shuffled order at n^0.99 per ray against n^0.37 row by row (22x at 4096
// instances), and the aircraft layout lists its aircraft in random-position order.
// Casters in motion drift from the order of their first positions: that costs locality, never a wrong
// answer, and re-sorting would rewrite every slot each frame.
// Which slot holds which instance changes nothing a ray sees: shaders/raytraced/rays.glsl asks only
// whether any opaque triangle lies on the segment (terminate on first hit), never which instance.
//
// Needs VulkanContext::rayQuery().
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "scenes/Scene.h"
#include "vk/AccelerationStructure.h"
#include "vk/VulkanBuffer.h"
#include "vk/VulkanContext.h"

namespace sb {

class AccelerationStructures {
public:
    /// Builds every structure of `scene` and waits. Throws sb::Error(Failure) when a Vulkan call fails.
    AccelerationStructures(VulkanContext& context, const Scene& scene);
    AccelerationStructures(const AccelerationStructures&) = delete;
    AccelerationStructures& operator=(const AccelerationStructures&) = delete;

    /// What the lighting pass's ray queries traverse (set 1, binding 0).
    VkAccelerationStructureKHR topLevel() const { return mTopLevel.handle(); }
    /// The storage of every structure, bottom levels and top level (the `structure_bytes` counter).
    uint64_t bytes() const;
    size_t bottomLevelCount() const;
    /// The instances in the top level: the casters whose mesh has triangles.
    uint32_t instanceCount() const { return uint32_t(mCasters.size()); }
    /// Host wall time (ms) of the one submission that built every bottom level, recorded, submitted and
    /// waited for (0 when no mesh has triangles).
    double bottomLevelsBuildMs() const { return mBottomLevelsBuildMs; }
    /// The same for the top level's first build: the build a frame whose casters moved repeats, over the
    /// same instances with the same flags, inside its command buffer (where the host cannot time it alone).
    double topLevelBuildMs() const { return mTopLevelBuildMs; }

    /// Writes the casters' current model matrices into the instance buffer (a scene in motion moved
    /// them); the next recordTopLevelBuild() builds over them. The previous frame must have finished
    /// (the harness waits for each frame's fence).
    void writeInstances(const Scene& scene);
    /// Records the top level's build over the instance buffer into `cmd`, outside a render pass, and a
    /// barrier from the build to the fragment shaders' ray queries.
    void recordTopLevelBuild(VkCommandBuffer cmd);

private:
    /// Reorders mCasters along the Morton code of each caster's world-space bounds centre (its mesh's
    /// bounds under its model matrix now); called once, before the first build.
    void orderCastersInSpace(const Scene& scene);
    /// Bottom levels of every mesh with triangles, built together (one scratch buffer).
    void buildBottomLevels(const Scene& scene);
    /// The top level's geometry over the instance buffer and its build sizes.
    void createTopLevel();
    void recordBottomLevelBuilds(VkCommandBuffer cmd, const std::vector<VulkanBuffer>& inputs);

    VulkanContext& mContext;
    VkDeviceSize mScratchAlignment = 1;
    std::vector<AccelerationStructure> mBottomLevels; ///< per mesh; empty for a mesh without triangles
    std::vector<size_t> mCasters; ///< scene instance of each top-level slot, in Morton order
    VulkanBuffer mInstances;      ///< host-visible VkAccelerationStructureInstanceKHR per caster
    AccelerationStructure mTopLevel;
    VulkanBuffer mTopLevelScratch;
    double mBottomLevelsBuildMs = 0.0;
    double mTopLevelBuildMs = 0.0;
};

} // namespace sb
