#include "techniques/planar/Planar.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/MeshGenerators.h"
#include "scenes/ProxyCollection.h"
#include "scenes/ShadowWork.h"
#include "shading/ShaderLimits.h"
#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        flag(Planar::kStencil, "true",
             "the slides' stencil algorithm (false: depth-tested with bias: double blending, shadows off the "
             "receiver)"),
        choice(Planar::kOccluder, "mesh", {"mesh", "proxy"},
               "what is flattened: the caster's mesh, or its ShadowProxy (sphere/box/cylinder)"),
        real(Planar::kDarkness, "1", 0, 1,
             "share of the light a shadow removes (1: ambient only, like the other techniques)"),
        flag(Planar::kGuards, "true",
             "clip occluder parts behind the receiver or beyond the light, skip lights behind the plane "
             "(false: the slides' wrong shadows and anti-shadows)"),
        flag(Planar::kCull, "true",
             "leave out of a flattening the casters whose flattened bounds miss the view (mesh occluders; "
             "a flattening none reaches is skipped, its receiver marking too)"),
    };
}

} // namespace

TechniqueInfo Planar::declaration() {
    return {.name = "planar",
            .description = "projected planar shadows: casters flattened onto each receiver plane, stencil "
                           "keeps them on it (no self-shadowing, planar receivers only)",
            .effects = Effect::HardShadows | Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"lighting", "shadows"},
            .properties = declareProperties(),
            .quality = {
                {kOccluder, {"mesh", "proxy"}},
                {kStencil, {"true", "false"}},
            }};
}

std::vector<Planar::Projection> Planar::projections(const std::vector<ReceiverPlane>& planes,
                                                    const Scene& scene, bool guards) {
    std::vector<Projection> out;
    const int lights = std::min<int>(int(scene.lights.size()), kMaxLights);
    for (size_t p = 0; p < planes.size(); ++p)
        for (int l = 0; l < lights; ++l) {
            if (!scene.lights[size_t(l)].castsShadows) continue; // a fill light: nothing flattened
            const glm::vec4 light = ReceiverPlane::homogeneousLight(scene.lights[size_t(l)]);
            // Relative to the light's coordinates: a light "in" the plane up to float rounding of its
            // position casts nothing (every occluder would collapse onto the light's footprint).
            const float side = planes[p].lightSide(light);
            if (guards && !(side > 1e-6f * std::max(1.0f, glm::length(glm::vec3(light))))) continue;
            out.push_back({p, l, light, planes[p].projection(light)});
        }
    return out;
}

Scene Planar::unitShapes() {
    Scene s;
    s.meshes.push_back(MeshGenerators::sphere(6));
    s.meshes.push_back(MeshGenerators::box(glm::vec3(1.0f), 1));
    Mesh cylinder = MeshGenerators::cylinder(6); // along +y: turn y onto z
    const glm::mat3 yToZ = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(1, 0, 0)));
    for (glm::vec3& p : cylinder.positions) p = yToZ * p;
    for (glm::vec3& n : cylinder.normals) n = yToZ * n;
    s.meshes.push_back(std::move(cylinder));
    return s;
}

Planar::ProxyPlan Planar::planProxies(const Scene& scene, const Scene& shapes) {
    const std::vector<ShadowProxy> proxies = ProxyCollection::collect(scene, false, nullptr);
    ProxyPlan plan;
    for (size_t s = 0; s < shapes.meshes.size(); ++s) {
        ProxyBatch b{s, uint32_t(plan.records.size()), 0};
        for (const ShadowProxy& p : proxies)
            if (size_t(p.shape) == s) plan.records.push_back({p.frame, glm::vec4(p.diffuse, 0.0f)});
        b.count = uint32_t(plan.records.size()) - b.first;
        plan.triangles += uint64_t(shapes.meshes[s].indices.size() / 3) * uint64_t(b.count);
        if (b.count) plan.batches.push_back(b);
    }
    return plan;
}

Counters Planar::counters(const SubmitStats& s, const FrameCounts& f, const Scene& scene) {
    const double proxies = f.proxies ? double(f.flattenings) : 0.0;
    return {{"draw_calls", double(s.drawCalls) + proxies * double(f.proxyBatches)},
            {"triangles", double(s.triangles) + proxies * double(f.proxyTriangles)},
            {"receiver_planes", double(f.planes)},
            {"flattenings", double(f.flattenings)},
            {"casters_culled", double(f.culled)},
            {"lights_unshadowed", double(ShadowWork::unshadowedLights(scene, kMaxLights))}};
}

} // namespace sb
