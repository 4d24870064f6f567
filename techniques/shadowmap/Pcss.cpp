#include "techniques/shadowmap/Pcss.h"

#include <algorithm>
#include <cmath>

#include "techniques/ContactShadows.h"
#include "techniques/LightFitProperties.h"
#include "techniques/Property.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/PoissonDisk.h"

namespace sb {

using P = ShadowMapProperties;

namespace {

/// Row r of a matrix (GLM is column-major).
glm::vec4 row(const glm::mat4& m, int r) {
    return glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
}

/// The light size the scene gives `light` (0 when it has no extent), see Pcss.h.
float sceneLightSize(const Light& light) {
    if (light.shape == LightShape::Point) return 0.0f;
    if (light.type == LightType::Directional)
        return 2.0f * std::tan(glm::radians(std::clamp(light.angularRadiusDeg, 0.0f, 89.0f)));
    if (light.shape == LightShape::Rect) // the disk of the same area
        return 2.0f * std::sqrt(std::max(light.size.x * light.size.y, 0.0f) / float(M_PI));
    return 2.0f * std::max(light.size.x, 0.0f); // disk and sphere: the diameter
}

/// Linear depth (Pcss::LightParams) of the nearest corner of the casters' bounds, held within the
/// map's depth range. Both a perspective map's w and an orthographic map's depth are linear in the world
/// position, so the nearest point of a box is one of its corners.
float nearestCasterDepth(const Scene& scene, const glm::mat4& lightViewProj, const Pcss::LightParams& lp) {
    Aabb casters = scene.computeBounds(true);
    if (casters.empty()) return lp.nearZ;
    float nearest = lp.farZ;
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 corner((c & 1) ? casters.max.x : casters.min.x,
                               (c & 2) ? casters.max.y : casters.min.y,
                               (c & 4) ? casters.max.z : casters.min.z);
        const glm::vec4 clip = lightViewProj * glm::vec4(corner, 1.0f);
        // Perspective: w is the depth along the axis; orthographic: window depth times (far - near).
        const float z = lp.perspective ? clip.w : (0.5f * clip.z / clip.w + 0.5f) * lp.farZ;
        nearest = std::min(nearest, z);
    }
    return std::clamp(nearest, lp.nearZ, lp.farZ);
}

std::vector<PropertyDesc> declareProperties() {
    return {
        P::resolution("2048", "shadow map width and height (texels)"),
        integer(Pcss::kBlockerTaps, "16", 1, Pcss::kMaxTaps, "Poisson taps of the blocker search (step 1)"),
        integer(Pcss::kFilterTaps, "32", 1, Pcss::kMaxTaps,
                "Poisson taps of the PCF over the penumbra (step 3)"),
        real(Pcss::kLightSize, "0", 0, 1e6,
             "light size L (0 = the scene's emitter): diameter in world units for spot lights, width per "
             "unit depth (2 tan of the angular radius) for directional lights"),
        P::biasConstant("glPolygonOffset units of the depth pass"),
        P::biasSlope("glPolygonOffset factor of the depth pass"),
        LightFitProperties::fit("map", "spot lights take their cone"),
        LightFitProperties::fitMargin(),
    };
}

} // namespace

TechniqueInfo Pcss::declaration() {
    return ContactShadows::declare(
        {.name = "pcss",
         .description = "percentage-closer soft shadows: blocker search, penumbra estimate, PCF over "
                        "it (a light with no extent gets a 1 degree emitter: counter "
                        "light_size_defaulted); penumbra width -5% to +9% of the closed form on thin "
                        "edges, +39% on a 1-thick box edge (techniques/shadowmap/README.md)",
         .effects = Effect::HardShadows | Effect::SoftShadows | Effect::SelfShadowing |
                    Effect::NonPlanarReceivers | Effect::MultipleLights,
         .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
         .passes = {"depth", "lighting"},
         .properties = declareProperties(),
         .quality =
             {
                 {P::kResolution, {"512", "1024", "2048", "4096"}},
                 {kBlockerTaps, {"4", "8", "16", "32"}},
                 {kFilterTaps, {"8", "16", "32", "64"}},
                 {kLightSize, {"0", "0.05", "0.2", "0.5"}},
             },
         .resources = [](const PropertySet& p, const ResourceInputs& in) {
             return squareMaps(p.getInt(P::kResolution), kDepthTexelBytes, 1, in);
         }});
}

