#include "techniques/volume/VolumeVulkan.h"

#include <algorithm>
#include <cstring>

#include "core/Error.h"
#include "scenes/Motion.h"
#include "techniques/volume/SilhouetteInputs.h"
#include "techniques/volume/Volume.h"
#include "techniques/vulkan/ScenePass.h"
#include "vk/PipelineLayout.h"

namespace sb {

namespace {

/// std140 offsets of volume/ambient.frag's VolumeAmbient.
constexpr uint32_t kLitRectOffset = 0, kDepthRangeOffset = 16 * kMaxLights,
                   kTargetHeightOffset = kDepthRangeOffset + 16 * kMaxLights,
                   kAmbientBlockSize = kTargetHeightOffset + 16;

VkStencilOpState stencilOps(VkCompareOp compare, VkStencilOp pass, VkStencilOp depthFail) {
    VkStencilOpState s{};
    s.failOp = VK_STENCIL_OP_KEEP;
    s.passOp = pass;
    s.depthFailOp = depthFail;
    s.compareOp = compare;
    s.compareMask = 0xff;
    s.writeMask = 0xff;
    s.reference = 0;
    return s;
}

int32_t floatBits(float f) {
    int32_t bits = 0;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
}

} // namespace

VolumeVulkan::VolumeVulkan() : VulkanTechnique(Volume::declaration()) {}

VolumeVulkan::~VolumeVulkan() {
    release();
}

void VolumeVulkan::release() {
    if (!mDevice) return;
    vkDestroyPipelineLayout(mDevice, mLayout, nullptr);
    vkDestroyPipelineLayout(mDevice, mMarkLayout, nullptr);
    mMarkLayout = VK_NULL_HANDLE;
    mSilhouettes.release();
    vkDestroyQueryPool(mDevice, mSamples, nullptr);
    mSamples = VK_NULL_HANDLE;
    mQueriesIssued = {};
    mSets = DescriptorSets();
    mLayout = VK_NULL_HANDLE;
    mAmbientBlock = VulkanBuffer();
}

void VolumeVulkan::setScene(const Scene& scene) {
    mPlanner.setSettings(VolumePlanner::readSettings(properties()));
    const VolumePlanner::Settings& settings = mPlanner.settings();
    mScene = &scene;
    // The CPU half of VolumeMeshBuffers::upload: welded meshes and, for the vertex path, the
    // McGuire-Hughes meshes; compile() puts them in buffers.
    mMeshes.clear();
    mMeshes.resize(scene.meshes.size());
    std::vector<bool> casts(scene.meshes.size(), false);
    for (const Instance& inst : scene.instances)
        if (inst.castsShadow) casts[inst.mesh] = true;
    std::vector<VolumePlanner::MeshInfo> infos(scene.meshes.size());
    for (size_t i = 0; i < scene.meshes.size(); ++i) {
        if (!casts[i]) continue;
        MeshGpu& g = mMeshes[i];
        g.mesh = std::make_unique<ShadowVolumeMesh>(scene.meshes[i]);
        if (settings.vertexExtrusion) {
            g.extrusion = std::make_unique<ExtrusionMesh>(g.mesh->buildExtrusionMesh(settings.policy));
            g.capIndices = uint32_t(g.extrusion->capIndices.size());
            g.sideIndices = uint32_t(g.extrusion->sideIndices.size());
        }
        infos[i] = {g.mesh.get(), g.capIndices, g.sideIndices};
    }
    mUploaded = false;
    mPlanner.setMeshes(std::move(infos));
    mPlanner.checkClosed(scene);
    mPlanner.checkGpuSilhouettes(scene);
    mPlanner.setScene(scene);
}

void VolumeVulkan::sceneChanged(const Scene& scene, uint32_t changes) {
    // As on GL: silhouettes, extrusions and regions are found every frame; only the casters' places
    // are fixed once.
    if (changes & kCastersMoved) mPlanner.placeCasters(scene);
}

void VolumeVulkan::uploadMeshes(VulkanContext& context) {
    for (MeshGpu& g : mMeshes) {
        if (!g.mesh) continue;
        const std::vector<glm::vec4> doubled = g.mesh->doubledVertices();
        const std::vector<glm::vec4> one(1, glm::vec4(0.0f));
        const std::vector<glm::vec4>& v = doubled.empty() ? one : doubled;
        g.doubled =
            VulkanBuffer(context, v.size() * sizeof(glm::vec4), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, v.data());
        if (!g.extrusion) continue;
        const ExtrusionMesh& m = *g.extrusion;
        // Interleaved (x, y, z, 1) position and (N, dot(N, P0)) plane, as VolumeMeshBuffers lays them out.
        std::vector<glm::vec4> interleaved;
        interleaved.reserve(std::max<size_t>(2, m.positions.size() * 2));
        for (size_t i = 0; i < m.positions.size(); ++i) {
            interleaved.push_back(glm::vec4(m.positions[i], 1.0f));
            interleaved.push_back(m.facePlanes[i]);
        }
        if (interleaved.empty()) interleaved.resize(2, glm::vec4(0.0f));
        std::vector<uint32_t> indices = m.capIndices;
        indices.insert(indices.end(), m.sideIndices.begin(), m.sideIndices.end());
        if (indices.empty()) indices.push_back(0);
        g.extrusionVertices = VulkanBuffer(context, interleaved.size() * sizeof(glm::vec4),
                                           VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, interleaved.data());
        g.extrusionIndices = VulkanBuffer(context, indices.size() * sizeof(uint32_t),
                                          VK_BUFFER_USAGE_INDEX_BUFFER_BIT, indices.data());
        g.extrusion.reset();
    }
    mUploaded = true;
}

void VolumeVulkan::createDescriptors(VulkanContext& context) {
    // Set 1: ambient.frag's block (the lights' regions and the target height).
    mSets = DescriptorSets(
        mDevice,
        {{DescriptorSets::binding(0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, VK_SHADER_STAGE_FRAGMENT_BIT)}},
        "volume");
    mAmbientBlock = VulkanBuffer(context, kAmbientBlockSize, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    std::memset(mAmbientBlock.map(), 0, kAmbientBlockSize);
    mSets.writeBuffer(0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, mAmbientBlock.buffer(), kAmbientBlockSize);
}

void VolumeVulkan::buildPipelines(const VulkanCompileContext& ctx) {
    const VolumePlanner::Settings& settings = mPlanner.settings();
    const bool clamp = settings.far == VolumePlanner::Far::DepthClamp;
    const std::string state =
        std::string("|clamp=") + (clamp ? "1" : "0") + "|bounds=" + (mDepthBounds ? "1" : "0") + "|";
    const Defines scene = withLightKinds(ctx.submitter.defines(), ctx.scene);

    // Ambient: GL's default state (depth LESS with writes), the visibility target written.
    std::string key = "volume-ambient" + state;
    GraphicsPipelineDesc ambient =
        scenePipeline(ctx, "common/scene.vert", "volume/ambient.frag", scene, mLayout, key);
    ambient.depthClamp = clamp;
    mAmbient.build(ctx.pipelines, key, ambient, ctx.targets);

    // Lighting: depth EQUAL without writes, colour ONE + ONE, visibility MAX; with and without the
    // stencil test EQUAL 0.
    for (int stencil = 0; stencil < 2; ++stencil) {
        key = "volume-light" + state + "stencil=" + std::to_string(stencil) + "|";
        GraphicsPipelineDesc light =
            scenePipeline(ctx, "common/scene.vert", "volume/light.frag", scene, mLayout, key);
        light.depthClamp = clamp;
        light.depthWrite = false;
        light.depthCompare = VK_COMPARE_OP_EQUAL;
        light.depthBounds = mDepthBounds;
        light.additive = true;
        light.maxVisibility = true;
        light.stencilTest = stencil == 1;
        light.stencilFront = light.stencilBack =
            stencilOps(VK_COMPARE_OP_EQUAL, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP);
        mLight[stencil].build(ctx.pipelines, key, light, ctx.targets);
    }

    // Marking: the volumes, no colour, depth LESS without writes, two-sided wrapping stencil counts.
    Defines volume;
    if (settings.vertexExtrusion) volume["VS_EXTRUSION"] = "";
    const bool geometry = settings.extrusion == VolumePlanner::Extrusion::Geometry;
    if (geometry) volume["GPU_SILHOUETTES"] = "";
    if (settings.extrusion == VolumePlanner::Extrusion::Compute) volume["PULLED"] = "";
    // extrusion=mesh: volume/silhouette.mesh instead of the vertex stage (no vertex input).
    const bool mesh = settings.extrusion == VolumePlanner::Extrusion::Mesh;
    if (mesh) volume = GpuSilhouettesVulkan::meshDefines();
    ShaderSources volumeSources{"volume/extrude.vert", "volume/stencil.frag",
                                geometry ? "volume/silhouette.geom" : ""};
    if (mesh) {
        volumeSources.vertex.clear();
        volumeSources.mesh = "volume/silhouette.mesh";
    }
    std::string volumeKeys;
    for (int finite = 0; finite < 2; ++finite) {
        if (finite && !(settings.finiteVolumes || settings.boundedVolumes)) continue;
        if (finite) volume["FINITE"] = "";
        for (int zfail = 0; zfail < 2; ++zfail) {
            GraphicsPipelineDesc d;
            const ShaderModules modules = ctx.shaders.get(volumeSources, volume);
            d.vertex = modules.vertex;
            d.geometry = modules.geometry;
            d.fragment = modules.fragment;
            d.mesh = modules.mesh;
            describeVolumeInput(d);
            d.layout = mMarkLayout ? mMarkLayout : mLayout;
            d.depthClamp = clamp;
            d.depthWrite = false;
            d.depthCompare = VK_COMPARE_OP_LESS;
            d.depthBounds = mDepthBounds;
            d.colourWrite = 0;
            d.visibilityWrite = false;
            d.stencilTest = true;
            if (zfail) { // Listing 9-4: count intersections behind the visible point (depth test fails)
                d.stencilFront =
                    stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_DECREMENT_AND_WRAP);
                d.stencilBack =
                    stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_INCREMENT_AND_WRAP);
            } else { // section 9.5.4: count towards the viewer (depth test passes); no caps
                d.stencilFront =
                    stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_INCREMENT_AND_WRAP, VK_STENCIL_OP_KEEP);
                d.stencilBack =
                    stencilOps(VK_COMPARE_OP_ALWAYS, VK_STENCIL_OP_DECREMENT_AND_WRAP, VK_STENCIL_OP_KEEP);
            }
            key = "volume-mark" + state + "zfail=" + std::to_string(zfail) +
                  (mesh ? "|volume/silhouette.mesh" : "|volume/extrude.vert") + "+volume/stencil.frag" +
                  (geometry ? "+volume/silhouette.geom" : "") + "[" + definesKey(volume) + "]";
            mMark[finite][zfail].build(ctx.pipelines, key, d, ctx.targets);
        }
        volumeKeys += "|" + definesKey(volume);
    }
    setPermutationKey(definesKey(scene) + volumeKeys + state);
}

