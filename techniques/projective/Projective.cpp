#include "techniques/projective/Projective.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "scenes/ShadowWork.h"
#include "shading/ShaderLimits.h"
#include "techniques/LightFitProperties.h"
#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        integer(Projective::kResolution, "512", 16, 8192, "projective texture width and height (texels)"),
        integer(Projective::kBlur, "0", 0, 32, "blur radius in texels: the slides' fake softness"),
        flag(Projective::kCull, "true",
             "leave out of each light's texture the casters whose shadow cannot reach the view (blur 0 only: "
             "a blurred edge reaches further)"),
        LightFitProperties::fit("projector", "point and spot lights aim at the casters' bounding sphere"),
        LightFitProperties::fitMargin(),
    };
}

} // namespace

TechniqueInfo Projective::declaration() {
    return {.name = "projective",
            .description = "projective texture shadows: casters black on white from each light, "
                           "projected onto the non-casting receivers (no self-shadowing)",
            // Blurred edges are a fixed-width fake, not soft shadows; casters are never shadowed.
            .effects = Effect::HardShadows | Effect::NonPlanarReceivers | Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"texture", "blur", "lighting"},
            .properties = declareProperties(),
            .quality =
                {
                    {kResolution, {"128", "256", "512", "1024", "2048"}},
                    {kBlur, {"0", "1", "2", "4", "8"}},
                },
            .resources = [](const PropertySet& p, const ResourceInputs& in) {
                return squareMaps(p.getInt(kResolution), 1, 1, in, 1);
            }};
}

namespace {
/// World bounds of the instances that cast no shadow: DrawSet::NonCasters, what the texture is
/// projected onto.
Aabb receiverBounds(const Scene& scene) {
    Aabb bounds;
    for (const Instance& inst : scene.instances)
        if (!inst.castsShadow && inst.mesh < scene.meshes.size())
            bounds.extend(transformBounds(scene.meshBoundsOf(inst.mesh), inst.model));
    return bounds;
}

/// `a` and `b`'s common part (empty when they do not meet).
Aabb intersect(const Aabb& a, const Aabb& b) {
    Aabb r;
    if (a.empty() || b.empty()) return r;
    r.min = glm::max(a.min, b.min);
    r.max = glm::min(a.max, b.max);
    if (glm::any(glm::greaterThan(r.min, r.max))) return {};
    return r;
}

bool contains(const Aabb& box, const glm::vec3& p) {
    return glm::all(glm::greaterThanEqual(p, box.min)) && glm::all(glm::lessThanEqual(p, box.max));
}

/// The half-angle that holds a cone of half-angle `exact` off the texture's border: 1% and a quarter
/// degree of padding (the border is white: lit).
float padded(float exact) {
    return exact * 1.01f + glm::radians(0.25f);
}
} // namespace

Projective::Projector Projective::aimAtReceivers(const Light& light, const Aabb& receivers) {
    const glm::vec3 toCentre = receivers.center() - light.position;
    // The light among the receivers (a room's walls and floor around it) has no one direction
    // towards them: the spot's axis, or straight down.
    glm::vec3 forward = light.type == LightType::Spot ? glm::normalize(light.direction) : glm::vec3(0, -1, 0);
    if (!contains(receivers, light.position) && glm::length(toCentre) > 0.0f)
        forward = glm::normalize(toCentre);
    float cosWidest = 1.0f, deepest = 0.0f;
    for (const glm::vec3& c : receivers.corners()) {
        const glm::vec3 d = c - light.position;
        const float len = glm::length(d);
        if (!(len > 0.0f)) continue;
        cosWidest = std::min(cosWidest, glm::dot(d, forward) / len);
        deepest = std::max(deepest, glm::dot(d, forward));
    }
    Projector p;
    float half = padded(std::acos(std::clamp(cosWidest, -1.0f, 1.0f)));
    if (!(half < glm::radians(kMaxHalfAngleDeg))) {
        half = glm::radians(kMaxHalfAngleDeg);
        p.clamped = true;
    }
    // Far just past the deepest receiver corner: a caster beyond every receiver shadows none of them.
    // Near a thousandth of it: a silhouette has no depth to resolve, so only clipping matters, and
    // everything between the light and the receivers belongs in the texture.
    const float farZ = std::max(deepest * 1.01f, 1e-4f);
    const glm::mat4 view = glm::lookAt(light.position, light.position + forward, anyPerpendicularUp(forward));
    p.viewProj = glm::perspective(2.0f * half, 1.0f, 1e-3f * farZ, farZ) * view;
    return p;
}

