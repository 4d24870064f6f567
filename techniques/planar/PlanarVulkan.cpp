#include "techniques/planar/PlanarVulkan.h"

#include <algorithm>
#include <cstring>
#include <iostream>

#include "core/Error.h"
#include "scenes/Motion.h"
#include "scenes/ShadowWork.h"
#include "shading/ShaderLimits.h"
#include "techniques/vulkan/ScenePass.h"

namespace sb {

namespace {

/// std140 record of planar/shadow.*'s Flattening block.
struct FlatteningRecord {
    glm::mat4 flatten;
    glm::vec4 plane;
    glm::vec4 light;
    glm::vec4 albedoLight;
    float darkness;
};

/// Vertex input of the proxy pipeline: the unit shape's vertices and the proxies' instance records
/// (common/instance.glsl with SB_INSTANCED), whatever the submitter's mode.
void proxyInput(GraphicsPipelineDesc& d) {
    d.bindings = {{0, uint32_t(kVertexStride), VK_VERTEX_INPUT_RATE_VERTEX},
                  {1, sizeof(InstanceRecord), VK_VERTEX_INPUT_RATE_INSTANCE}};
    d.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, 0, VK_FORMAT_R32G32B32_SFLOAT, kNormalOffset}};
    for (uint32_t c = 0; c < 4; ++c)
        d.attributes.push_back({4 + c, 1, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(c * sizeof(glm::vec4))});
    d.attributes.push_back(
        {8, 1, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(InstanceRecord, colorId))});
}

} // namespace

PlanarVulkan::PlanarVulkan() : VulkanTechnique(Planar::declaration()) {}

PlanarVulkan::~PlanarVulkan() {
    release();
}

void PlanarVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    mLayout = VK_NULL_HANDLE;
    mSets = DescriptorSets();
    mFlattenings = VulkanBuffer();
}

void PlanarVulkan::readProperties() {
    const PropertySet& p = properties();
    mStencil = p.getBool(Planar::kStencil);
    mUseProxies = p.getEnum(Planar::kOccluder) == "proxy";
    mGuards = p.getBool(Planar::kGuards);
    mCull = p.getBool(Planar::kCull) && !mUseProxies;
    mDarkness = float(p.getFloat(Planar::kDarkness));
}

void PlanarVulkan::setScene(const Scene& scene) {
    mScene = &scene;
    mPlanes = ReceiverPlane::find(scene);
    if (mPlanes.empty())
        std::cerr << "planar: scene '" << scene.name
                  << "' declares no receiver plane (a planar instance that receives and casts no shadow): "
                     "nothing is shadowed\n";
    mReceivers.setPlanes(mPlanes);
    mCulling.setScene(scene);
    mShapes.clear();
    mProxiesDirty = true;
}

void PlanarVulkan::sceneChanged(const Scene& scene, uint32_t changes) {
    if (changes & kLightsMoved) {
        mProjections = Planar::projections(mPlanes, scene, mGuards);
        writeFlattenings();
    }
    if (changes & kCastersMoved) mCulling.instancesMoved(scene);
    if ((changes & kCastersMoved) && mUseProxies && mContext) writeProxyRecords(*mContext);
}

void PlanarVulkan::uploadProxyShapes(VulkanContext& context) {
    const Scene shapes = Planar::unitShapes();
    mShapes.clear();
    for (const Mesh& mesh : shapes.meshes) {
        const std::vector<glm::vec3> interleaved = interleavedVertices(mesh);
        ShapeGpu g;
        g.vertices = VulkanBuffer(context, interleaved.size() * sizeof(glm::vec3),
                                  VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, interleaved.data());
        g.indices = VulkanBuffer(context, mesh.indices.size() * sizeof(uint32_t),
                                 VK_BUFFER_USAGE_INDEX_BUFFER_BIT, mesh.indices.data());
        g.indexCount = uint32_t(mesh.indices.size());
        mShapes.push_back(std::move(g));
    }
    mProxiesDirty = true;
}