void VolumeVulkan::describeVolumeInput(GraphicsPipelineDesc& d) const {
    constexpr uint32_t vec4 = sizeof(glm::vec4);
    const VolumePlanner::Settings& settings = mPlanner.settings();
    if (settings.vertexExtrusion) {
        d.bindings = {{0, 2 * vec4, VK_VERTEX_INPUT_RATE_VERTEX}};
        d.attributes = {{0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0}, {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, vec4}};
    } else if (settings.extrusion == VolumePlanner::Extrusion::Geometry) {
        // SilhouetteInputs::adjacencyVertices: position, the face's normal and first vertex per vertex.
        d.bindings = {{0, SilhouetteInputs::kVec4PerVertex * vec4, VK_VERTEX_INPUT_RATE_VERTEX}};
        d.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0},
                        {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, vec4},
                        {2, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 2 * vec4}};
        d.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST_WITH_ADJACENCY;
    } else if (settings.extrusion != VolumePlanner::Extrusion::Compute &&
               settings.extrusion != VolumePlanner::Extrusion::Mesh) { // compute: pulled; mesh: no input
        d.bindings = {{0, vec4, VK_VERTEX_INPUT_RATE_VERTEX}};
        d.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 0}};
    }
}

void VolumeVulkan::createSilhouettes(const VulkanCompileContext& ctx) {
    const VolumePlanner::Settings& settings = mPlanner.settings();
    if (!settings.gpuSilhouettes()) return;
    const std::string& device = ctx.context.info().name;
    const bool mesh = settings.extrusion == VolumePlanner::Extrusion::Mesh;
    if (mesh) {
        size_t maxFaces = 0;
        for (const MeshGpu& g : mMeshes)
            if (g.mesh) maxFaces = std::max(maxFaces, g.mesh->faceCount());
        const std::string problem = GpuSilhouettesVulkan::meshShaderProblem(ctx.context, maxFaces);
        if (!problem.empty())
            throw Error("volume: extrusion=mesh needs " + problem +
                            ": unsupported here, skipped (run with extrusion=compute)",
                        ExitCode::Unsupported);
    }
    const bool geometry = settings.extrusion == VolumePlanner::Extrusion::Geometry;
    if (geometry) {
        // The geometry shader counts what it emits in a storage buffer: stores in a pre-rasterisation
        // stage. VulkanContext enables both features wherever the device offers them.
        VkPhysicalDeviceFeatures features{};
        vkGetPhysicalDeviceFeatures(ctx.context.physicalDevice(), &features);
        for (const auto& [offered, name] :
             {std::pair{features.geometryShader, "geometryShader"},
              std::pair{features.vertexPipelineStoresAndAtomics, "vertexPipelineStoresAndAtomics"}})
            if (!offered)
                throw Error(std::string("volume: extrusion=geometry needs the ") + name +
                                " feature, which '" + device +
                                "' does not offer: unsupported here, skipped (run with "
                                "extrusion=compute)",
                            ExitCode::Unsupported);
    }
    std::vector<const ShadowVolumeMesh*> meshes(mMeshes.size(), nullptr);
    for (size_t m = 0; m < mMeshes.size(); ++m) meshes[m] = mMeshes[m].mesh.get();
    mSilhouettes.create(ctx, meshes, settings.extrusion);
    // The marking pipelines' own layout: set 1 the silhouettes' (the count, the extracted entries, or
    // the mesh shader's inputs), and for the geometry or mesh shader push constants in its stage too.
    mMarkPushStages = geometry ? kPushStages | VK_SHADER_STAGE_GEOMETRY_BIT
                      : mesh   ? kPushStages | VK_SHADER_STAGE_MESH_BIT_EXT
                               : kPushStages;
    mMarkLayout = createPipelineLayout(ctx.context, {ctx.frame.setLayout(), mSilhouettes.markLayout()},
                                       sizeof(VulkanPush), mMarkPushStages);
}

