#include "techniques/volume/VolumePlanner.h"

#include <algorithm>
#include <cmath>

#include "core/Error.h"

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

Aabb transformBounds(const glm::mat4& m, const Aabb& b) {
    Aabb out;
    for (const glm::vec4& c : VolumeGeometry::corners(b)) out.extend(glm::vec3(m * c));
    return out;
}

bool rangedFinite(const Light& l, bool finiteVolumes) {
    return finiteVolumes && l.type != LightType::Directional && l.range > 0.0f;
}
} // namespace

std::vector<PropertyDesc> VolumePlanner::declareProperties() {
    return {
        choice(kMode, "auto", {"zfail", "zpass", "auto"},
               "stencil counting: z-fail with caps, z-pass without, or per caster (occlusion pyramid)"),
        choice(kExtrusion, "cpu", {"cpu", "vertex", "geometry", "compute", "mesh"},
               "silhouettes on the CPU per caster (chapter), in the vertex shader (McGuire-Hughes), or per "
               "face in a geometry, compute or mesh (Vulkan) shader, counted on the device"),
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

VolumePlanner::Settings VolumePlanner::readSettings(const PropertySet& p) {
    Settings s;
    const std::string& mode = p.getEnum(kMode);
    s.mode = mode == "zfail" ? Mode::ZFail : mode == "zpass" ? Mode::ZPass : Mode::Auto;
    const std::string& far = p.getEnum(kFar);
    s.far = far == "depth_clamp" ? Far::DepthClamp : far == "finite" ? Far::Finite : Far::Infinite;
    const std::string& extrusion = p.getEnum(kExtrusion);
    s.extrusion = extrusion == "vertex"     ? Extrusion::Vertex
                  : extrusion == "geometry" ? Extrusion::Geometry
                  : extrusion == "compute"  ? Extrusion::Compute
                  : extrusion == "mesh"     ? Extrusion::Mesh
                                            : Extrusion::Cpu;
    s.vertexExtrusion = s.extrusion == Extrusion::Vertex;
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

glm::mat4 VolumePlanner::infiniteFrom(const glm::mat4& proj) {
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

glm::vec4 VolumePlanner::worldLight(const Light& l) {
    return l.type == LightType::Directional ? glm::vec4(-glm::normalize(l.direction), 0.0f)
                                            : glm::vec4(l.position, 1.0f);
}

OpenEdgePolicy VolumePlanner::policyFor(const ShadowVolumeMesh& mesh) const {
    // The chapter's closed volumes are exact for a closed mesh and cost half of the multiplicity form
    // (which draws every face in both caps and each silhouette side twice, counting 2 inside): closed
    // casters keep them whatever the property says, so the multiplicity default costs them nothing.
    return mesh.closed() ? OpenEdgePolicy::Closed : mSettings.policy;
}

bool VolumePlanner::boundedFor(const Light& light) const {
    return mSettings.boundedVolumes && light.type == LightType::Directional && !mSceneBounds.empty();
}

bool VolumePlanner::finiteFor(const Light& light) const {
    return boundedFor(light) || rangedFinite(light, mSettings.finiteVolumes);
}

void VolumePlanner::checkClosed(const Scene& scene) const {
    if (mSettings.policy != OpenEdgePolicy::Closed) return;
    // The user asked for closed casters only and the scene has an open one: their input and their
    // choice disagree (exit 2); the context lacks nothing (exit 3 is for that).
    for (size_t m = 0; m < mMeshes.size(); ++m) {
        const ShadowVolumeMesh* mesh = mMeshes[m].mesh;
        if (!mesh || mesh->closed()) continue;
        throw Error("volume: caster mesh '" + scene.meshes[m].name + "' has " +
                        std::to_string(mesh->openEdgeCount()) +
                        " open edges after welding and open_edges=refuse was asked for (closed-mesh "
                        "volumes of open meshes leak streaks, GPU Gems 9.1.1); use the default "
                        "open_edges=multiplicity, or make the instance not cast",
                    ExitCode::BadInput);
    }
}

void VolumePlanner::checkGpuSilhouettes(const Scene& scene) const {
    if (!mSettings.gpuSilhouettes()) return;
    for (size_t m = 0; m < mMeshes.size(); ++m) {
        const ShadowVolumeMesh* mesh = mMeshes[m].mesh;
        if (!mesh || mesh->closed()) continue;
        throw Error("volume: caster mesh '" + scene.meshes[m].name + "' has " +
                        std::to_string(mesh->openEdgeCount()) +
                        " open edges after welding; the GPU silhouette paths (extrusion=geometry, compute, "
                        "mesh) build the chapter's closed-mesh volume only: use extrusion=cpu or vertex",
                    ExitCode::Unsupported);
    }
}

void VolumePlanner::setScene(const Scene& scene) {
    mHasNonReceivers = scene.hasNonReceivers();
    mMeshBounds.resize(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) mMeshBounds[m] = scene.meshBoundsOf(m);
    placeCasters(scene);
}

void VolumePlanner::placeCasters(const Scene& scene) {
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
    // Draw order inside a light: by mesh, so the vertex buffer changes once per mesh.
    std::stable_sort(mCasters.begin(), mCasters.end(),
                     [](const Caster& a, const Caster& b) { return a.mesh < b.mesh; });
}

glm::mat4 VolumePlanner::projection(const glm::mat4& cameraProj) const {
    return mSettings.far == Far::Infinite ? infiniteFrom(cameraProj) : cameraProj;
}

VolumePlanner::View VolumePlanner::viewOf(const glm::mat4& proj, const glm::mat4& cameraView, int width,
                                          int height) {
    View view;
    view.viewProj = proj * cameraView;
    view.frustum = VolumeGeometry::frustumPlanes(view.viewProj);
    view.nearRect = VolumeGeometry::nearRectangle(view.viewProj);
    view.width = width;
    view.height = height;
    return view;
}

VolumePlanner::LightRegion VolumePlanner::regionOf(const Light& light, const glm::mat4& cameraView,
                                                   const View& view, const glm::mat4& proj,
                                                   bool depthBoundsAvailable) const {
    LightRegion r;
    r.rect = {0, 0, view.width, view.height};
    if (mSettings.scissor) {
        const std::optional<glm::ivec4> rect =
            VolumeGeometry::scissorRect(light, view.viewProj, view.width, view.height);
        r.rect = rect ? glm::ivec4(rect->x, rect->y, rect->x + rect->z, rect->y + rect->w) : glm::ivec4(0);
    }
    if (mSettings.depthBounds && depthBoundsAvailable) {
        const std::optional<glm::vec2> bounds = VolumeGeometry::depthBounds(light, cameraView, proj);
        if (bounds) r.depthBounds = true, r.depth = *bounds;
    }
    return r;
}

void VolumePlanner::collectDraws(const Light& light, const View& view, FrameStats& stats) {
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
        const MeshInfo& mesh = mMeshes[c.mesh];
        if (mSettings.gpuSilhouettes()) {
            // buildVolume's request as bits; the device builds and counts the volume.
            namespace F = GpuVolumeFlags;
            const bool directional = mSettings.directional && lw.w == 0.0f && !finite;
            d.gpuFlags = (d.zfail && !cull.lightCap ? F::kLightCap : 0u) |
                         (d.zfail && !cull.darkCap && !directional ? F::kDarkCap : 0u) |
                         (cull.sides ? 0u : F::kSides) | (directional ? F::kDirectional : 0u);
            if (!(d.gpuFlags & (F::kLightCap | F::kDarkCap | F::kSides))) continue;
        } else if (mSettings.vertexExtrusion) {
            // Light and dark caps are the same triangles here (the shader decides which each is).
            const bool caps = d.zfail && !(cull.lightCap && cull.darkCap);
            d.capCount = caps ? mesh.capIndices : 0;
            d.sideCount = cull.sides ? 0 : mesh.sideIndices;
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
            r.policy = policyFor(*mesh.mesh);
            mesh.mesh->buildVolume(r, mVolume);
            d.first = uint32_t(mStream.size());
            for (const auto* part : {&mVolume.lightCap, &mVolume.darkCap, &mVolume.sides})
                mStream.insert(mStream.end(), part->begin(), part->end());
            d.count = uint32_t(mStream.size()) - d.first;
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
}

Counters VolumePlanner::counters(const FrameStats& stats, const SubmitStats& s,
                                 std::optional<double> stencilSamples) const {
    Counters out = {{"draw_calls", double(s.drawCalls)},
                    {"triangles", double(s.triangles)},
                    {"volume_triangles", stats.volumeTriangles},
                    {"casters_zfail", stats.zfail},
                    {"casters_zpass", stats.zpass},
                    {"casters_range_culled", stats.rangeCulled},
                    {"caps_culled", stats.capsCulled}};
    if (stencilSamples) out.emplace_back("stencil_samples_passed", *stencilSamples);
    out.emplace_back("lights_unshadowed", stats.unshadowedLights);
    // The vertex-shader path finds silhouettes on the GPU: there is no count to report.
    if (mSettings.extrusion == Extrusion::Cpu) out.emplace_back("silhouette_edges", stats.silhouetteEdges);
    return out;
}

Counters VolumePlanner::withDeviceTriangles(Counters counters, double triangles) {
    for (auto& [name, value] : counters)
        if (name == "volume_triangles") value = triangles;
    return counters;
}

} // namespace sb
