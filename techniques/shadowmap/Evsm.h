#pragma once
// `evsm`: exponential variance shadow maps (Lauritzen and McCool 2008, Layered Variance Shadow Maps, GI, the
// section on the exponential warp). The declaration (techniques/TechniqueInfo.h) its GL and Vulkan forms both
// take: name, effects, the capabilities of each API's form, passes, properties and quality knobs, and the
// pieces of the method both forms share (the map's format, its "no occluder" value, the shaders' defines).
#include <glm/glm.hpp>

#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Evsm {
    static constexpr const char* kBleedReduction = "bleed_reduction";
    static constexpr const char* kBlur = "blur";
    static constexpr const char* kComponents = "components";
    static constexpr const char* kCull = "cull";
    static constexpr const char* kExponentNegative = "exponent_negative";
    static constexpr const char* kExponentPositive = "exponent_positive";
    static constexpr const char* kMinVariance = "min_variance";
    static constexpr const char* kReceiverBackground = "receiver_background";
    static constexpr const char* kResolution = "resolution";

    /// The largest exponent a 32-bit float map holds: the second moment exp(2 c d) at d = 1 stays below
    /// FLT_MAX (3.4e38 = exp(88.7)) for c < 44.3; 42 leaves the blur's sums and the gradient bias room.
    static constexpr double kMaxExponent = 42.0;

    static TechniqueInfo declaration();

    /// Whether the map holds the negative warp's moments too (`components=4`).
    static bool negativeWarp(const PropertySet& p);
    /// The map's texel: four floats with the negative warp, two without.
    static int channels(const PropertySet& p) { return negativeWarp(p) ? 4 : 2; }
    /// Defines of the depth and lighting shaders (shadowmap/moments.frag, evsm.frag): EVSM_EXPONENTS
    /// (vec2(c+, c-) as GLSL floats) and, with the negative warp, EVSM_NEGATIVE.
    static void addDefines(const PropertySet& p, Defines& defines);
    /// The moments of depth 1 (nothing in front of the far end): the layer's clear value; the warps of
    /// shadowmap/evsm.glsl at d = 1 (tests/MsmEvsmVkTest.cpp compares the two).
    static glm::vec4 noOccluder(const PropertySet& p);
};

} // namespace sb
