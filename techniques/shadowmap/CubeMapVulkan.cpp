#include "techniques/shadowmap/CubeMapVulkan.h"

#include <algorithm>
#include <cstring>

#include "core/Error.h"
#include "scenes/ShadowWork.h"
#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/CubeMap.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

namespace {
using P = ShadowMapProperties;
constexpr const char* kLayered = "layered";

/// std140 offsets of omni_lighting.glsl's block for `lights` lights: mat4 uShadowMatrix[], then
/// ivec2 uMap[] and vec2 uDepthRange[], 16 bytes per element.
struct BlockLayout {
    explicit BlockLayout(uint32_t lights) : maps(64 * lights), ranges(80 * lights), size(96 * lights) {}
    uint32_t maps, ranges, size;
};

/// cube_depth.geom's CubePass (std140): six face matrices and the cube's first layer; its first matrix
/// is common/depth.vert's LightPass.
constexpr uint32_t kFaceMatricesBytes = 6 * 64;
constexpr uint32_t kCubePassBytes = kFaceMatricesBytes + 16;

} // namespace

CubeMapVulkan::CubeMapVulkan() : VulkanTechnique(CubeMap::declaration()) {}

CubeMapVulkan::~CubeMapVulkan() {
    release();
}

void CubeMapVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mDepthLayout, nullptr);
    vkDestroyPipelineLayout(mDevice, mLightingLayout, nullptr);
    mSets = DescriptorSets();
    mDepthLayout = mLightingLayout = VK_NULL_HANDLE;
    mFaceDepthPipeline = mLayeredDepthPipeline = VK_NULL_HANDLE; // owned by the pipeline cache
    mCubes = VulkanDepthMapSet();
    mFlat = VulkanDepthMapSet();
    mLightingBlock = VulkanBuffer();
}

void CubeMapVulkan::propertiesApplied() {
    mutableInfo().passes = ContactShadows::passes(properties(), CubeMap::declaration().passes);
}

void CubeMapVulkan::setScene(const Scene& scene) {
    mLights.setScene(scene, OmniShape::Cube, int(properties().getInt(P::kResolution)));
    mCubeLights = CubeMap::cubes(mLights);
    mCulling.setScene(scene);
    mOmniCulling.setScene(scene);
}

void CubeMapVulkan::createMaps(VulkanContext& context) {
    // A kind the scene lacks gets a 1 x 1 stand-in (its lookups are compiled out, FLAT_MAPS/OMNI_MAPS).
    const uint32_t cubeLayers = uint32_t(CubeFaces::kFaces * std::max(1, mCubeCount));
    const uint32_t cubeSize = mCubeCount > 0 ? uint32_t(mSize) : 1u;
    const uint32_t faces = mCubeCount > 0 && !mLayered ? cubeLayers : 0u; // six-pass: one per layer-face
    mCubes = VulkanDepthMapSet(context, cubeSize, cubeLayers, faces, true);
    if (mCubeCount > 0 && mLayered) mCubes.addLayeredFramebuffer();
    mFlat = VulkanDepthMapSet(context, mFlatCount > 0 ? uint32_t(mSize) : 1u,
                              uint32_t(std::max(1, mFlatCount)), uint32_t(mFlatCount));
}

