#include "techniques/volume/VolumeTechnique.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/type_ptr.hpp>

#include "core/Error.h"
#include "scenes/Motion.h"

namespace sb {

namespace {
constexpr const char* kMode = "mode";
constexpr const char* kExtrusion = "extrusion";
constexpr const char* kFar = "far";
constexpr const char* kOpenEdges = "open_edges";
constexpr const char* kDirectional = "directional";
constexpr const char* kRangeCull = "range_cull";
constexpr const char* kFrustumCull = "frustum_cull";
constexpr const char* kScissor = "scissor";
constexpr const char* kFiniteVolumes = "finite_volumes";
constexpr const char* kBoundedVolumes = "bounded_volumes";
constexpr const char* kDepthBounds = "depth_bounds";
// shaders/volume/extrude.vert and light.frag
constexpr GLint kModelLocation = 0, kLightLocation = 1, kRangeLocation = 2, kLightIndexLocation = 12;
// shaders/volume/ambient.frag
constexpr GLint kLitRectLocation = 13, kDepthRangeLocation = 17;

glm::vec4 worldLight(const Light& l) {
    // The chapter's L: the position for point and spot lights, the vector towards a directional one.
    return l.type == LightType::Directional ? glm::vec4(-glm::normalize(l.direction), 0.0f)
                                            : glm::vec4(l.position, 1.0f);
}

Aabb transformBounds(const glm::mat4& m, const Aabb& b) {
    Aabb out;
    for (const glm::vec4& c : VolumeGeometry::corners(b)) out.extend(glm::vec3(m * c));
    return out;
}

bool rangedFinite(const Light& l, bool finiteVolumes) {
    return finiteVolumes && l.type != LightType::Directional && l.range > 0.0f;
}

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        choice(kMode, "auto", {"zfail", "zpass", "auto"},
               "stencil counting: z-fail with caps, z-pass without, or per caster (occlusion pyramid)"),
        choice(kExtrusion, "cpu", {"cpu", "vertex"},
               "silhouettes on the CPU per caster (chapter) or in the vertex shader (McGuire-Hughes)"),
        choice(kFar, "infinite", {"infinite", "depth_clamp", "finite"},
               "far plane at infinity, depth clamping, or the camera's (negative control)"),
        choice(kOpenEdges, "multiplicity", {"multiplicity", "refuse"},
               "casters with open edges: count per-edge multiplicities (closed meshes keep the chapter's "
               "volumes), or refuse naming the mesh"),
        flag(kDirectional, "true", "directional lights: sides as triangles to one point, no dark cap"),
        flag(kRangeCull, "true", "point/spot: casters outside the light's range cast nothing"),
        flag(kFrustumCull, "true", "cull light cap, dark cap and sides against the view frustum"),
        flag(kScissor, "true", "scissor marking and lighting to the light range's screen bounds"),
        flag(kFiniteVolumes, "false", "point/spot with range: extrude by the range, not to infinity"),
        flag(kBoundedVolumes, "true",
             "directional: extrude only past the scene's bounds, not to infinity (beyond 9.6.1)"),
        flag(kDepthBounds, "false", "depth bounds test of the light range (GL_EXT_depth_bounds_test)"),
    };
}
} // namespace

VolumeTechnique::VolumeTechnique()
    : Technique({.name = "volume",
                 .description = "stencil shadow volumes (GPU Gems ch. 9), each optimisation a switch",
                 .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                            Effect::MultipleLights,
                 .capabilities = {{"GL 4.5", 4, 5, ""}},
                 .passes = {"ambient", "mark", "lighting"},
                 .viewPasses = {"ambient", "lighting"},
                 .properties = declareProperties(),
                 .quality = {}}) {}

VolumeTechnique::~VolumeTechnique() {
    for (auto& slot : mQueries)
        if (slot[0]) glDeleteQueries(GLsizei(slot.size()), slot.data());
}