std::string VolumeVulkan::checkCapabilities(const VulkanContext& context) const {
    std::string missing = VulkanTechnique::checkCapabilities(context);
    if (!missing.empty()) return missing;
    if (VolumePlanner::readSettings(properties()).extrusion != VolumePlanner::Extrusion::Mesh ||
        context.hasDeviceExtension("VK_EXT_mesh_shader"))
        return "";
    return "volume: extrusion=mesh needs the device extension VK_EXT_mesh_shader (not available on " +
           context.info().name + ", Vulkan " + context.info().apiVersion +
           "); the driver entry mesa-25.0.7 has it: --driver mesa-25.0.7";
}

void VolumeVulkan::compile(const VulkanCompileContext& ctx) {
    release();
    mContext = &ctx.context;
    mDevice = ctx.context.device();
    mPlanner.setSettings(VolumePlanner::readSettings(properties()));
    const VolumePlanner::Settings& settings = mPlanner.settings();
    if (settings.depthBounds && !ctx.context.depthBounds())
        throw Error("volume: depth_bounds needs the depthBounds feature, which '" + ctx.context.info().name +
                        "' does not offer: unsupported here, skipped (run without depth_bounds=true)",
                    ExitCode::Unsupported);
    mDepthBounds = settings.depthBounds;
    if (settings.far == VolumePlanner::Far::DepthClamp && !ctx.context.depthClamp())
        throw Error("volume: far=depth_clamp needs the depthClamp feature, which '" +
                        ctx.context.info().name +
                        "' does not offer: unsupported here, skipped (run with far=infinite)",
                    ExitCode::Unsupported);
    if (!ctx.context.independentBlend())
        throw Error("volume: the light pass blends colour and visibility differently, which needs the "
                    "independentBlend feature '" +
                        ctx.context.info().name + "' does not offer: unsupported here",
                    ExitCode::Unsupported);
    if (!mUploaded) uploadMeshes(ctx.context);
    createDescriptors(ctx.context);
    mLayout = createScenePipelineLayout(ctx, {mSets.layout(0)});
    createSilhouettes(ctx);
    buildPipelines(ctx);
    if (ctx.context.occlusionQueryPrecise()) {
        VkQueryPoolCreateInfo pool{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
        pool.queryType = VK_QUERY_TYPE_OCCLUSION;
        pool.queryCount = 2 * kMaxLights;
        VulkanContext::check(vkCreateQueryPool(mDevice, &pool, nullptr, &mSamples),
                             "vkCreateQueryPool (occlusion)");
    }
}

void VolumeVulkan::readStencilQueries(VkCommandBuffer cmd) {
    // As VolumeGL::readStencilQuery: this slot's queries were issued two frames ago. The harness waited
    // for that frame's fence, so they are there; never wait on them all the same.
    if (!mSamples) return;
    const uint32_t slot = uint32_t(mQueryFrame % 2), first = slot * uint32_t(kMaxLights);
    const int issued = mQueriesIssued[slot];
    if (issued) {
        std::array<uint64_t, kMaxLights> samples{};
        const VkResult r = vkGetQueryPoolResults(mDevice, mSamples, first, uint32_t(issued), sizeof samples,
                                                 samples.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT);
        if (r == VK_SUCCESS) {
            double sum = 0;
            for (int i = 0; i < issued; ++i) sum += double(samples[size_t(i)]);
            mStencilSamples = sum;
        }
    }
    mQueriesIssued[slot] = 0;
    vkCmdResetQueryPool(cmd, mSamples, first, uint32_t(kMaxLights));
}

void VolumeVulkan::setDepthBounds(VkCommandBuffer cmd, int light) const {
    if (!mDepthBounds) return;
    const VolumePlanner::LightRegion& r = mRegions[size_t(light)];
    const glm::vec2 bounds = r.depthBounds ? r.depth : glm::vec2(0.0f, 1.0f);
    vkCmdSetDepthBounds(cmd, bounds.x, bounds.y);
}

void VolumeVulkan::collectFrame(const VulkanFrameContext& ctx, const VolumePlanner::View& view, int lights,
                                VolumePlanner::FrameStats& stats) {
    // The frame's command buffer holds every light's marking pass: each light's indices get their own
    // range of one stream (GL refills its stream buffer per light instead).
    mDraws.clear();
    mFrameStream.clear();
    for (int i = 0; i < lights; ++i) {
        LightDraws& range = mLightDraws[size_t(i)];
        range = {mDraws.size(), mDraws.size()};
        const Light& light = ctx.scene.lights[size_t(i)];
        if (mRegions[size_t(i)].empty()) continue; // the light's range is off screen
        if (!light.castsShadows) {
            ++stats.unshadowedLights;
            continue;
        }
        mPlanner.collectDraws(light, view, stats);
        const uint32_t base = uint32_t(mFrameStream.size());
        mFrameStream.insert(mFrameStream.end(), mPlanner.stream().begin(), mPlanner.stream().end());
        for (VolumePlanner::Draw d : mPlanner.draws()) {
            d.first += base;
            mDraws.push_back(d);
        }
        range.end = mDraws.size();
    }
    if (mPlanner.settings().vertexExtrusion || mFrameStream.empty()) return;
    const VkDeviceSize bytes = mFrameStream.size() * sizeof(uint32_t);
    if (bytes > mStream.size()) {
        // Grow geometrically so a frame with a few more silhouette edges does not reallocate. The last
        // frame that drew from the old buffer has finished (the harness waited for its fence).
        mStream =
            VulkanBuffer(*mContext, std::max(bytes, 2 * mStream.size()), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    }
    std::memcpy(mStream.map(), mFrameStream.data(), size_t(bytes));
}

void VolumeVulkan::writeAmbientBlock(int lights, int height) {
    char* base = static_cast<char*>(mAmbientBlock.map());
    for (int i = 0; i < kMaxLights; ++i) {
        const VolumePlanner::LightRegion& r = mRegions[size_t(i)];
        const glm::ivec4 rect = i < lights ? r.rect : glm::ivec4(0);
        const glm::vec2 depth = i < lights && r.depthBounds ? r.depth : glm::vec2(0.0f, 1.0f);
        std::memcpy(base + kLitRectOffset + 16 * i, &rect, sizeof rect);
        std::memcpy(base + kDepthRangeOffset + 16 * i, &depth, sizeof depth);
    }
    const float h = float(height);
    std::memcpy(base + kTargetHeightOffset, &h, sizeof h);
}

VkRect2D VolumeVulkan::scissorOf(const VolumePlanner::LightRegion& region, int width, int height) const {
    if (!mPlanner.settings().scissor) return {{0, 0}, {uint32_t(width), uint32_t(height)}};
    // GL's rectangle counts y from the bottom; Vulkan's framebuffer y runs top-down.
    const int x0 = std::clamp(region.rect.x, 0, width), x1 = std::clamp(region.rect.z, 0, width);
    const int y0 = std::clamp(region.rect.y, 0, height), y1 = std::clamp(region.rect.w, 0, height);
    return {{x0, height - y1}, {uint32_t(std::max(0, x1 - x0)), uint32_t(std::max(0, y1 - y0))}};
}

void VolumeVulkan::renderAmbient(VulkanFrameContext& ctx, uint32_t frame) {
    // Listing 9-1's ambient + emissive pass: depth written once; the light passes only add.
    ctx.targets.beginPass(ctx.cmd);
    vkCmdBindPipeline(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mAmbient.get(ctx.targets));
    ctx.frame.bind(ctx.cmd, mLayout, frame);
    const VkDescriptorSet set = mSets.set(0);
    vkCmdBindDescriptorSets(ctx.cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, 1, 1, &set, 0, nullptr);
    ctx.submitter.draw(ctx.cmd, mLayout, DrawSet::All);
    vkCmdEndRenderPass(ctx.cmd);
}

void VolumeVulkan::markShadows(VulkanFrameContext& ctx, uint32_t frame, int lightIndex,
                               const VkRect2D& scissor) {
    const Light& light = ctx.scene.lights[size_t(lightIndex)];
    const VolumePlanner::Settings& settings = mPlanner.settings();
    VkCommandBuffer cmd = ctx.cmd;
    ctx.targets.beginPass(cmd);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    // glClear(GL_STENCIL_BUFFER_BIT) inside the scissor rectangle.
    VkClearAttachment clear{};
    clear.aspectMask = VK_IMAGE_ASPECT_STENCIL_BIT;
    clear.colorAttachment = 0;
    clear.clearValue.depthStencil = {1.0f, 0};
    const VkClearRect rect{scissor, 0, 1};
    if (scissor.extent.width && scissor.extent.height) vkCmdClearAttachments(cmd, 1, &clear, 1, &rect);

    const int finite = mPlanner.finiteFor(light) ? 1 : 0;
    using Extrusion = VolumePlanner::Extrusion;
    const Extrusion extrusion = settings.extrusion;
    // The marking pipelines' layout: mLayout, or the geometry path's with the count as set 1.
    const VkPipelineLayout layout = mMarkLayout ? mMarkLayout : mLayout;
    const VkShaderStageFlags pushStages = mMarkLayout ? mMarkPushStages : kPushStages;
    ctx.frame.bind(cmd, layout, frame);
    if (mMarkLayout) {
        const VkDescriptorSet set = mSilhouettes.markSet();
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 1, 1, &set, 0, nullptr);
    }
    setDepthBounds(cmd, lightIndex);
    const uint32_t slot = uint32_t(mQueryFrame % 2);
    if (mSamples)
        vkCmdBeginQuery(cmd, mSamples, slot * uint32_t(kMaxLights) + uint32_t(lightIndex),
                        VK_QUERY_CONTROL_PRECISE_BIT);
    if (extrusion == Extrusion::Cpu && mStream)
        vkCmdBindIndexBuffer(cmd, mStream.buffer(), 0, VK_INDEX_TYPE_UINT32);

    int counting = -1;
    uint32_t boundMesh = UINT32_MAX;
    const LightDraws& range = mLightDraws[size_t(lightIndex)];
    for (size_t k = range.begin; k < range.end; ++k) {
        const VolumePlanner::Draw& d = mDraws[k];
        if (int(d.zfail) != counting) {
            counting = int(d.zfail);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mMark[finite][counting].get(ctx.targets));
        }
        const MeshGpu& gpu = mMeshes[d.caster->mesh];
        if (extrusion != Extrusion::Compute && extrusion != Extrusion::Mesh &&
            d.caster->mesh != boundMesh) { // compute, mesh: set 1 has them
            const VkDeviceSize zero = 0;
            const VkBuffer vb = extrusion == Extrusion::Vertex     ? gpu.extrusionVertices.buffer()
                                : extrusion == Extrusion::Geometry ? mSilhouettes.adjacency(d.caster->mesh)
                                                                   : gpu.doubled.buffer();
            vkCmdBindVertexBuffers(cmd, 0, 1, &vb, &zero);
            if (settings.vertexExtrusion)
                vkCmdBindIndexBuffer(cmd, gpu.extrusionIndices.buffer(), 0, VK_INDEX_TYPE_UINT32);
            boundMesh = d.caster->mesh;
        }
        VulkanPush push;
        push.model = d.caster->model;
        push.vec = d.lightObject;
        if (finite) push.ints.y = floatBits(d.extrusion / d.caster->scale);
        push.ints.z = int32_t(d.gpuFlags);
        push.ints.w = int32_t(d.caster->mesh); // extrusion=mesh: the mesh's bases (volume/silhouette.mesh)
        vkCmdPushConstants(cmd, layout, pushStages, 0, sizeof push, &push);
        if (extrusion == Extrusion::Cpu) {
            vkCmdDrawIndexed(cmd, d.count, 1, d.first, 0, 0);
            continue;
        }
        if (extrusion == Extrusion::Compute) {
            mSilhouettes.drawIndirect(cmd, k);
            continue;
        }
        if (extrusion == Extrusion::Mesh) {
            mSilhouettes.drawMesh(cmd, d.caster->mesh);
            continue;
        }
        if (extrusion == Extrusion::Geometry) {
            vkCmdDraw(cmd, uint32_t(SilhouetteInputs::kVerticesPerFace * gpu.mesh->faceCount()), 1, 0, 0);
            continue;
        }
        if (d.capCount) vkCmdDrawIndexed(cmd, d.capCount, 1, 0, 0, 0);
        if (d.sideCount) vkCmdDrawIndexed(cmd, d.sideCount, 1, gpu.capIndices, 0, 0);
    }
    if (mSamples) {
        vkCmdEndQuery(cmd, mSamples, slot * uint32_t(kMaxLights) + uint32_t(lightIndex));
        mQueriesIssued[slot] = std::max(mQueriesIssued[slot], lightIndex + 1);
    }
    vkCmdEndRenderPass(cmd);
}