void PlanarVulkan::writeProxyRecords(VulkanContext& context) {
    mProxies = Planar::planProxies(*mScene, Planar::unitShapes());
    const VkDeviceSize bytes = std::max<size_t>(1, mProxies.records.size()) * sizeof(InstanceRecord);
    // The last frame that read the buffer has finished (the harness waits for each frame's fence).
    if (!mProxyInstances || mProxyInstances.size() < bytes)
        mProxyInstances = VulkanBuffer(context, bytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    if (!mProxies.records.empty())
        std::memcpy(mProxyInstances.map(), mProxies.records.data(),
                    mProxies.records.size() * sizeof(InstanceRecord));
    mProxiesDirty = false;
}

void PlanarVulkan::writeFlattenings() {
    if (!mFlattenings) return;
    char* base = static_cast<char*>(mFlattenings.map());
    for (size_t i = 0; i < mProjections.size(); ++i) {
        const Planar::Projection& p = mProjections[i];
        const ReceiverPlane& plane = mPlanes[p.plane];
        const FlatteningRecord r{p.matrix, plane.equation(), p.lightPos,
                                 glm::vec4(plane.albedo, float(p.light)), mDarkness};
        std::memcpy(base + size_t(mStride) * i, &r, sizeof r);
    }
}

void PlanarVulkan::buildPipelines(const VulkanCompileContext& ctx) {
    Defines lit = withLightKinds(ctx.submitter.defines(), ctx.scene);
    lit["LIGHT_COUNT"] = std::to_string(std::clamp<int>(int(ctx.scene.lights.size()), 1, kMaxLights));
    std::string litKey = "planar-lit|";
    mLit.build(ctx.pipelines, litKey,
               scenePipeline(ctx, "common/scene.vert", "common/lit.frag", lit, mLayout, litKey), ctx.targets);

    Defines shadow = lit;
    if (mGuards) shadow["GUARDS"] = "";
    const std::string state = std::string("|stencil=") + (mStencil ? "1" : "0") + "|";
    // The shadow polygons: as GL's setShadowState. With the stencil, no depth test (ReceiverStencil::mark
    // leaves it off) and each pixel once; without, depth-tested LEQUAL with the offset, no writes.
    auto shadowState = [&](GraphicsPipelineDesc& d) {
        if (mStencil) {
            VulkanReceiverStencil::darkenState(d, VK_STENCIL_OP_ZERO);
            return;
        }
        d.depthBias = true;
        d.depthBiasSlope = VulkanReceiverStencil::kOffsetFactor;
        d.depthBiasConstant = VulkanReceiverStencil::kOffsetUnits;
        d.depthWrite = false;
        d.depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
        d.subtractColour = true;
        d.multiplyVisibility = true;
    };
    std::string shadowKey = "planar-shadow" + state;
    GraphicsPipelineDesc d =
        scenePipeline(ctx, "planar/shadow.vert", "planar/shadow.frag", shadow, mLayout, shadowKey);
    shadowState(d);
    d.dynamicCull = false; // the flattened casters: both faces, fixed
    shadowKey += "|both-faces";
    mShadow.build(ctx.pipelines, shadowKey, d, ctx.targets);
    std::string key = definesKey(lit) + "|" + definesKey(shadow) + state;

    if (mUseProxies) {
        Defines proxy = shadow;
        proxy["SB_INSTANCED"] = ""; // the proxies' own instance buffer
        std::string proxyKey = "planar-proxy" + state;
        GraphicsPipelineDesc p =
            scenePipeline(ctx, "planar/shadow.vert", "planar/shadow.frag", proxy, mLayout, proxyKey);
        proxyInput(p);
        shadowState(p);
        p.dynamicCull = false;
        proxyKey += "|both-faces";
        mProxy.build(ctx.pipelines, proxyKey, p, ctx.targets);
        key += "|proxy";
    }
    if (mStencil) mReceivers.compile(ctx, mLayout);
    setPermutationKey(key);
}

void PlanarVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mContext = &ctx.context;
    mDevice = ctx.context.device();
    readProperties();
    if (mGuards && !ctx.context.clipDistance())
        throw Error("planar: guards=true clips with gl_ClipDistance, which needs the shaderClipDistance "
                    "feature '" +
                        ctx.context.info().name +
                        "' does not offer: unsupported here (run with guards=false)",
                    ExitCode::Unsupported);
    if (!ctx.context.independentBlend())
        throw Error("planar: the shadows blend colour and visibility differently, which needs the "
                    "independentBlend feature '" +
                        ctx.context.info().name + "' does not offer: unsupported here",
                    ExitCode::Unsupported);
    mProjections = Planar::projections(mPlanes, ctx.scene, mGuards);
    if (mUseProxies && mShapes.empty()) uploadProxyShapes(ctx.context);
    if (mUseProxies && mProxiesDirty) writeProxyRecords(ctx.context);

    // Room for every plane and light: moving lights change which flattenings exist, never their number
    // beyond this.
    mStride = ctx.context.uniformStride(sizeof(FlatteningRecord));
    const size_t capacity = std::max<size_t>(1, mPlanes.size() * kMaxLights);
    mFlattenings = VulkanBuffer(ctx.context, capacity * mStride, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mFlattenings.map(), 0, capacity * mStride);
    writeFlattenings();
    mSets =
        DescriptorSets(mDevice,
                       {{DescriptorSets::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                                                 VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT)}},
                       "planar");
    mSets.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, mFlattenings.buffer(),
                      sizeof(FlatteningRecord));
    mLayout = createScenePipelineLayout(ctx, {mSets.layout(0)});
    buildPipelines(ctx);
}

