#pragma once
// `evsm`: exponential variance shadow maps (Lauritzen and McCool 2008, Layered Variance Shadow Maps, GI, the
// section on the exponential warp; Lauritzen 2007, Summed-Area Variance Shadow Maps, GPU Gems 3 ch. 8, for
// the variance shadow maps it builds on). vsm's three passes and maps (techniques/shadowmap/Vsm.h has the
// method) over warped depth:
//   "depth"    per light the moments of the warps w+ = exp(c+ d) and, with `components=4`, w- = -exp(-c- d)
//              of linear light-space depth d into an RG32F (2) or RGBA32F (4) array layer
//              (FilterableShadowMaps; shadowmap/moments.frag, shadowmap/evsm.glsl);
//   "blur"     vsm's separable Gaussian over every channel (the warped moments filter linearly);
//   "lighting" Chebyshev's bound in each warped space, the smaller of the two, then vsm's light-bleeding
//              reduction (shadowmap/evsm.frag).
// Why: the exponential warp spreads the depths behind an occluder apart (exp(c+ t) - exp(c+ d) grows with
// exp(c+ d)), so the two-depth case where vsm's bound leaks (a receiver close behind the farther of two
// occluders) reads far from the filter's mean in the warped space and gets a small bound. The exponents
// are compile-time constants of the shaders (EVSM_EXPONENTS): changing them recompiles. Point lights need
// an omni map (`cubemap`, `paraboloid`): refused with ExitCode::Unsupported.
// The declaration (techniques/TechniqueInfo.h) and the kind (techniques/shadowmap/MomentMapKind.h) that its
// GL and Vulkan forms, MomentMapGL and MomentMapVulkan, both take, and the pieces of the method both
// share (the map's format, its "no occluder" value, the shaders' defines).
#include <glm/glm.hpp>

#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/shadowmap/MomentMapKind.h"

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
    /// What sets it apart from the other filterable maps: its GL and Vulkan forms are MomentMapGL and
    /// MomentMapVulkan over this kind.
    static MomentMapKind kind();

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