glm::mat4 VolumeTechnique::infiniteFrom(const glm::mat4& proj) {
    // glm::perspective: [2][2] = -(f + n) / (f - n), [3][2] = -2 f n / (f - n), so
    // n = [3][2] / ([2][2] - 1). Only the depth row changes (Listing 9-2's limit with the epsilon
    // guard of VolumeGeometry::infinitePerspective); the x and y rows are kept as they are, so a
    // sub-pixel jitter or off-centre frustum of the camera (the accuracy harness's shifts) survives.
    const float nearZ = proj[3][2] / (proj[2][2] - 1.0f);
    const glm::mat4 limit =
        VolumeGeometry::infinitePerspective(2.0f * std::atan(1.0f / proj[1][1]), 1.0f, nearZ);
    glm::mat4 out = proj;
    out[2][2] = limit[2][2];
    out[3][2] = limit[3][2];
    return out;
}

OpenEdgePolicy VolumeTechnique::policyFor(const ShadowVolumeMesh& mesh) const {
    // The chapter's closed volumes are exact for a closed mesh and cost half of the multiplicity form
    // (which draws every face in both caps and each silhouette side twice, counting 2 inside): closed
    // casters keep them whatever the property says, so the multiplicity default costs them nothing.
    return mesh.closed() ? OpenEdgePolicy::Closed : mSettings.policy;
}

bool VolumeTechnique::boundedFor(const Light& light) const {
    return mSettings.boundedVolumes && light.type == LightType::Directional && !mSceneBounds.empty();
}

VolumeTechnique::Settings VolumeTechnique::readSettings() const {
    const PropertySet& p = properties();
    Settings s;
    const std::string& mode = p.getEnum(kMode);
    s.mode = mode == "zfail" ? Mode::ZFail : mode == "zpass" ? Mode::ZPass : Mode::Auto;
    const std::string& far = p.getEnum(kFar);
    s.far = far == "depth_clamp" ? Far::DepthClamp : far == "finite" ? Far::Finite : Far::Infinite;
    s.vertexExtrusion = p.getEnum(kExtrusion) == "vertex";
    s.policy =
        p.getEnum(kOpenEdges) == "multiplicity" ? OpenEdgePolicy::Multiplicity : OpenEdgePolicy::Closed;
    s.directional = p.getBool(kDirectional);
    s.rangeCull = p.getBool(kRangeCull);
    s.frustumCull = p.getBool(kFrustumCull);
    s.scissor = p.getBool(kScissor);
    s.finiteVolumes = p.getBool(kFiniteVolumes);
    s.boundedVolumes = p.getBool(kBoundedVolumes);
    s.depthBounds = p.getBool(kDepthBounds);
    return s;
}

void VolumeTechnique::checkClosed(const Scene& scene) const {
    if (mSettings.policy != OpenEdgePolicy::Closed) return;
    // The user asked for closed casters only and the scene has an open one: their input and their
    // choice disagree (exit 2); the context lacks nothing (exit 3 is for that).
    for (size_t m = 0; m < mBuffers.size(); ++m) {
        const ShadowVolumeMesh* mesh = mBuffers.mesh(m).mesh.get();
        if (!mesh || mesh->closed()) continue;
        throw Error("volume: caster mesh '" + scene.meshes[m].name + "' has " +
                        std::to_string(mesh->openEdgeCount()) +
                        " open edges after welding and open_edges=refuse was asked for (closed-mesh "
                        "volumes of open meshes leak streaks, GPU Gems 9.1.1); use the default "
                        "open_edges=multiplicity, or make the instance not cast",
                    ExitCode::BadInput);
    }
}

void VolumeTechnique::setScene(const Scene& scene) {
    mSettings = readSettings();
    mScene = &scene;
    mHasNonReceivers = scene.hasNonReceivers();
    mBuffers.upload(scene, mSettings.vertexExtrusion, mSettings.policy);
    checkClosed(scene);
    mMeshBounds.resize(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) mMeshBounds[m] = scene.meshes[m].computeBounds();
    placeCasters(scene);
}

