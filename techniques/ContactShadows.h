#pragma once
// Screen-space contact shadows, a property a shadow-map technique's lighting pass turns on (`contact`):
// a short ray march from each shaded point towards each light through the view's depth (the view depth
// pre-pass, techniques/ViewDepth.h), as Unreal Engine's contact shadows and Filament's screen-space
// contact shadows do. A map's depth bias (glPolygonOffset's constant and slope) moves the map's surfaces
// away from the light, so where a caster stands on a receiver the first texels under its foot compare
// as lit: the light leaks under the contact ("peter panning"). The march sees the caster in the view's
// depth a few steps towards the light and darkens those points. The neutral half: the knobs, the defines
// the one GLSL include reads (shaders/common/contact_shadow.glsl), and the pass the pre-pass is timed in.
//
// The march (contact_shadow.glsl): `contact_steps` points evenly spaced along `contact_length` world units
// towards the light (towards a positional light at most its distance), starting half a step off the
// surface along its normal (a tessellated curve's neighbouring facets stay behind that), each projected
// with the camera's view-projection; a point is hidden when the view's depth there lies in front of it by
// more than a rounding margin (1e-4 of its depth) and by less than two steps (the ray entered that
// surface since the last point; a surface farther in front is taken as passing in front of the ray, the
// screen-space method's one guess). The light is then blocked (visibility 0) for that pixel; the map's
// answer is kept where it is darker.
//
// Which members have it: every map member, GL and Vulkan: `shadowmap`, `cascaded` (with fit=sdsm one view
// depth pre-pass for both readers), `pcss`, `cubemap`, `paraboloid`, `vsm`, `esm`, `evsm` and `msm`. The
// forms' wiring has one home per API: techniques/gl/ContactShadowsGL.h, techniques/vulkan/
// ContactShadowsVulkan.h (cascaded keeps its own view depth, shared with fit=sdsm). Measured on
// contact_point_sun's low camera with a deliberately large bias (tests/hard/HardCases.h,
// shadowmap_contact_leak*, cascaded_contact_leak_sdsm_contact): shadowmap 0.105% of the pixels wrong off the
// edge band without, 0.029% with contact_length=1, contact_steps=16; cascaded:fit=sdsm 0.166% and 0.054%; at
// shadowmap's defaults the error is the same with and without. pcss as shadowmap (0.102% -> 0.028%);
// cubemap and paraboloid under a point light (contact_point_lamp) 1.000% -> 0.761% and 1.996% -> 1.580%;
// the moment maps, which have no bias, have no leak there and the march adds none off the edge band
// (rows pcss_contact_leak_contact ... msm_contact).

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "shading/Defines.h"
#include "techniques/Property.h"
#include "techniques/PropertySet.h"
#include "techniques/TechniqueInfo.h"

namespace sb {

struct ContactShadows {
    static constexpr const char* kContact = "contact";
    static constexpr const char* kLength = "contact_length";
    static constexpr const char* kSteps = "contact_steps";
    /// The pass the view depth pre-pass is drawn and timed in, first in the frame (DepthLightingFrame's
    /// optional first pass).
    static constexpr const char* kPass = "view_depth";

    /// contact (off), contact_length (world units) and contact_steps: what a member declares.
    static std::vector<PropertyDesc> properties();
    /// Whether `p` (of a technique that declares properties()) turns the march on.
    static bool enabled(const PropertySet& p);
    /// SB_CONTACT_SHADOWS into the lighting pass's defines when enabled; nothing otherwise (the program is
    /// the one without the march).
    static void addDefines(const PropertySet& p, Defines& defines);
    /// The march's uniform block (contact_shadow.glsl's ContactBlock: x contact_length, y contact_steps):
    /// uniforms, so that a length or a step count is no program permutation of its own.
    static glm::vec4 block(const PropertySet& p);
    /// `passes` with kPass first when enabled.
    static std::vector<std::string> passes(const PropertySet& p, std::vector<std::string> passes);
    /// A member's declaration with contact: properties() after its own, and its resource estimate
    /// grown by the view depth (ViewDepth::bytes) when enabled. One home for what every member adds
    /// (`cascaded` counts its view depth itself: fit=sdsm shares it).
    static TechniqueInfo declare(TechniqueInfo info);
};

} // namespace sb
