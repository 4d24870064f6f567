#include "techniques/shadowmap/MomentMapKind.h"

#include <string>

#include "techniques/LightFitProperties.h"
#include "techniques/ShadowMapProperties.h"

namespace sb {

std::vector<PropertyDesc> MomentMapKind::properties(const char* map, const char* blurOver,
                                                    std::vector<PropertyDesc> afterBlur,
                                                    std::vector<PropertyDesc> afterCull) {
    std::vector<PropertyDesc> out = {
        integer(kResolution, "1024", 16, 8192, std::string(map) + " width and height (texels)"),
        integer(kBlur, "3", 0, ShadowMapProperties::kMaxBlurWidth,
                std::string("separable Gaussian kernel width in texels") + blurOver +
                    " (sigma = width / 4; 0 or 1 = no blur)"),
    };
    out.insert(out.end(), afterBlur.begin(), afterBlur.end());
    out.push_back(flag(kReceiverBackground, "true",
                       "non-casters drawn behind the casters as the map's background (the farthest per "
                       "texel): the filter sees the receiver, not the far plane, beside an occluder's edge"));
    out.push_back(flag(kCull, "true",
                       "leave out of each light's map the casters whose shadow cannot reach the view (grown "
                       "by the blur's reach)"));
    out.insert(out.end(), afterCull.begin(), afterCull.end());
    out.push_back(LightFitProperties::fit("map", "spot lights take their cone"));
    out.push_back(LightFitProperties::fitMargin());
    return out;
}

} // namespace sb