void VolumeTechnique::placeCasters(const Scene& scene) {
    mCasters.clear();
    mSceneBounds = Aabb{};
    for (uint32_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        const Aabb bounds = transformBounds(inst.model, mMeshBounds[inst.mesh]);
        mSceneBounds.extend(bounds);
        if (!inst.castsShadow) continue;
        Caster c;
        c.instance = i;
        c.mesh = inst.mesh;
        c.model = inst.model;
        c.inverseModel = glm::inverse(inst.model);
        c.bounds = bounds;
        c.scale = inst.scale;
        mCasters.push_back(c);
    }
    // Draw order inside a light: by mesh, so the VAO changes once per mesh.
    std::stable_sort(mCasters.begin(), mCasters.end(),
                     [](const Caster& a, const Caster& b) { return a.mesh < b.mesh; });
}

void VolumeTechnique::sceneChanged(const Scene& scene, uint32_t changes) {
    // Silhouettes, extrusions and the light regions are found every frame from the lights as they are;
    // what a static scene fixes once is where the casters stand.
    if (changes & kCastersMoved) placeCasters(scene);
}

void VolumeTechnique::compile(const CompileContext& ctx) {
    mSettings = readSettings();
    mHasDepthBounds = ctx.context.hasExtension("GL_EXT_depth_bounds_test");
    if (mSettings.depthBounds && !mHasDepthBounds)
        throw Error("volume: depth_bounds needs GL_EXT_depth_bounds_test, which '" + ctx.context.renderer +
                        "' does not expose: unsupported here, skipped (run without depth_bounds=true)",
                    ExitCode::Unsupported);
    Defines scene = ctx.submitter.defines();
    mAmbientProgram = &ctx.programs.get({"common/scene.vert", "volume/ambient.frag", ""}, scene);
    mLightProgram = &ctx.programs.get({"common/scene.vert", "volume/light.frag", ""}, scene);
    Defines volume;
    if (mSettings.vertexExtrusion) volume["VS_EXTRUSION"] = "";
    mVolumeProgram = &ctx.programs.get({"volume/extrude.vert", "volume/stencil.frag", ""}, volume);
    volume["FINITE"] = "";
    mFiniteProgram = mSettings.finiteVolumes || mSettings.boundedVolumes
                         ? &ctx.programs.get({"volume/extrude.vert", "volume/stencil.frag", ""}, volume)
                         : nullptr;
    std::string key = mAmbientProgram->key() + "|" + mLightProgram->key() + "|" + mVolumeProgram->key();
    if (mFiniteProgram) key += "|" + mFiniteProgram->key();
    setPermutationKey(key);
    if (!mFrameUniforms) mFrameUniforms = std::make_unique<FrameUniforms>();
    if (!mQueries[0][0])
        for (auto& slot : mQueries) glGenQueries(GLsizei(slot.size()), slot.data());
}

VolumeTechnique::LightRegion VolumeTechnique::regionOf(const Light& light, const FrameContext& ctx,
                                                       const View& view, const glm::mat4& proj) const {
    LightRegion r;
    r.rect = {0, 0, view.width, view.height};
    if (mSettings.scissor) {
        const std::optional<glm::ivec4> rect =
            VolumeGeometry::scissorRect(light, view.viewProj, view.width, view.height);
        r.rect = rect ? glm::ivec4(rect->x, rect->y, rect->x + rect->z, rect->y + rect->w) : glm::ivec4(0);
    }
    if (mSettings.depthBounds && mHasDepthBounds) {
        const std::optional<glm::vec2> bounds = VolumeGeometry::depthBounds(light, ctx.view, proj);
        if (bounds) r.depthBounds = true, r.depth = *bounds;
    }
    return r;
}

