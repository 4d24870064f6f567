#include "techniques/volume/VolumeGL.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "scenes/Motion.h"

namespace sb {

namespace {
// shaders/volume/extrude.vert and light.frag
constexpr GLint kModelLocation = 0, kLightLocation = 1, kRangeLocation = 2, kLightIndexLocation = 12;
// shaders/volume/silhouette.geom
constexpr GLint kFlagsLocation = 3;
// shaders/volume/ambient.frag
constexpr GLint kLitRectLocation = 13, kDepthRangeLocation = 17;
} // namespace

VolumeGL::VolumeGL() : GlTechnique(Volume::declaration()) {}

VolumeGL::~VolumeGL() {
    for (auto& slot : mQueries)
        if (slot[0]) glDeleteQueries(GLsizei(slot.size()), slot.data());
}

void VolumeGL::setScene(const Scene& scene) {
    mPlanner.setSettings(VolumePlanner::readSettings(properties()));
    const VolumePlanner::Settings& settings = mPlanner.settings();
    mScene = &scene;
    using Extrusion = VolumePlanner::Extrusion;
    mBuffers.upload(scene,
                    {.extrusion = settings.vertexExtrusion,
                     .adjacency = settings.extrusion == Extrusion::Geometry,
                     .faces = settings.extrusion == Extrusion::Compute},
                    settings.policy);
    if (settings.gpuSilhouettes()) mSilhouettes.create(settings.extrusion == Extrusion::Compute);
    std::vector<VolumePlanner::MeshInfo> meshes(mBuffers.size());
    for (size_t m = 0; m < mBuffers.size(); ++m) {
        const VolumeMeshBuffers::Gpu& gpu = mBuffers.mesh(m);
        meshes[m] = {gpu.mesh.get(), uint32_t(gpu.extrusionCapIndices), uint32_t(gpu.extrusionSideIndices)};
    }
    mPlanner.setMeshes(std::move(meshes));
    mPlanner.checkClosed(scene);
    mPlanner.checkGpuSilhouettes(scene);
    mPlanner.setScene(scene);
}

void VolumeGL::sceneChanged(const Scene& scene, uint32_t changes) {
    // Silhouettes, extrusions and the light regions are found every frame from the lights as they are;
    // what a static scene fixes once is where the casters stand.
    if (changes & kCastersMoved) mPlanner.placeCasters(scene);
}

void VolumeGL::compile(const CompileContext& ctx) {
    mPlanner.setSettings(VolumePlanner::readSettings(properties()));
    const VolumePlanner::Settings& settings = mPlanner.settings();
    mHasDepthBounds = ctx.context.hasExtension("GL_EXT_depth_bounds_test");
    if (settings.depthBounds && !mHasDepthBounds)
        throw Error("volume: depth_bounds needs GL_EXT_depth_bounds_test, which '" + ctx.context.renderer +
                        "' does not expose: unsupported here, skipped (run without depth_bounds=true)",
                    ExitCode::Unsupported);
    if (settings.extrusion == VolumePlanner::Extrusion::Mesh)
        throw Error("volume: extrusion=mesh needs VK_EXT_mesh_shader, which GL does not have: unsupported "
                    "here (run with --api vulkan --driver mesa-25.0.7)",
                    ExitCode::Unsupported);
    Defines scene = withLightKinds(ctx.submitter.defines(), ctx.scene);
    mAmbientProgram = &ctx.programs.get({"common/scene.vert", "volume/ambient.frag", ""}, scene);
    mLightProgram = &ctx.programs.get({"common/scene.vert", "volume/light.frag", ""}, scene);
    Defines volume;
    if (settings.vertexExtrusion) volume["VS_EXTRUSION"] = "";
    if (settings.extrusion == VolumePlanner::Extrusion::Compute) volume["PULLED"] = "";
    const bool geometry = settings.extrusion == VolumePlanner::Extrusion::Geometry;
    if (geometry) volume["GPU_SILHOUETTES"] = "";
    const ShaderSources volumeSources{"volume/extrude.vert", "volume/stencil.frag",
                                      geometry ? "volume/silhouette.geom" : ""};
    mVolumeProgram = &ctx.programs.get(volumeSources, volume);
    volume["FINITE"] = "";
    mFiniteProgram = settings.finiteVolumes || settings.boundedVolumes
                         ? &ctx.programs.get(volumeSources, volume)
                         : nullptr;
    mSilhouetteProgram = settings.extrusion == VolumePlanner::Extrusion::Compute
                             ? &ctx.programs.get({.compute = "volume/silhouette.comp"}, {})
                             : nullptr;
    std::string key = mAmbientProgram->key() + "|" + mLightProgram->key() + "|" + mVolumeProgram->key();
    if (mFiniteProgram) key += "|" + mFiniteProgram->key();
    if (mSilhouetteProgram) key += "|compute";
    setPermutationKey(key);
    if (!mFrameUniforms) mFrameUniforms = std::make_unique<FrameUniforms>();
    if (!mQueries[0][0])
        for (auto& slot : mQueries) glGenQueries(GLsizei(slot.size()), slot.data());
}

void VolumeGL::renderAmbient(FrameContext& ctx, int lights) {
    // Listing 9-1's ambient + emissive pass: depth written once; the light passes only add. Where a
    // light pass will not run (outside its scissor rectangle or depth bounds: beyond the light's range)
    // nothing is shadowed, so the visibility target gets 1 there now (the range is a lighting term,
    // not a shadow); inside, 0 until the light pass adds 1 where the stencil count is 0.
    mAmbientProgram->use();
    std::array<glm::ivec4, kMaxLights> rects{};
    std::array<glm::vec2, kMaxLights> depths{};
    for (int i = 0; i < lights; ++i) {
        const LightRegion& r = mRegions[size_t(i)];
        rects[size_t(i)] = r.rect;
        depths[size_t(i)] = r.depthBounds ? r.depth : glm::vec2(0.0f, 1.0f);
    }
    glUniform4iv(kLitRectLocation, kMaxLights, glm::value_ptr(rects[0]));
    glUniform2fv(kDepthRangeLocation, kMaxLights, glm::value_ptr(depths[0]));
    ctx.submitter.draw(DrawSet::All);
}

void VolumeGL::collectDraws(const Light& light, const View& view, FrameStats& stats) {
    mPlanner.collectDraws(light, view, stats);
    if (mPlanner.settings().extrusion == VolumePlanner::Extrusion::Cpu)
        mBuffers.streamIndices(mPlanner.stream());
}

void VolumeGL::setStencilCounting(bool zfail) const {
    if (zfail) {
        // Listing 9-4: count intersections behind the visible point (depth test fails).
        glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
        glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
    } else {
        // Section 9.5.4: count towards the viewer (depth test passes); no caps needed.
        glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
        glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    }
}

void VolumeGL::markShadows(int lightIndex) {
    const Light& light = mScene->lights[size_t(lightIndex)];
    glStencilMask(0xff);
    glClear(GL_STENCIL_BUFFER_BIT); // inside the scissor rectangle when scissoring
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    // LESS: the light cap lies on the caster's lit surface at the same depth and must count as behind
    // it in z-fail (the point just under that surface is inside the volume); same vertex arithmetic as
    // the ambient pass, so the depths are equal, not merely close.
    glDepthFunc(GL_LESS);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    const bool finite = mPlanner.finiteFor(light);
    using Extrusion = VolumePlanner::Extrusion;
    const Extrusion extrusion = mPlanner.settings().extrusion;
    if (extrusion == Extrusion::Compute)
        mSilhouettes.extract(mPlanner.draws(), mBuffers, *mSilhouetteProgram);
    if (extrusion == Extrusion::Geometry) mSilhouettes.bindCount();
    const Program* program = finite ? mFiniteProgram : mVolumeProgram;
    program->use();
    const GLuint query = mQueries[mQueryFrame % 2][size_t(lightIndex)];
    glBeginQuery(GL_SAMPLES_PASSED, query);
    int counting = -1;
    uint32_t boundMesh = UINT32_MAX;
    const std::vector<Draw>& draws = mPlanner.draws();
    for (size_t i = 0; i < draws.size(); ++i) {
        const Draw& d = draws[i];
        if (int(d.zfail) != counting) setStencilCounting(d.zfail), counting = int(d.zfail);
        const VolumeMeshBuffers::Gpu& gpu = mBuffers.mesh(d.caster->mesh);
        if (d.caster->mesh != boundMesh) {
            glBindVertexArray(extrusion == Extrusion::Vertex     ? gpu.extrusionVao
                              : extrusion == Extrusion::Geometry ? gpu.adjacencyVao
                              : extrusion == Extrusion::Compute  ? mSilhouettes.vertexArray()
                                                                 : gpu.doubledVao);
            if (extrusion == Extrusion::Compute) mSilhouettes.bindCaster(gpu.doubledVbo);
            boundMesh = d.caster->mesh;
        }
        glUniformMatrix4fv(kModelLocation, 1, GL_FALSE, glm::value_ptr(d.caster->model));
        glUniform4fv(kLightLocation, 1, glm::value_ptr(d.lightObject));
        if (finite) glUniform1f(kRangeLocation, d.extrusion / d.caster->scale);
        if (extrusion == Extrusion::Cpu) {
            glDrawElements(GL_TRIANGLES, GLsizei(d.count), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(size_t(d.first) * sizeof(uint32_t)));
            continue;
        }
        if (extrusion == Extrusion::Compute) {
            mSilhouettes.drawIndirect(i);
            continue;
        }
        if (extrusion == Extrusion::Geometry) {
            glUniform1ui(kFlagsLocation, d.gpuFlags);
            glDrawArrays(GL_TRIANGLES_ADJACENCY, 0,
                         GLsizei(SilhouetteInputs::kVerticesPerFace * gpu.mesh->faceCount()));
            continue;
        }
        if (d.capCount) glDrawElements(GL_TRIANGLES, GLsizei(d.capCount), GL_UNSIGNED_INT, nullptr);
        if (d.sideCount)
            glDrawElements(GL_TRIANGLES, GLsizei(d.sideCount), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(size_t(gpu.extrusionCapIndices) * sizeof(uint32_t)));
    }
    glEndQuery(GL_SAMPLES_PASSED);
    if (extrusion == Extrusion::Compute) glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    mQueriesIssued[mQueryFrame % 2] = std::max(mQueriesIssued[mQueryFrame % 2], lightIndex + 1);
    glBindVertexArray(0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void VolumeGL::renderLight(FrameContext& ctx, int lightIndex) {
    // Listing 9-1's light pass: add this light where the stencil count is 0, on the surfaces the
    // ambient pass left in the depth buffer.
    glDepthFunc(GL_EQUAL);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    // Visibility by MAX, not ADD: coincident triangles (a mesh's duplicated seams) pass depth EQUAL
    // twice and would count a light twice; the colour keeps the chapter's additive blend.
    glBlendEquationi(1, GL_MAX);
    glStencilFunc(GL_EQUAL, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    mLightProgram->use();
    glUniform1i(kLightIndexLocation, lightIndex);
    if (mPlanner.hasNonReceivers()) {
        // An instance that receives no shadow is lit whatever the stencil count under it says.
        ctx.submitter.draw(DrawSet::Receivers);
        glDisable(GL_STENCIL_TEST);
        ctx.submitter.draw(DrawSet::NonReceivers);
    } else {
        ctx.submitter.draw(DrawSet::All);
    }
    glBlendEquationi(1, GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
}

void VolumeGL::readStencilQuery() {
    // This slot's queries were issued two frames ago; read them if the GPU has them, never wait.
    const size_t slot = mQueryFrame % 2;
    double sum = 0;
    for (int i = 0; i < mQueriesIssued[slot]; ++i) {
        GLuint available = 0;
        glGetQueryObjectuiv(mQueries[slot][size_t(i)], GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return;
        GLuint64 samples = 0;
        glGetQueryObjectui64v(mQueries[slot][size_t(i)], GL_QUERY_RESULT, &samples);
        sum += double(samples);
    }
    if (mQueriesIssued[slot]) mStencilSamples = sum;
    mQueriesIssued[slot] = 0;
}

void VolumeGL::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    const VolumePlanner::Settings& settings = mPlanner.settings();
    const glm::mat4 proj = mPlanner.projection(ctx.proj);
    const View view = VolumePlanner::viewOf(proj, ctx.view, ctx.targets.width(), ctx.targets.height());
    // The scene passes must use the same projection as the volumes: this technique's own frame block.
    mFrameUniforms->upload(computeFrameUniforms(*mScene, ctx.view, proj, ctx.eye));
    if (settings.far == VolumePlanner::Far::DepthClamp) glEnable(GL_DEPTH_CLAMP);
    // The ambient and light passes cull alike (one view for both): the light passes' GL_EQUAL finds the
    // surfaces the ambient pass left. The volumes themselves are not the submitter's: both faces.
    const CullView sceneView{proj * ctx.view, false};
    const BackFaceScope culling(ctx.submitter, sceneView);

    const int lights = std::min<int>(int(mScene->lights.size()), kMaxLights);
    for (int i = 0; i < lights; ++i)
        mRegions[size_t(i)] =
            mPlanner.regionOf(mScene->lights[size_t(i)], ctx.view, view, proj, mHasDepthBounds);
    ctx.passes.begin("ambient");
    renderAmbient(ctx, lights);
    readStencilQuery();
    if (settings.gpuSilhouettes()) mSilhouettes.beginFrame();
    FrameStats stats;
    for (int i = 0; i < lights; ++i) {
        const Light& light = mScene->lights[size_t(i)];
        const LightRegion& region = mRegions[size_t(i)];
        if (region.empty()) continue; // the light's range is off screen: it adds nothing to this frame
        if (settings.scissor) {
            glScissor(region.rect.x, region.rect.y, region.rect.z - region.rect.x,
                      region.rect.w - region.rect.y);
            glEnable(GL_SCISSOR_TEST);
        }
        if (region.depthBounds) {
            glEnable(GL_DEPTH_BOUNDS_TEST_EXT);
            glDepthBoundsEXT(region.depth.x, region.depth.y);
        }
        if (light.castsShadows) {
            ctx.passes.begin("mark");
            collectDraws(light, view, stats);
            markShadows(i);
        } else { // no volume, no stencil test: the light pass lights everything it reaches
            ctx.passes.skip("mark", "a light that casts no shadow");
            ++stats.unshadowedLights;
        }
        ctx.passes.begin("lighting");
        renderLight(ctx, i);
        glDisable(GL_SCISSOR_TEST);
        if (region.depthBounds) glDisable(GL_DEPTH_BOUNDS_TEST_EXT);
    }
    ++mQueryFrame;
    glDisable(GL_DEPTH_CLAMP);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);

    mCounters = mPlanner.counters(stats, ctx.submitter.stats(), mStencilSamples);
}

Counters VolumeGL::counters() const {
    if (!mPlanner.settings().gpuSilhouettes()) return mCounters;
    return VolumePlanner::withDeviceTriangles(mCounters, mSilhouettes.readTriangles());
}

} // namespace sb