Projective::Projector Projective::computeProjector(const Scene& scene, const Light& light,
                                                   const LightFit& fit) {
    if (light.type == LightType::Directional) return {fitLightViewProjection(scene, light, fit), false};
    // Point and spot: a perspective projector at the light looking at the casters' bounding sphere.
    const Aabb casters = scene.computeBounds(true);
    const glm::vec3 centre = casters.center();
    const float radius = std::max(0.5f * glm::length(casters.extent()), 1e-4f);
    const glm::vec3 toCentre = centre - light.position;
    const float dist = glm::length(toCentre);
    if (!(dist > radius)) {
        // Inside the sphere the casters are all around the light; what can shadow a receiver lies
        // between the light and the receivers (within the range, beyond which nothing is lit).
        Aabb receivers = receiverBounds(scene);
        if (light.range > 0.0f)
            receivers = intersect(receivers, Aabb{light.position - glm::vec3(light.range),
                                                  light.position + glm::vec3(light.range)});
        if (!receivers.empty()) return aimAtReceivers(light, receivers);
    }
    // The light at the centre itself has no direction towards it: the spot's axis, or straight down.
    glm::vec3 forward = toCentre / dist;
    if (!(dist > 1e-6f * radius))
        forward = light.type == LightType::Spot ? glm::normalize(light.direction) : glm::vec3(0, -1, 0);
    const float maxHalf = glm::radians(kMaxHalfAngleDeg);
    Projector p;
    float half = maxHalf;
    // The sphere subtends asin(r / dist) around the axis.
    if (dist > radius) half = padded(std::asin(radius / dist));
    if (!(half < maxHalf)) {
        half = maxHalf;
        p.clamped = true;
    }
    const float nearZ = std::max(dist - radius, 1e-3f * std::max(dist, radius));
    const float farZ = std::max(dist + radius, 2.0f * nearZ);
    const glm::mat4 view = glm::lookAt(light.position, light.position + forward, anyPerpendicularUp(forward));
    p.viewProj = glm::perspective(2.0f * half, 1.0f, nearZ, farZ) * view;
    return p;
}

Projective::Plan Projective::plan(const Scene& scene, const PropertySet& properties) {
    const LightFit fit = LightFitProperties::lightFit(properties);
    Plan p;
    p.receivers = receiverBounds(scene);
    // No casters, no light that casts, or no receiver: nothing to project, everything is lit (and the
    // frame does no texture work).
    p.noProjector =
        scene.computeBounds(true).empty() ? "no instance casts a shadow" : ShadowWork::noneNeeded(scene);
    if (p.noProjector) return p;
    const size_t count = std::min<size_t>(scene.lights.size(), kMaxLights);
    const glm::mat4 bias =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));
    for (size_t i = 0; i < count; ++i) {
        p.castsShadows.push_back(scene.lights[i].castsShadows);
        if (!scene.lights[i].castsShadows) { // a layer never drawn nor looked up (common/lighting.glsl)
            p.viewProj.emplace_back(1.0f);
            p.textureMatrix.push_back(bias);
            continue;
        }
        const Projector projector = computeProjector(scene, scene.lights[i], fit);
        p.viewProj.push_back(projector.viewProj);
        p.textureMatrix.push_back(bias * projector.viewProj);
        p.clamped += projector.clamped;
    }
    return p;
}

Counters Projective::counters(const SubmitStats& s, const Scene& scene, int resolution,
                              const std::vector<uint8_t>& castsShadows, int blurPasses, int clamped,
                              size_t culled) {
    return {{"draw_calls", double(s.drawCalls)},
            {"triangles", double(s.triangles)},
            {"projective_texels", double(resolution) * resolution *
                                      double(std::count(castsShadows.begin(), castsShadows.end(), 1))},
            {"blur_passes", double(blurPasses)},
            {"projector_clamped", double(clamped)},
            {"casters_culled", double(culled)},
            {"lights_unshadowed", double(ShadowWork::unshadowedLights(scene, kMaxLights))}};
}

} // namespace sb
