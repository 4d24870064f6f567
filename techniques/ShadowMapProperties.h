#pragma once
// The knobs every depth-map member of the family has (`shadowmap`, `pcss`, `cascaded`, `cubemap`,
// `paraboloid`): the map's resolution, the depth pass's glPolygonOffset bias (constant and slope-scaled)
// and the PCF kernel width. (The flat maps' light fit, `fit` and `fit_margin`, is
// techniques/LightFitProperties.h: `projective` shares it.) One name and one maker each, so the members
// cannot drift apart in what a knob is called or which range it takes; each member passes its own default or
// description where its map differs (a cube face, a cascade, a paraboloid half), the shared wording
// otherwise; and the sweeps of the knobs whose sweeps are the same. It lives below the technique folders,
// with the flat light fits (techniques/FlatLightFits.h) and the Vulkan depth maps
// (techniques/vulkan/VulkanDepthMapSet.h) that read it, because a technique outside the family that
// renders a light's depth map takes the same knobs and no technique folder includes another.
#include <string>

#include "techniques/Property.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

class ShadowMapProperties {
public:
    static constexpr const char* kResolution = "resolution";
    static constexpr const char* kBiasConstant = "bias_constant";
    static constexpr const char* kBiasSlope = "bias_slope";
    static constexpr const char* kPcf = "pcf";
    /// The widest separable blur the filterable maps' shaders are compiled for (their `blur` maximum).
    static constexpr int kMaxBlurWidth = 64;

    /// Width and height of each map (texels), 16 to 8192.
    static PropertyDesc resolution(std::string defaultValue, std::string description);
    /// glPolygonOffset units of the depth pass, 0 to 10000, default 2.
    static PropertyDesc biasConstant(
        std::string description = "glPolygonOffset units: constant depth bias in depth-buffer steps");
    /// glPolygonOffset factor of the depth pass, 0 to 64, default 2.
    static PropertyDesc
    biasSlope(std::string description = "glPolygonOffset factor: slope-scaled depth bias");
    /// PCF kernel width, 1 to 9, default 1 (pcf x pcf taps).
    static PropertyDesc pcf(std::string description);

    /// The sweeps `bench accuracy --sweep` walks for these knobs (TechniqueInfo::quality), the same in
    /// every member so their accuracy curves line up.
    static QualityKnob pcfSweep() { return {kPcf, {"1", "3", "5"}}; }
    static QualityKnob biasConstantSweep() { return {kBiasConstant, {"0.5", "2", "8", "32"}}; }
    static QualityKnob biasSlopeSweep() { return {kBiasSlope, {"0.5", "2", "4"}}; }
};

} // namespace sb