void CubeMapVulkan::createDescriptors(VulkanContext& context) {
    // As DepthLayers on GL: hardware compare (LEQUAL) with LINEAR, the four comparison results filtered.
    const VkSampler sampler = mFlat.addSampler(true);
    mFlat.createSlots(context, kCubePassBytes,
                      uint32_t(std::max(1, mFlatCount + (CubeFaces::kFaces + 1) * mCubeCount)));
    // Set 1 of the depth passes: a dynamic slot per pass (CubePass, whose first matrix is LightPass).
    // Set 1 of the lighting pass: the lights' block, the flat maps and the cube maps.
    using D = DescriptorSets;
    const VkShaderStageFlags vertexFragment = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    mSets = DescriptorSets(
        mDevice,
        {{D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                     VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_GEOMETRY_BIT)},
         {D::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, vertexFragment),
          D::binding(1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT),
          D::binding(2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "cubemap");

    const BlockLayout block{uint32_t(mLights.shaderLightCount())};
    mLightingBlock = VulkanBuffer(context, block.size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mLightingBlock.map(), 0, block.size);

    mSets.writeBuffer(kDepthSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mFlat.slots().buffer(),
                      mFlat.slots().bytes());
    mSets.writeBuffer(kLightingSet, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mLightingBlock.buffer(),
                      block.size);
    mSets.writeImage(kLightingSet, 1, sampler, mFlat.view(), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
    mSets.writeImage(kLightingSet, 2, sampler, mCubes.view(),
                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
}

void CubeMapVulkan::writeBlocks() {
    // The lighting pass's per-light arrays, the GL form's uniforms (OmniLightSet::lightingArrays): flat
    // maps at their index (flatBase 0), cubes by cube index (one layer-cube each); std140 pads each
    // ivec2 and vec2 entry to 16 bytes.
    char* base = static_cast<char*>(mLightingBlock.map());
    const int n = mLights.shaderLightCount();
    const BlockLayout block{uint32_t(n)};
    const OmniLightSet::LightingArrays a = mLights.lightingArrays(0, 1);
    std::vector<glm::ivec4> maps(size_t(n), glm::ivec4(0));
    std::vector<glm::vec4> ranges(size_t(n), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
    for (size_t i = 0; i < size_t(n); ++i) {
        maps[i] = {a.maps[i].x, a.maps[i].y, 0, 0};
        ranges[i] = {a.depthRanges[i].x, a.depthRanges[i].y, 0.0f, 0.0f};
    }
    std::memcpy(base, a.shadowMatrices.data(), 64 * size_t(n));
    std::memcpy(base + block.maps, maps.data(), 16 * size_t(n));
    std::memcpy(base + block.ranges, ranges.data(), 16 * size_t(n));

    // The depth passes' matrices: Vulkan's depth range, no flip (VulkanFrameBlock::depthFromGl).
    const UniformSlots& slots = mFlat.slots();
    const glm::mat4 z = VulkanFrameBlock::depthFromGl();
    for (const OmniLight& o : mLights.lights()) {
        if (o.kind != OmniMapKind::Flat || o.index >= mFlatCount) continue;
        const glm::mat4 m = z * o.viewProj;
        slots.write(flatSlot(o.index), &m, sizeof m);
    }
    for (size_t cube = 0; cube < mCubeLights.size() && cube < size_t(mCubeCount); ++cube) {
        glm::mat4 faces[CubeFaces::kFaces];
        for (int f = 0; f < CubeFaces::kFaces; ++f) {
            faces[f] = z * mCubeLights[cube].faces.viewProjection(f);
            slots.write(faceSlot(cube, f), &faces[f], sizeof(glm::mat4));
        }
        char* layered = slots.at(layeredSlot(cube));
        std::memcpy(layered, faces, kFaceMatricesBytes);
        const int32_t layerBase = CubeFaces::kFaces * int32_t(cube);
        std::memcpy(layered + kFaceMatricesBytes, &layerBase, sizeof layerBase);
    }
}

void CubeMapVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mDevice = ctx.context.device();
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(ctx.context.physicalDevice(), &features); // VulkanContext enables these
    if (!features.imageCubeArray)
        throw Error("cubemap: the Vulkan device '" + ctx.context.info().name +
                        "' has no imageCubeArray (samplerCubeArrayShadow); run it with --api gl",
                    ExitCode::Unsupported);
    const PropertySet& p = properties();
    mSize = int(p.getInt(P::kResolution));
    mLayered = p.getBool(kLayered) && features.geometryShader;
    mCubeCount = mLights.omniCount();
    mFlatCount = mLights.flatCount();
    createMaps(ctx.context);
    createDescriptors(ctx.context);
    writeBlocks();

    // Depth passes: casters only, depth with the bias of glPolygonOffset(slope, constant), no colour, no
    // fragment stage.
    mDepthLayout = createScenePipelineLayout(ctx, {mSets.layout(kDepthSet)});
    const Defines base = ctx.submitter.defines();
    const std::string bias = VulkanDepthMapSet::biasKey(p);
    // mFlat's render pass, compatible with mCubes' (the same depth attachment).
    auto depthState = [&](GraphicsPipelineDesc& d) { mFlat.depthPipeline(d, p); };
    std::string faceKey = "cubemap-depth" + bias;
    GraphicsPipelineDesc face = scenePipeline(ctx, "common/depth.vert", VulkanDepthMapSet::kDepthFragment,
                                              base, mDepthLayout, faceKey);
    depthState(face);
    mFaceDepthPipeline = ctx.pipelines.get(faceKey, face);
    if (mLayered) {
        std::string layeredKey = "cubemap-layered-depth" + bias;
        GraphicsPipelineDesc layered =
            scenePipeline(ctx, "shadowmap/cube_depth.vert", VulkanDepthMapSet::kDepthFragment, base,
                          mDepthLayout, layeredKey, "shadowmap/cube_depth.geom");
        depthState(layered);
        // One draw for six faces: drawn with both faces, fixed.
        layered.dynamicCull = false;
        mLayeredDepthPipeline = ctx.pipelines.get(layeredKey + "|both-faces", layered);
    }

    // Lighting pass: the GL technique's defines, permutation for permutation.
    // The depth passes have no shadow to apply: only the lighting pass takes the scene's exceptions.
    const Defines lit = CubeMap::lightingDefines(ctx.defines(), p, mLights);
    mContact.compile(p, ctx);
    mLightingLayout = createScenePipelineLayout(ctx, mContact.lightingSets({mSets.layout(kLightingSet)}));
    const std::string litPermutation = mLighting.build(
        ctx, "common/scene.vert", "shadowmap/cube_lighting.frag", lit, mLightingLayout, "cubemap-lighting|");
    std::string key = definesKey(base) + "|" + litPermutation;
    if (mLayered) key += "|layered:" + definesKey(base);
    setPermutationKey(key);
}

void CubeMapVulkan::beginDepthPass(VulkanFrameContext& ctx, const VulkanDepthMapSet& maps, size_t framebuffer,
                                   VkPipeline pipeline) {
    maps.begin(ctx.cmd, framebuffer);
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    ctx.frame.bind(ctx.cmd, mDepthLayout, ctx.frameOffset);
}

void CubeMapVulkan::bindSlot(VulkanFrameContext& ctx, uint32_t slot) {
    mFlat.slots().bind(ctx.cmd, mDepthLayout, mSets.set(kDepthSet), slot);
}

void CubeMapVulkan::renderFlatMaps(VulkanFrameContext& ctx) {
    // As the GL form's renderOmniFlatMaps: each flat map cleared, its casters culled against its frustum.
    for (const OmniLight& o : mLights.lights()) {
        if (o.kind != OmniMapKind::Flat || o.index >= mFlatCount) continue;
        beginDepthPass(ctx, mFlat, size_t(o.index), mFaceDepthPipeline);
        bindSlot(ctx, flatSlot(o.index));
        mCulled += mLights.cullFlatCasters(o, mCulling, mKeep);
        ctx.submitter.drawCulled(ctx.cmd, mDepthLayout, DrawSet::Casters, {o.viewProj, false}, false, mKeep);
        vkCmdEndRenderPass(ctx.cmd);
    }
}

void CubeMapVulkan::renderCubesLayered(VulkanFrameContext& ctx) {
    // Every cube in the array belongs to a light that casts: the render pass clears them all.
    beginDepthPass(ctx, mCubes, 0, mLayeredDepthPipeline); // the one framebuffer over all
    for (size_t cube = 0; cube < mCubeLights.size() && cube < size_t(mCubeCount); ++cube) {
        const CubeMap::Cube& c = mCubeLights[cube];
        const size_t kept = mOmniCulling.cullSphere(c.light.position, c.light.farZ, mRange);
        mCulled += mOmniCulling.casters() - kept;
        if (kept == 0) continue;
        bindSlot(ctx, layeredSlot(cube));
        ctx.submitter.draw(ctx.cmd, mDepthLayout, DrawSet::Casters, mRange);
        mFacesRendered += CubeFaces::kFaces;
    }
    vkCmdEndRenderPass(ctx.cmd);
}

void CubeMapVulkan::renderCubesSixPass(VulkanFrameContext& ctx) {
    for (size_t cube = 0; cube < mCubeLights.size() && cube < size_t(mCubeCount); ++cube) {
        const CubeMap::Cube& c = mCubeLights[cube];
        mOmniCulling.cullSphere(c.light.position, c.light.farZ, mRange);
        for (int f = 0; f < CubeFaces::kFaces; ++f) {
            beginDepthPass(ctx, mCubes, size_t(CubeFaces::kFaces * int(cube) + f), mFaceDepthPipeline);
            mCulling.cull(c.faces.viewProjection(f), DrawSet::Casters, CullPlanes::All, mKeep);
            size_t kept = 0;
            for (size_t i = 0; i < mKeep.size(); ++i) kept += (mKeep[i] &= mRange[i]) ? 1 : 0;
            mCulled += mCulling.count(DrawSet::Casters) - kept;
            if (kept > 0) { // else the cleared face is the answer: nothing casts into it
                bindSlot(ctx, faceSlot(cube, f));
                // Each face's own view decides, and its handedness sets the front face.
                ctx.submitter.drawCulled(ctx.cmd, mDepthLayout, DrawSet::Casters,
                                         {c.faces.viewProjection(f), false}, false, mKeep);
                ++mFacesRendered;
            }
            vkCmdEndRenderPass(ctx.cmd);
        }
    }
}

void CubeMapVulkan::renderDepth(VulkanFrameContext& ctx) {
    if (mCubeCount == 0 && mFlatCount == 0) return; // no light casts: no depth work at all
    if (mFlatCount > 0) renderFlatMaps(ctx);
    if (mCubeCount > 0) {
        if (mLayered)
            renderCubesLayered(ctx);
        else
            renderCubesSixPass(ctx);
    }
}

void CubeMapVulkan::execute(VulkanFrameContext& ctx) {
    // As GL sets its uniforms every frame: a scene in motion (sceneChanged -> setScene) moved the fits.
    // The previous frame's fence has been waited for, so no slot is in flight.
    writeBlocks();
    mCulled = 0;
    mFacesRendered = 0;
    const SubmitStats s = DepthLightingFrame::run(
        ctx, [&] { renderDepth(ctx); },
        [&] {
            mContact.bind(ctx.cmd, mLightingLayout);
            mLighting.draw(ctx, mLightingLayout, mSets.set(kLightingSet));
        },
        mContact.prePass(ctx), ContactShadows::kPass);
    mCounters = CubeMap::counters(s, mSize, mLights, mFacesRendered, mCulled);
}

} // namespace sb
