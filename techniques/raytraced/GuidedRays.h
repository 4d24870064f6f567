#pragma once
// `raytraced:mode=guided`: shadow rays only where a light's depth map cannot decide them. After the hybrid
// shadows of AMD's FidelityFX SDK (the Hybrid Shadows sample, whose FidelityFX Classifier rejects the
// pixels a shadow map shows lit, and those it shows shadowed, before a ray is spent on them) and Boksansky,
// Wimmer and Bittner, "Ray Traced Shadows: Maintaining Real-Time Frame Rates" (Ray Tracing Gems, ch. 13,
// its section on adaptive sampling: rays where the shadow changes, few where it does not). Unrelated to the
// `hybrid` technique, which splits a frame by object. The API-neutral half: knobs, defines, counters; the
// maps and their pass are techniques/raytraced/GuideMapsVulkan.h, the test shaders/raytraced/guided.glsl.
//
// A frame: a pass "depth" renders one map per light that can have one (techniques/FlatLightFits.h, the
// fit of `shadowmap`'s default: the casters framed, `resolution`^2 texels, 24-bit depth), drawn with no
// depth bias: the rule's band takes its place. The lighting pass then takes every fragment and light
// where `hard` traces a ray (the light reaches the point, its shadow applies) and asks the map first.
//
// The rule. Let p be the point in the map (texture coordinates and depth), n the geometric normal of its
// triangle (the one `hard` offsets its ray along), and z_P(u, v) the depth of p's own plane (through p,
// normal n) seen through the map: exact, since the light's projection maps a plane to a plane. The taps
// are the 2 x 2 texels whose centres surround p, grown by `neighbourhood` rings r: (2 + 2r)^2 texels;
// tap t holds d_t, the depth of the nearest caster at its centre (1 where none). The band e is `margin`
// texels of world distance along the ray to the light at p, in map depth, plus kDepthSteps steps of
// 2^-24 (the map's rounding and the plane's float error). Tap t is in front when d_t < z_P(t) - e.
//   no tap in front     surely lit: visibility 1, no ray
//   every tap in front  surely shadowed: 0, no ray
//   otherwise           unsure: `hard`'s ray decides
// A directional light's map frames every caster and a ray towards it keeps its (u, v): a point outside
// the map is surely lit, and a tap outside it holds no caster. For a spot light a point or tap outside
// its map is unsure. Point lights have no map (a flat map cannot hold them; FlatLightFits::PointLights::
// Unmapped): all their rays are traced, as `hard` traces them.
//
// Why it is conservative. Each tap's caster is compared with p's own plane at that tap, not with p's
// depth, so a receiver slanted against the light is in its own band at every tap (no acne, no bias
// needed) rather than in front of itself. A planar caster's depth and the plane are both linear in (u, v):
// if the caster is in front at every tap, it is in front at p, which lies inside the taps' hull (the
// 2 x 2 centres already surround it); if it is in front at none, it is not in front at p. So a decision
// can be wrong only where the map misses what the ray meets:
//   - a caster, or a gap between casters, thinner than the texel spacing that passes between the tap
//     centres (a sub-texel feature; the rings make a thin but long one meet a centre: unsure);
//   - a caster less than e in front of p's plane (a contact closer than `margin` texels): called lit, as
//     a depth bias would call it; near a contact the taps further out usually see the caster rise, and
//     the point is unsure;
//   - a receiver that curves towards the light by more than e within the taps, whose neighbouring
//     triangles are then in front at every tap, the nearest (at most 0.71 texels away) included: a
//     concave radius under 1 / (4 x margin) texels, one texel at the default: called shadowed;
//   - a caster closer to a spot light than its map's near plane (scenes/LightFit.h), which no map holds.
// A finer `resolution` shrinks each of these and the unsure band with them; a wider `margin` trades
// contact shadows for rays, more rings trade rays for thin features. techniques/raytraced/README.md has
// what `bench accuracy` measured.
#include <cstdint>
#include <vector>

#include "shading/Defines.h"
#include "techniques/Property.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct GuidedRays {
    static constexpr const char* kNeighbourhood = "neighbourhood";
    static constexpr const char* kMargin = "margin";
    /// Steps of 2^-24 (one step of the 24-bit map; float's spacing just below depth 1) every band adds.
    static constexpr float kDepthSteps = 4.0f;

    /// Its knobs, which only mode=guided reads: `resolution` (ShadowMapProperties::resolution, default
    /// 1024), `neighbourhood` (rings, 0 to 3, default 1) and `margin` (texels, 0 to 16, default 0.25).
    static std::vector<PropertyDesc> properties();
    /// The rings as a define, GUIDED_RINGS=<r>: the taps' loop is unrolled.
    static void addDefines(const PropertySet& p, Defines& defines);
    /// The maps' memory for `p` (techniques/ResourceEstimate.h): one `resolution`^2 depth map per light.
    static ResourceEstimate resources(const PropertySet& p, const ResourceInputs& in);
    /// The counters guided adds, after raytraced's, in this order:
    ///   rays_decided       pixel-lights the maps decided without a ray (surely lit or shadowed)
    ///   unsure_pct         rays_traced / (rays_traced + rays_decided), in percent: the share of the
    ///                      pixel-lights `hard` traces that guided still traces (0 when there are none)
    ///   shadow_map_texels  the maps' texels (lights with a map x resolution^2)
    static Counters counters(uint64_t raysTraced, uint64_t raysDecided, double mapTexels);
};

} // namespace sb
