#include "techniques/shadowmap/Paraboloid.h"

#include <algorithm>
#include <cmath>

#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/Property.h"
#include "techniques/ShadowMapProperties.h"

namespace sb {

using P = ShadowMapProperties;

namespace {

std::vector<PropertyDesc> declareProperties() {
    return {
        P::resolution("2048",
                      "width and height of each paraboloid half and of each spot/directional map (texels)"),
        P::biasConstant(),
        P::biasSlope(),
        P::pcf("PCF kernel width: pcf x pcf taps one texel apart in map space"),
        flag(Paraboloid::kSplit, "true",
             "split the triangles of casters whose edges span more than the angle whose chord stays within "
             "half a texel of its arc, in a geometry stage of the depth pass (true), or project per vertex "
             "only, as the paper does (false: long edges bend, and shadow is lost at the halves' seam)"),
    };
}

} // namespace

TechniqueInfo Paraboloid::declaration() {
    return ContactShadows::declare(
        {.name = "paraboloid",
         .description = "dual-paraboloid shadow maps: two hemispherical depth maps per point light",
         .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                    Effect::MultipleLights,
         .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
         .passes = {"depth", "lighting"},
         .properties = declareProperties(),
         .quality =
             {
                 {P::kResolution, {"512", "1024", "2048", "4096"}},
                 P::pcfSweep(),
                 P::biasConstantSweep(),
                 P::biasSlopeSweep(),
             },
         .resources = [](const PropertySet& p, const ResourceInputs& in) {
             return squareMaps(p.getInt(P::kResolution), kDepthTexelBytes, 2, in);
         }});
}

float Paraboloid::beyondRim(int resolution, int pcf) {
    // The lookup's footprint reaches pcf / 2 texels plus the bilinear one past its centre; one more
    // for the half-texel chords of the cut. At the rim a map unit spans one radian, a texel 2 /
    // resolution of both.
    const float texels = 0.5f * float(pcf) + 2.0f;
    return std::sin(texels * 2.0f / float(std::max(resolution, 1)));
}

glm::vec3 Paraboloid::hemisphereAxis(int half) {
    return half == 0 ? glm::vec3(0.0f, -1.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

Defines Paraboloid::lightingDefines(Defines lit, const PropertySet& p, const OmniLightSet& lights) {
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(lights.shaderLightCount());
    lit["PCF_SIZE"] = std::to_string(p.getInt(P::kPcf));
    if (lights.flatCount() > 0) lit["FLAT_MAPS"] = "";
    if (lights.omniCount() > 0) lit["OMNI_MAPS"] = "";
    ContactShadows::addDefines(p, lit);
    return lit;
}

Counters Paraboloid::counters(const SubmitStats& s, int resolution, int layers, const OmniLightSet& lights,
                              int hemispheresRendered, size_t culled, size_t split) {
    const double res = double(resolution);
    return DepthLightingFrame::counters(s, res * res * double(layers),
                                        {{"hemispheres_rendered", double(hemispheresRendered)},
                                         {"casters_culled", double(culled)},
                                         {"casters_split", double(split)},
                                         {"lights_skipped", double(lights.skippedCount())},
                                         {"lights_unshadowed", double(lights.unshadowedCount())}});
}

} // namespace sb