void PlanarVulkan::drawOccluders(VulkanFrameContext& ctx, size_t index, InstanceMask keep) {
    const uint32_t offset = uint32_t(index) * mStride;
    const VkDescriptorSet set = mSets.set(0);
    vkCmdBindDescriptorSets(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, 1, 1, &set, 1, &offset);
    if (!mUseProxies) {
        ctx.submitter.draw(ctx.cmd, mLayout, DrawSet::Casters, keep);
        return;
    }
    const VkDeviceSize zero = 0;
    for (const Planar::ProxyBatch& b : mProxies.batches) {
        const ShapeGpu& g = mShapes[b.shape];
        const VkBuffer buffers[2] = {g.vertices.buffer(), mProxyInstances.buffer()};
        const VkDeviceSize offsets[2] = {zero, zero};
        vkCmdBindVertexBuffers(ctx.cmd, 0, 2, buffers, offsets);
        vkCmdBindIndexBuffer(ctx.cmd, g.indices.buffer(), 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(ctx.cmd, g.indexCount, b.count, 0, 0, b.first);
    }
}

void PlanarVulkan::renderShadows(VulkanFrameContext& ctx) {
    ctx.passes.begin("shadows");
    VkCommandBuffer cmd = ctx.cmd;
    ctx.targets.beginPass(cmd);
    ctx.frame.bind(cmd, mLayout, ctx.frameOffset);
    const VkPipeline occluders = (mUseProxies ? mProxy : mShadow).get(ctx.targets);
    if (!mStencil) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, occluders);
    uint32_t ref = 0;
    mCulled = 0;
    const glm::mat4 viewProj = ctx.proj * ctx.view;
    for (size_t i = 0; i < mProjections.size(); ++i) {
        const Planar::Projection& p = mProjections[i];
        if (mCull) {
            // Casters whose flattened bounds miss the view darken nothing the camera sees.
            const size_t kept = mCulling.cullFlattened(p.matrix, viewProj, !mGuards, mKeep);
            mCulled += mCulling.count(DrawSet::Casters) - kept;
            if (kept == 0) continue; // nothing to flatten: no receiver marking either
        }
        if (mStencil) {
            // A fresh reference value per flattening marks the receiver anew without clearing the
            // stencil, as on GL: 255 flattenings, then a clear.
            if (++ref > 255) {
                VkClearAttachment clear{};
                clear.aspectMask = VK_IMAGE_ASPECT_STENCIL_BIT;
                clear.clearValue.depthStencil = {1.0f, 0};
                const VkClearRect rect{
                    {{0, 0}, {uint32_t(ctx.targets.width()), uint32_t(ctx.targets.height())}}, 0, 1};
                vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);
                ref = 1;
            }
            mReceivers.mark(ctx, p.plane, ref);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, occluders);
        }
        drawOccluders(ctx, i, mCull ? InstanceMask(mKeep) : InstanceMask{});
    }
    vkCmdEndRenderPass(cmd);
}

void PlanarVulkan::execute(VulkanFrameContext& ctx) {
    ctx.submitter.resetStats();
    ctx.passes.begin("lighting");
    drawLitScene(ctx, mLit, mLayout);
    if (mProjections.empty()) {
        const char* reason = ShadowWork::noneNeeded(ctx.scene);
        ctx.passes.skip("shadows", reason            ? reason
                                   : mPlanes.empty() ? "no receiver plane"
                                                     : "no light above a plane");
    } else {
        renderShadows(ctx);
    }
    mCounters = Planar::counters(ctx.submitter.stats(),
                                 {.planes = mPlanes.size(),
                                  .flattenings = mProjections.size(),
                                  .culled = mCulled,
                                  .proxyBatches = mProxies.batches.size(),
                                  .proxyTriangles = mProxies.triangles,
                                  .proxies = mUseProxies},
                                 ctx.scene);
}

} // namespace sb
