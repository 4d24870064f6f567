#include "techniques/shadowmap/CubeMap.h"

#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/Property.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/shadowmap/CubeFaces.h"

namespace sb {

using P = ShadowMapProperties;

namespace {

std::vector<PropertyDesc> declareProperties() {
    return {
        P::resolution("1024", "width and height of each cube face and of each spot/directional map (texels)"),
        P::biasConstant(),
        P::biasSlope(),
        P::pcf("PCF kernel width: pcf x pcf taps one texel apart on the face"),
        flag(CubeMap::kLayered, "true",
             "one pass per light with a geometry shader routing triangles to faces (true, where the "
             "context allows it), or six passes per light with per-face caster culling (false)"),
    };
}

} // namespace

TechniqueInfo CubeMap::declaration() {
    return ContactShadows::declare(
        {.name = "cubemap",
         .description = "omnidirectional shadow mapping: a depth cube map per point light",
         .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                    Effect::MultipleLights,
         .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
         .passes = {"depth", "lighting"},
         .properties = declareProperties(),
         .quality =
             {
                 {P::kResolution, {"256", "512", "1024", "2048"}},
                 P::pcfSweep(),
                 P::biasConstantSweep(),
                 P::biasSlopeSweep(),
             },
         .resources = [](const PropertySet& p, const ResourceInputs& in) {
             return squareMaps(p.getInt(P::kResolution), kDepthTexelBytes, CubeFaces::kFaces, in);
         }});
}

std::vector<CubeMap::Cube> CubeMap::cubes(const OmniLightSet& lights) {
    std::vector<Cube> cubes;
    for (const OmniLight& o : lights.lights())
        if (o.kind == OmniMapKind::Omni)
            cubes.push_back({o.point, CubeFaces(o.point.position, o.point.nearZ, o.point.farZ)});
    return cubes;
}

Defines CubeMap::lightingDefines(Defines lit, const PropertySet& p, const OmniLightSet& lights) {
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(lights.shaderLightCount());
    lit["PCF_SIZE"] = std::to_string(p.getInt(P::kPcf));
    if (lights.flatCount() > 0) lit["FLAT_MAPS"] = "";
    if (lights.omniCount() > 0) lit["OMNI_MAPS"] = "";
    ContactShadows::addDefines(p, lit);
    return lit;
}

Counters CubeMap::counters(const SubmitStats& s, int resolution, const OmniLightSet& lights,
                           size_t facesRendered, size_t culled) {
    const double res = double(resolution);
    const double maps = double(CubeFaces::kFaces * lights.omniCount() + lights.flatCount());
    return DepthLightingFrame::counters(s, res * res * maps,
                                        {{"faces_rendered", double(facesRendered)},
                                         {"casters_culled", double(culled)},
                                         {"lights_skipped", double(lights.skippedCount())},
                                         {"lights_unshadowed", double(lights.unshadowedCount())}});
}

} // namespace sb
