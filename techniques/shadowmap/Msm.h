#pragma once
// `msm`: moment shadow maps (Peters and Klein 2015, Moment Shadow Mapping, I3D). vsm's three passes and maps
// (techniques/shadowmap/Vsm.h has the method) with four moments:
//   "depth"    per light the power moments (d, d^2, d^3, d^4) of linear light-space depth d, through the
//              paper's quantisation transform into an RGBA16 unorm layer (`format=unorm16`, 64 bits per
//              texel; the paper's section on quantization) or raw into RGBA32F (`format=float`)
//              (FilterableShadowMaps; shadowmap/moments.frag, shadowmap/msm.glsl);
//   "blur"     vsm's separable Gaussian over the four channels (the transform is affine, so filtering the
//              stored values filters the moments);
//   "lighting" the moments de-quantised, biased by `moment_bias` and the Hamburger four-moment
//              reconstruction of the fraction in front of the receiver (shadowmap/msm.frag).
// Why: two moments (vsm) bound the lit fraction by Chebyshev's inequality, loose for a receiver close
// behind the farther of two occluders (light leaks); four moments determine a distribution of two depths
// exactly, so that case is answered right but for the bias. Point lights need an omni map (`cubemap`,
// `paraboloid`): refused with ExitCode::Unsupported.
// The declaration (techniques/TechniqueInfo.h) and the kind (techniques/shadowmap/MomentMapKind.h) that its
// GL and Vulkan forms, MomentMapGL and MomentMapVulkan, both take, and the pieces of the method both
// share (the map's format, its "no occluder" value, the shaders' defines).
#include <glm/glm.hpp>

#include "shading/Defines.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"
#include "techniques/shadowmap/MomentMapKind.h"

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
    /// What sets it apart from the other filterable maps: its GL and Vulkan forms are MomentMapGL and
    /// MomentMapVulkan over this kind.
    static MomentMapKind kind();

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