void VolumeTechnique::renderAmbient(FrameContext& ctx, int lights) {
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

void VolumeTechnique::collectDraws(const Light& light, const View& view, FrameStats& stats) {
    mDraws.clear();
    mStream.clear();
    const glm::vec4 lw = worldLight(light);
    const bool bounded = boundedFor(light);
    const bool finite = bounded || rangedFinite(light, mSettings.finiteVolumes);
    for (const Caster& c : mCasters) {
        if (mSettings.rangeCull && !VolumeGeometry::lightReaches(light, c.bounds)) {
            ++stats.rangeCulled;
            continue;
        }
        Draw d;
        d.caster = &c;
        d.lightObject = c.inverseModel * lw;
        if (finite)
            d.extrusion = bounded ? VolumeGeometry::boundedExtrusion(mSceneBounds, c.bounds, -glm::vec3(lw))
                                  : light.range;
        d.zfail =
            mSettings.mode == Mode::ZFail ||
            (mSettings.mode == Mode::Auto && VolumeGeometry::mayShadowViewport(view.nearRect, lw, c.bounds));
        VolumeGeometry::CapCull cull;
        if (mSettings.frustumCull) cull = VolumeGeometry::cullVolume(view.frustum, c.bounds, lw);
        if (finite) cull.darkCap = false; // the finite dark cap is near the scene, not at infinity
        const VolumeMeshBuffers::Gpu& gpu = mBuffers.mesh(c.mesh);
        if (mSettings.vertexExtrusion) {
            // Light and dark caps are the same triangles here (the shader decides which each is).
            const bool caps = d.zfail && !(cull.lightCap && cull.darkCap);
            d.capCount = caps ? gpu.extrusionCapIndices : 0;
            d.sideCount = cull.sides ? 0 : gpu.extrusionSideIndices;
            if (d.capCount + d.sideCount == 0) continue;
            stats.volumeTriangles += double(d.capCount + d.sideCount) / 3.0;
        } else {
            VolumeRequest r;
            r.light = d.lightObject;
            r.caps = d.zfail;
            r.lightCap = !cull.lightCap;
            r.darkCap = !cull.darkCap;
            r.sides = !cull.sides;
            // A finite volume needs its dark cap: the directional form closes sides at infinity.
            r.directionalForm = mSettings.directional && lw.w == 0.0f && !finite;
            r.policy = policyFor(*gpu.mesh);
            gpu.mesh->buildVolume(r, mVolume);
            d.first = GLint(mStream.size());
            for (const auto* part : {&mVolume.lightCap, &mVolume.darkCap, &mVolume.sides})
                mStream.insert(mStream.end(), part->begin(), part->end());
            d.count = GLsizei(mStream.size()) - d.first;
            if (d.count == 0) continue;
            stats.silhouetteEdges += mVolume.silhouetteEdges;
            stats.volumeTriangles += double(d.count) / 3.0;
        }
        if (d.zfail) stats.capsCulled += double(cull.lightCap) + double(cull.darkCap);
        (d.zfail ? stats.zfail : stats.zpass) += 1;
        mDraws.push_back(d);
    }
    // z-fail casters first, then z-pass: one change of the stencil operations per light.
    std::stable_partition(mDraws.begin(), mDraws.end(), [](const Draw& d) { return d.zfail; });
    if (!mSettings.vertexExtrusion) mBuffers.streamIndices(mStream);
}

void VolumeTechnique::setStencilCounting(bool zfail) const {
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

void VolumeTechnique::markShadows(int lightIndex) {
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
    const bool finite = boundedFor(light) || rangedFinite(light, mSettings.finiteVolumes);
    const Program* program = finite ? mFiniteProgram : mVolumeProgram;
    program->use();
    const GLuint query = mQueries[mQueryFrame % 2][size_t(lightIndex)];
    glBeginQuery(GL_SAMPLES_PASSED, query);
    int counting = -1;
    uint32_t boundMesh = UINT32_MAX;
    for (const Draw& d : mDraws) {
        if (int(d.zfail) != counting) setStencilCounting(d.zfail), counting = int(d.zfail);
        const VolumeMeshBuffers::Gpu& gpu = mBuffers.mesh(d.caster->mesh);
        if (d.caster->mesh != boundMesh) {
            glBindVertexArray(mSettings.vertexExtrusion ? gpu.extrusionVao : gpu.doubledVao);
            boundMesh = d.caster->mesh;
        }
        glUniformMatrix4fv(kModelLocation, 1, GL_FALSE, glm::value_ptr(d.caster->model));
        glUniform4fv(kLightLocation, 1, glm::value_ptr(d.lightObject));
        if (finite) glUniform1f(kRangeLocation, d.extrusion / d.caster->scale);
        if (!mSettings.vertexExtrusion) {
            glDrawElements(GL_TRIANGLES, d.count, GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(size_t(d.first) * sizeof(uint32_t)));
            continue;
        }
        if (d.capCount) glDrawElements(GL_TRIANGLES, d.capCount, GL_UNSIGNED_INT, nullptr);
        if (d.sideCount)
            glDrawElements(GL_TRIANGLES, d.sideCount, GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(size_t(gpu.extrusionCapIndices) * sizeof(uint32_t)));
    }
    glEndQuery(GL_SAMPLES_PASSED);
    mQueriesIssued[mQueryFrame % 2] = std::max(mQueriesIssued[mQueryFrame % 2], lightIndex + 1);
    glBindVertexArray(0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void VolumeTechnique::renderLight(FrameContext& ctx, int lightIndex) {
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
    if (mHasNonReceivers) {
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

void VolumeTechnique::readStencilQuery() {
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

void VolumeTechnique::execute(FrameContext& ctx) {
    ctx.submitter.resetStats();
    View view;
    const glm::mat4 proj = mSettings.far == Far::Infinite ? infiniteFrom(ctx.proj) : ctx.proj;
    view.viewProj = proj * ctx.view;
    view.frustum = VolumeGeometry::frustumPlanes(view.viewProj);
    view.nearRect = VolumeGeometry::nearRectangle(view.viewProj);
    view.width = ctx.targets.width();
    view.height = ctx.targets.height();
    // The scene passes must use the same projection as the volumes: this technique's own frame block.
    mFrameUniforms->upload(FrameUniforms::compute(*mScene, ctx.view, proj, ctx.eye));
    if (mSettings.far == Far::DepthClamp) glEnable(GL_DEPTH_CLAMP);

    const int lights = std::min<int>(int(mScene->lights.size()), kMaxLights);
    for (int i = 0; i < lights; ++i)
        mRegions[size_t(i)] = regionOf(mScene->lights[size_t(i)], ctx, view, proj);
    ctx.passes.begin("ambient");
    renderAmbient(ctx, lights);
    readStencilQuery();
    FrameStats stats;
    for (int i = 0; i < lights; ++i) {
        const Light& light = mScene->lights[size_t(i)];
        const LightRegion& region = mRegions[size_t(i)];
        if (region.empty()) continue; // the light's range is off screen: it adds nothing to this frame
        if (mSettings.scissor) {
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

    const SubmitStats& s = ctx.submitter.stats();
    mCounters = {{"draw_calls", double(s.drawCalls)},
                 {"triangles", double(s.triangles)},
                 {"volume_triangles", stats.volumeTriangles},
                 {"casters_zfail", stats.zfail},
                 {"casters_zpass", stats.zpass},
                 {"casters_range_culled", stats.rangeCulled},
                 {"caps_culled", stats.capsCulled},
                 {"stencil_samples_passed", mStencilSamples},
                 {"lights_unshadowed", stats.unshadowedLights}};
    // The vertex-shader path finds silhouettes on the GPU: there is no count to report.
    if (!mSettings.vertexExtrusion) mCounters.emplace_back("silhouette_edges", stats.silhouetteEdges);
}

} // namespace sb