void VolumeVulkan::renderLight(VulkanFrameContext& ctx, uint32_t frame, int lightIndex,
                               const VkRect2D& scissor) {
    // Listing 9-1's light pass: add this light where the stencil count is 0, on the surfaces the
    // ambient pass left in the depth buffer. Visibility by MAX, not ADD (VolumeGL::renderLight).
    // A light that casts no shadow marked nothing: no stencil test, as on GL.
    const bool marked = ctx.scene.lights[size_t(lightIndex)].castsShadows;
    VkCommandBuffer cmd = ctx.cmd;
    ctx.targets.beginPass(cmd);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    setDepthBounds(cmd, lightIndex);
    ctx.frame.bind(cmd, mLayout, frame);
    const VkDescriptorSet set = mSets.set(0);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLayout, 1, 1, &set, 0, nullptr);
    VulkanPush push;
    push.ints.x = lightIndex;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLight[marked ? 1 : 0].get(ctx.targets));
    if (mPlanner.hasNonReceivers()) {
        // An instance that receives no shadow is lit whatever the stencil count under it says.
        ctx.submitter.draw(cmd, mLayout, DrawSet::Receivers, {}, push);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, mLight[0].get(ctx.targets));
        ctx.submitter.draw(cmd, mLayout, DrawSet::NonReceivers, {}, push);
    } else {
        ctx.submitter.draw(cmd, mLayout, DrawSet::All, {}, push);
    }
    vkCmdEndRenderPass(cmd);
}