Pcss::LightParams Pcss::lightParams(const Scene& scene, const Light& light, const glm::mat4& lightViewProj,
                                    float sizeOverride) {
    LightParams lp;
    const glm::vec4 r0 = row(lightViewProj, 0), r1 = row(lightViewProj, 1);
    const glm::vec4 r2 = row(lightViewProj, 2), r3 = row(lightViewProj, 3);
    lp.extent = glm::vec2(2.0f / glm::length(glm::vec3(r0)), 2.0f / glm::length(glm::vec3(r1)));
    lp.perspective = glm::dot(glm::vec3(r3), glm::vec3(r3)) > 0.0f;
    if (lp.perspective) {
        // Clip z = alpha w + beta (glm::perspective): alpha = (f + n) / (f - n), beta = -2 f n / (f - n).
        const float alpha = glm::dot(glm::vec3(r2), glm::vec3(r3)) / glm::dot(glm::vec3(r3), glm::vec3(r3));
        const float beta = r2.w - alpha * r3.w;
        lp.nearZ = -beta / (alpha + 1.0f);
        lp.farZ = beta / (1.0f - alpha);
    } else {
        lp.nearZ = 0.0f; // depth from the near plane: 2 / |row 2| = far - near
        lp.farZ = 2.0f / glm::length(glm::vec3(r2));
    }
    lp.nearestCaster = nearestCasterDepth(scene, lightViewProj, lp);
    float size = sizeOverride > 0.0f ? sizeOverride : sceneLightSize(light);
    if (!(size > 0.0f)) {
        lp.defaulted = true;
        size = 2.0f * std::tan(glm::radians(kDefaultAngularRadiusDeg));
        if (light.type != LightType::Directional) {
            Aabb casters = scene.computeBounds(true);
            if (casters.empty()) casters = scene.computeBounds(false);
            size *= std::max(glm::length(casters.center() - light.position), 1e-3f);
        }
    }
    lp.size = size;
    return lp;
}

glm::vec4 Pcss::lightVector(const LightParams& lp) {
    return {lp.size, lp.perspective ? 1.0f : 0.0f, lp.nearZ, lp.farZ};
}

glm::vec4 Pcss::searchVector(const LightParams& lp) {
    return {lp.extent, lp.nearestCaster, 0.0f};
}

Counters Pcss::counters(const SubmitStats& s, int mapSize, const FlatLightFits& fits, size_t culled,
                        size_t blockerTaps, size_t filterTaps, const std::vector<LightParams>& params) {
    const size_t lights = fits.size(), shadowed = fits.shadowed();
    double defaulted = 0.0;
    for (const LightParams& lp : params) defaulted += lp.defaulted ? 1.0 : 0.0;
    return {{"draw_calls", double(s.drawCalls)},
            {"triangles", double(s.triangles)},
            {"shadow_map_texels", double(mapSize) * mapSize * double(shadowed)},
            {"lights_unshadowed", double(lights - shadowed)},
            {"casters_culled", double(culled)},
            {"blocker_taps", double(blockerTaps)},
            {"filter_taps", double(filterTaps)},
            {"light_size", params.empty() ? 0.0 : double(params[0].size)},
            {"light_size_defaulted", defaulted},
            {"map_covered_pct", fits.coverage().percent()}};
}

uint64_t Pcss::filterSeed() {
    return PoissonDisk::kSeed ^ 0x46494c544552ull;
}

} // namespace sb
