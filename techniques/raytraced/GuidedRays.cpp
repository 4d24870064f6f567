#include "techniques/raytraced/GuidedRays.h"

#include <string>

#include "techniques/ShadowMapProperties.h"

namespace sb {

std::vector<PropertyDesc> GuidedRays::properties() {
    return {
        ShadowMapProperties::resolution("1024",
                                        "guided: width and height of each light's depth map (texels)"),
        integer(
            kNeighbourhood, "1", 0, 3,
            "guided: rings of map texels around the 2 x 2 around a point that must agree before no ray is "
            "traced"),
        real(kMargin, "0.25", 0, 16,
             "guided: band around the point's own plane, in map texels of world distance along the ray, "
             "within which a caster does not count as in front"),
    };
}

void GuidedRays::addDefines(const PropertySet& p, Defines& defines) {
    defines["GUIDED_RINGS"] = std::to_string(p.getInt(kNeighbourhood));
}

ResourceEstimate GuidedRays::resources(const PropertySet& p, const ResourceInputs& in) {
    return squareMaps(p.getInt(ShadowMapProperties::kResolution), kDepthTexelBytes, 1, in);
}

Counters GuidedRays::counters(uint64_t raysTraced, uint64_t raysDecided, double mapTexels) {
    const uint64_t asked = raysTraced + raysDecided;
    return {{"rays_decided", double(raysDecided)},
            {"unsure_pct", asked ? 100.0 * double(raysTraced) / double(asked) : 0.0},
            {"shadow_map_texels", mapTexels}};
}

} // namespace sb
