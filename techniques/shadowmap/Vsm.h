#pragma once
// `vsm`: variance shadow maps (Donnelly and Lauritzen 2006, Variance Shadow Maps, I3D, sections 3-4;
// Lauritzen 2007, Summed-Area Variance Shadow Maps, GPU Gems 3 ch. 8, sections 8.3-8.4.3). Three passes:
//   "depth"    per light the moments (d, d^2 + 0.25 |grad d|^2) of linear light-space depth into an RG32F
//              array layer (FilterableShadowMaps: directional lights an orthographic map, spot lights a
//              perspective one storing distance; casters culled per light frustum);
//   "blur"     a separable Gaussian of `blur` texels over each layer (SeparableBlur; 0 = none; the pass
//              exists at blur 0 but does no GL work);
//   "lighting" per fragment the bilinearly filtered moments give mean and variance, and Chebyshev's
//              upper bound p_max = sigma^2 / (sigma^2 + (t - mu)^2) the lit fraction (shadowmap/vsm.frag),
//              with the variance clamped to `min_variance` (section 8.4.2) and light-bleeding reduction
//              linstep(bleed_reduction, 1, p_max) (section 8.4.3).
// Because the moments filter linearly, the map is filtered as a texture (bilinear here; mipmaps and
// anisotropy would work the same and are not done), which hard shadow maps cannot do: edges come out
// anti-aliased at one sample per fragment. The non-casters are drawn behind the casters as the map's
// background (FilterableShadowMaps.h, property `receiver_background`), so that beside an occluder's edge
// the filter sees the receiver rather than the far plane (aircraft, 1024^2 frame against the reference:
// 0.34% wrong with it, 1.65% without). The known limit, measured in the hard-case table
// (moments_vsm_bleeding_*): light bleeding where two occluders at different depths share a filter region
// (p_max is an upper bound, tight for one occluder over one receiver, loose when the receiver lies close
// behind the farther of two): the default 0.2 leaves it (0.78% of the two plates' view falsely lit, 4.2%
// with the lower plate 0.3 above the ground, moments_bleeding_slab), 0.5 removes the first and not the
// second, only 0.9 removes both, and every step darkens real soft edges (techniques/shadowmap/README.md
// has the sweep); the default 0.2 has the lowest RMSE against the reference on
// `aircraft` and `teapot` (1024^2 frames: 0.0547 and 0.0442, against 0.0556 and 0.0471 at 0 and 0.0702
// and 0.0522 at 0.5; wrong 0.34% and 0.22%, at 0 0.29% and 0.24%).
// Resolution default 1024, not `shadowmap`'s 2048: the filtered edge is placed to a fraction of a texel
// (the moments interpolate where a depth compare snaps), RG32F stores 8 bytes per texel against
// `shadowmap`'s 4, and the blur's cost grows with the texels: on llvmpipe (unloaded, paired rounds) a
// frame of `aircraft` cost 1.47x `shadowmap`'s at 2048 and 1.10x at 1024, for 0.17% and 0.34% wrong
// against shadowmap's 0.14% at 2048 (0.26% at 1024); the accuracy sweep walks 256..4096.
// Point lights need an omni map (`cubemap`, `paraboloid`): refused with ExitCode::Unsupported.
// The declaration (techniques/TechniqueInfo.h) and the kind (techniques/shadowmap/MomentMapKind.h) that its
// GL and Vulkan forms, MomentMapGL and MomentMapVulkan, both take.
#include "techniques/TechniqueInfo.h"
#include "techniques/shadowmap/MomentMapKind.h"

namespace sb {

struct Vsm {
    static constexpr const char* kBleedReduction = "bleed_reduction";
    static constexpr const char* kBlur = "blur";
    static constexpr const char* kCull = "cull";
    static constexpr const char* kMinVariance = "min_variance";
    static constexpr const char* kReceiverBackground = "receiver_background";
    static constexpr const char* kResolution = "resolution";

    static TechniqueInfo declaration();
    /// What sets it apart from the other filterable maps: its GL and Vulkan forms are MomentMapGL and
    /// MomentMapVulkan over this kind.
    static MomentMapKind kind();
};

} // namespace sb
