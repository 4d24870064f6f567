#pragma once
// `msm`: moment shadow maps (Peters and Klein 2015, Moment Shadow Mapping, I3D). The declaration
// (techniques/TechniqueInfo.h) its GL and Vulkan forms both take: name, effects, the capabilities of each
// API's form, passes, properties and quality knobs, and the pieces of the method both forms share (the
// map's format choice, its "no occluder" value, the shaders' defines).
#include <glm/glm.hpp>

#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct Msm {
    static constexpr const char* kBleedReduction = "bleed_reduction";
    static constexpr const char* kBlur = "blur";
    static constexpr const char* kCull = "cull";
    static constexpr const char* kFormat = "format";
    static constexpr const char* kMomentBias = "moment_bias";
    static constexpr const char* kReceiverBackground = "receiver_background";
    static constexpr const char* kResolution = "resolution";

    static TechniqueInfo declaration();

    /// Whether the map holds the paper's quantised moments in 16-bit unorm (`format=unorm16`, 64 bits per
    /// texel) rather than the raw moments in 32-bit floats (`format=float`, 128 bits).
    static bool quantized(const PropertySet& p);
    /// Bytes per texel of the map.
    static int texelBytes(const PropertySet& p) { return quantized(p) ? 8 : 16; }
    /// Defines of the depth and lighting shaders (shadowmap/moments.frag, msm.frag): MSM and, for the
    /// 16-bit map, MSM_QUANTIZED.
    static void addDefines(const PropertySet& p, Defines& defines);
    /// The stored moments of depth 1 (nothing in front of the far end): the layer's clear value. Float:
    /// (1, 1, 1, 1); unorm16: the quantisation transform of shadowmap/msm.glsl applied to it, to the
    /// digits below (tests/MsmEvsmVkTest.cpp compares the two).
    static glm::vec4 noOccluder(const PropertySet& p);
};

} // namespace sb
