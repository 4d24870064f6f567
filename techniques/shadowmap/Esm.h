#pragma once
// `esm`: exponential shadow maps (Annen, Mertens, Seidel, Bekaert, Kautz 2008, Exponential Shadow Maps,
// GI, sections 3-4), filtered in log space (Salvi 2008, Rendering Filtered Shadows with Exponential
// Shadow Maps, ShaderX6). Three passes:
//   "depth"    per light linear light-space depth d into an R32F array layer (FilterableShadowMaps:
//              directional lights an orthographic map, spot lights a perspective one storing distance;
//              casters culled per light frustum);
//   "blur"     a separable Gaussian of `blur` texels over exp(c d), kept in log space: each layer holds
//              log(sum w exp(c d)) / c afterwards (SeparableBlur, LogSpace; 0 = none);
//   "lighting" visibility = clamp(exp(c (d_occ - t)), 0, 1) of the filtered map at the receiver's depth t
//              (Annen et al., equation 5), the bilinear lookup done in log space too (shadowmap/esm.frag).
// Why log space: Annen et al. store exp(c d) and filter it linearly, which needs exp(c d) to fit a float:
// with d in [0, 1] that holds for c < 88.7 only, and `exponent` goes to 500 because the large exponents are
// what keep ESM's step sharp against receivers close behind their occluder (the lighter "contact" where
// c (t - d_occ) is small). Filtering the exponentials in log space (m + log sum w exp(c (d - m)), m the
// largest tap) is the same filter, computed without forming exp(c d): every exponent is at most 0, so the
// result is finite and in [0, 1] at every c the property allows (the hard-case table checks c = 500).
// The non-casters are drawn behind the casters as the map's background (FilterableShadowMaps.h, property
// `receiver_background`), so that beside an occluder's edge the filter sees the receiver rather than the
// far plane, whose exp(c (1 - t)) would outweigh the occluder's share until it covered nearly all of the
// region (aircraft, 1024^2 frame against the reference: 0.32% wrong with it, 1.8% without).
// Known limits: receivers close behind an occluder are lit by exp(-c (t - d_occ)) > 0 (shadows fade
// towards contact points, more at small c); beside an edge the texels of a receiver sloped in light space
// lie behind it and weigh exp(c slope) > 1, moving the soft edge into the shadow, more at large c (both
// measured in the hard-case table, moments_esm_max_exponent_teapot_near).
// Exponent default 160 (depth d in [0, 1] over what the scene covers inside the map's frustum): measured
// against the reference (512^2 frame), teapot 0.43% wrong at c = 80, 0.27% at 160 and 300, 0.31% at 500;
// aircraft 0.30% at 80, 0.31% at 160, 0.38% at 500.
// Resolution default 1024, as `vsm` (the filtered edge is placed to a fraction of a texel; the blur's cost
// grows with the texels: `aircraft` 1.12x `shadowmap`'s frame at 1024, 1.67x at 2048, for 0.32% and 0.16%
// wrong against shadowmap's 0.14%). Point lights need an omni map (`cubemap`, `paraboloid`): refused with
// ExitCode::Unsupported.
// The declaration (techniques/TechniqueInfo.h) and the kind (techniques/shadowmap/MomentMapKind.h) that its
// GL and Vulkan forms, MomentMapGL and MomentMapVulkan, both take.
#include "techniques/TechniqueInfo.h"
#include "techniques/shadowmap/MomentMapKind.h"

namespace sb {

struct Esm {
    static constexpr const char* kBlur = "blur";
    static constexpr const char* kCull = "cull";
    static constexpr const char* kExponent = "exponent";
    static constexpr const char* kReceiverBackground = "receiver_background";
    static constexpr const char* kResolution = "resolution";

    /// The largest `exponent`: exp(c) of a depth difference of 1 is far outside float range; the log-space
    /// filter never forms it.
    static constexpr double kMaxExponent = 500.0;

    static TechniqueInfo declaration();
    /// What sets it apart from the other filterable maps: its GL and Vulkan forms are MomentMapGL and
    /// MomentMapVulkan over this kind.
    static MomentMapKind kind();
};

} // namespace sb
