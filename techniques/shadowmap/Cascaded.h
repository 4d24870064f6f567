#pragma once
// `cascaded`: cascaded shadow maps for directional lights (Engel 2006, Cascaded Shadow Maps, ShaderX5; Zhang
// et al. 2006, Parallel-Split Shadow Maps). The declaration (techniques/TechniqueInfo.h) its GL and Vulkan
// forms both take: name, effects, the capabilities of each API's form, passes, properties and quality knobs.
//
// fit=practical (the default) places the splits by the practical split scheme over the receivers' view-depth
// interval (techniques/shadowmap/CascadeSplits.h). fit=sdsm is the sample distribution shadow map of
// Lauritzen, Salvi and Lefohn 2011 (Sample Distribution Shadow Maps, I3D; its z-partitioning of the tight
// depth range): a depth-only pre-pass of the camera's view is reduced on the GPU to the min and max depth
// of the pixels it covers (shaders/shadowmap/depth_range.comp), and the splits are the logarithmic
// partition of that tight interval. Pass "depth_range" (the pre-pass and the reduction) runs only then.
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Cascaded {
    static constexpr const char* kBlend = "blend";
    static constexpr const char* kCascades = "cascades";
    static constexpr const char* kFit = "fit";
    static constexpr const char* kFitPractical = "practical";
    static constexpr const char* kFitSdsm = "sdsm";
    static constexpr const char* kLambda = "lambda";
    static constexpr const char* kStabilize = "stabilize";

    /// The most cascades a light gets (the lighting shader's arrays).
    static constexpr int kMaxCascades = 4;

    static TechniqueInfo declaration();
    /// Whether `p` selects the sample distribution fit (fit=sdsm).
    static bool sampleDistribution(const PropertySet& p);
    /// The passes of a form: {"depth_range", "depth", "lighting"} for fit=sdsm (its pre-pass serves
    /// contact=on too), {"view_depth", "depth", "lighting"} for contact=on alone, else {"depth",
    /// "lighting"}.
    static std::vector<std::string> passes(const PropertySet& p);
    /// Whether a form draws the view depth pre-pass: fit=sdsm or contact=on.
    static bool viewDepth(const PropertySet& p);
    /// The name of the first pass, which draws it: "depth_range" (fit=sdsm) or "view_depth".
    static const char* viewDepthPass(const PropertySet& p);
};

} // namespace sb
