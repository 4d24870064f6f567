#pragma once
// What sets one filterable shadow map (`vsm`, `esm`, `evsm`, `msm`) apart from the others. The members
// share their three passes ("depth": moments of linear light-space depth per light into an array layer;
// "blur": a separable Gaussian over each layer; "lighting": a bound or reconstruction from the filtered
// moments), their light fits, culling and counters (MomentMapFits) and their properties' names; they
// differ only in what a kind holds: the map's texel format, the shaders' defines and the lighting pass's
// fragment shader and parameters, the value of a texel no caster covers, and whether the blur filters in
// log space (esm). One GL form (MomentMapGL) and one Vulkan form (MomentMapVulkan) take a kind, so a
// member is its declaration and these few functions (Vsm::kind(), Esm::kind(), Evsm::kind(),
// Msm::kind()), each written once for both APIs.
#include <vector>

#include <glm/glm.hpp>

#include "shading/Defines.h"
#include "techniques/Property.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct MomentMapKind {
    /// The map's texel format, named once: MomentMapGL and MomentMapVulkan each map it to their API's.
    enum class Format {
        R32F,        ///< esm: d
        RG32F,       ///< vsm: (d, d^2); evsm components=2: the positive warp's two moments
        RGBA16Unorm, ///< msm format=unorm16: the four moments through the quantisation transform
        RGBA32F,     ///< evsm components=4, msm format=float
    };

    // The properties every member declares under these names.
    static constexpr const char* kBlur = "blur";
    static constexpr const char* kCull = "cull";
    static constexpr const char* kReceiverBackground = "receiver_background";
    static constexpr const char* kResolution = "resolution";

    /// The members' property declarations, written once, in the order every member lists them:
    /// resolution, blur, `afterBlur` (the kind's own that come before the shared pair), receiver_background,
    /// cull, `afterCull` (the kind's own after it), fit, fit_margin (LightFitProperties). The help texts'
    /// only differences are words: `map` names what resolution sizes ("moment map", esm's "depth map"),
    /// `blurOver` what the blur filters where it says so (esm's ", over exp(c d)"; else empty).
    static std::vector<PropertyDesc> properties(const char* map, const char* blurOver,
                                                std::vector<PropertyDesc> afterBlur,
                                                std::vector<PropertyDesc> afterCull);

    TechniqueInfo (*declaration)() = nullptr;
    Format (*format)(const PropertySet&) = nullptr;
    /// The depth pass's defines (shadowmap/moments.frag: VSM, EVSM_EXPONENTS, MSM ...), added to the
    /// submitter's.
    void (*depthDefines)(const PropertySet&, Defines&) = nullptr;
    /// The lighting pass's defines, added to the frame's.
    void (*lightingDefines)(const PropertySet&, Defines&) = nullptr;
    /// The lighting pass's fragment shader under shaders/ ("shadowmap/vsm.frag").
    const char* lightingFragment = "";
    /// The lighting pass's parameters in the shader's order: GL uniform locations 40, 41, ...; the Vulkan
    /// block's floats after the margin (at most two).
    std::vector<float> (*params)(const PropertySet&) = nullptr;
    /// A layer's clear value: the stored moments of depth 1, nothing in front of the far end.
    glm::vec4 (*noOccluder)(const PropertySet&) = nullptr;
    /// The exponent c of a blur over exp(c d) kept in log space (esm); 0: the blur is linear.
    float (*logSpaceExponent)(const PropertySet&) = nullptr;
};

} // namespace sb