void VolumeVulkan::execute(VulkanFrameContext& ctx) {
    ctx.submitter.resetStats();
    const int width = ctx.targets.width(), height = ctx.targets.height();
    const glm::mat4 proj = mPlanner.projection(ctx.proj);
    const VolumePlanner::View view = VolumePlanner::viewOf(proj, ctx.view, width, height);
    // The scene passes must use the same projection as the volumes: a frame-block slot of its own.
    const uint32_t frame = ctx.frame.write(computeFrameUniforms(ctx.scene, ctx.view, proj, ctx.eye));

    const int lights = std::min<int>(int(ctx.scene.lights.size()), kMaxLights);
    for (int i = 0; i < lights; ++i)
        mRegions[size_t(i)] =
            mPlanner.regionOf(ctx.scene.lights[size_t(i)], ctx.view, view, proj, mDepthBounds);
    VolumePlanner::FrameStats stats;
    collectFrame(ctx, view, lights, stats);
    writeAmbientBlock(lights, height);

    // Outside the passes' render passes: the queries are reset before the marking passes reuse them,
    // and the compute path builds every light's volumes.
    readStencilQueries(ctx.cmd);
    const VolumePlanner::Settings& settings = mPlanner.settings();
    if (settings.gpuSilhouettes()) mSilhouettes.beginFrame();
    if (settings.extrusion == VolumePlanner::Extrusion::Compute) mSilhouettes.extract(ctx.cmd, mDraws);
    // The ambient and light passes cull alike (one view for both): the light passes' EQUAL test finds
    // the surfaces the ambient pass left. The volumes are not the submitter's: both faces.
    const CullView sceneView{proj * ctx.view, false};
    ctx.submitter.setCullView(&sceneView, true);
    ctx.passes.begin("ambient");
    renderAmbient(ctx, frame);
    for (int i = 0; i < lights; ++i) {
        const VolumePlanner::LightRegion& region = mRegions[size_t(i)];
        if (region.empty()) continue; // the light's range is off screen: it adds nothing to this frame
        const VkRect2D scissor = scissorOf(region, width, height);
        if (ctx.scene.lights[size_t(i)].castsShadows) {
            ctx.passes.begin("mark");
            markShadows(ctx, frame, i, scissor);
        } else { // no volume, no stencil test: the light pass lights everything it reaches
            ctx.passes.skip("mark", "a light that casts no shadow");
        }
        ctx.passes.begin("lighting");
        renderLight(ctx, frame, i, scissor);
    }
    ctx.submitter.setCullView(nullptr, true);
    if (settings.gpuSilhouettes()) mSilhouettes.endFrame(ctx.cmd);
    ++mQueryFrame;
    mCounters = mPlanner.counters(stats, ctx.submitter.stats(),
                                  mSamples ? std::optional<double>(mStencilSamples) : std::nullopt);
}

Counters VolumeVulkan::counters() const {
    if (!mPlanner.settings().gpuSilhouettes()) return mCounters;
    return VolumePlanner::withDeviceTriangles(mCounters, mSilhouettes.readTriangles());
}

} // namespace sb
