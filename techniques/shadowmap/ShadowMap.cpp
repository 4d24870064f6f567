#include "techniques/shadowmap/ShadowMap.h"

#include <algorithm>
#include <cmath>

#include "scenes/Math.h"
#include "techniques/ContactShadows.h"
#include "techniques/DepthLightingFrame.h"
#include "techniques/LightFitProperties.h"
#include "techniques/Property.h"
#include "techniques/ShadowMapProperties.h"
#include "techniques/ViewDepth.h"
#include "techniques/shadowmap/PoissonDisk.h"

namespace sb {

using P = ShadowMapProperties;

namespace {

/// Side of the rotated grid for `taps`: the nearest square, at least 2 x 2.
int rotatedGridSide(int taps) {
    return std::max(2, int(std::lround(std::sqrt(double(taps)))));
}

/// The kernel's tap offsets in texels, `radius` applied: the Poisson disk scaled to the radius, or the
/// unrotated n x n grid of cell centres covering the square [-radius, radius]^2.
std::vector<glm::vec2> kernelTaps(const std::string& kernel, int taps, float radius) {
    std::vector<glm::vec2> out;
    if (kernel == "poisson") {
        for (const glm::vec2& p : PoissonDisk::generate(taps)) out.push_back(p * radius);
        return out;
    }
    const int n = rotatedGridSide(taps);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            out.push_back((glm::vec2(float(x), float(y)) + 0.5f - 0.5f * float(n)) *
                          (2.0f * radius / float(n)));
    return out;
}

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    std::vector<PropertyDesc> out = {
        P::resolution("2048", "shadow map width and height (texels)"),
        P::biasConstant(),
        P::biasSlope(),
        P::pcf("PCF kernel width: pcf x pcf taps one texel apart"),
        flag(ShadowMap::kHardwareCompare, "true",
             "depth-compare sampler with bilinear filtering (true) or nearest fetch + shader compare"),
        choice(ShadowMap::kKernel, "grid", {"grid", "poisson", "rotated_grid"},
               "PCF kernel: grid (pcf x pcf), poisson (taps of a fixed Poisson disk), rotated_grid (a grid "
               "rotated per pixel by interleaved gradient noise)"),
        integer(ShadowMap::kTaps, "16", 4, 64,
                "taps of the poisson kernel; rotated_grid uses the nearest square n x n (n >= 2)"),
        real(ShadowMap::kRadius, "1.5", 0, 64, "radius of the poisson and rotated_grid kernels (map texels)"),
        real(ShadowMap::kNormalOffset, "0", 0, 64,
             "normal-offset bias: lookup moved along the normal by this many world texels x (1 - n.l)"),
        flag(ShadowMap::kReceiverPlane, "false",
             "receiver-plane depth bias: each tap compared with the receiver plane"),
        flag(ShadowMap::kCull, "true",
             "leave out of each light's map the casters whose shadow cannot reach the view (grown by the "
             "filter's footprint)"),
        LightFitProperties::fit("map", "spot lights take their cone"),
        LightFitProperties::fitMargin(),
    };
    return out;
}

} // namespace

TechniqueInfo ShadowMap::declaration() {
    return ContactShadows::declare(
        {.name = "shadowmap",
         .description = "two-pass shadow mapping: depth from each light, compare in the lighting pass",
         .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                    Effect::MultipleLights,
         .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
         .passes = {"depth", "lighting"},
         .properties = declareProperties(),
         // What `bench accuracy --sweep` walks, one knob at a time around the defaults.
         .quality =
             {
                 {P::kResolution, {"256", "512", "1024", "2048", "4096"}},
                 P::pcfSweep(),
                 P::biasConstantSweep(),
                 P::biasSlopeSweep(),
                 {kKernel, {"grid", "poisson", "rotated_grid"}},
                 {kTaps, {"8", "16", "32"}},
                 {kRadius, {"1", "1.5", "3"}},
                 {kNormalOffset, {"0", "1", "2", "4"}},
                 {kReceiverPlane, {"false", "true"}},
             },
         .resources =
             [](const PropertySet& p, const ResourceInputs& in) {
                 return squareMaps(p.getInt(P::kResolution), kDepthTexelBytes, 1, in);
             },
         // One member with the family's screen-space contact shadows (techniques/ContactShadows.h): the
         // others share its wiring (ContactShadowsGL/Vulkan) and have rows in the hard-case table.
         .matrixVariants = {{std::string(ContactShadows::kContact) + "=true", AccuracyRule::Map,
                             "the map's lookup, darkened where a short march through the view's depth meets "
                             "a blocker first: at the default bias it closes no leak and adds a few guesses "
                             "at contacts, so it is held to the map rule"}}});
}

std::vector<glm::vec2> ShadowMap::kernelOffsets(const PropertySet& p) {
    const std::string& kernel = p.getEnum(kKernel);
    if (kernel == "grid") return {};
    return kernelTaps(kernel, int(p.getInt(kTaps)), float(p.getFloat(kRadius)));
}

void ShadowMap::fitTexels(const Scene& scene, const FlatLightFits& lights, int mapSize, double kernelTexels,
                          float normalOffset, std::vector<float>& texelWorld, ViewCull& view) {
    texelWorld.clear();
    for (const glm::mat4& vp : lights.viewProj())
        texelWorld.push_back(FlatLightFits::texelWorldSize(vp, mapSize));
    // What the lighting pass reads around a receiver's texel, in texels: the kernel's half-width (the
    // grid's pcf x pcf, the other kernels' radius), the normal offset, and two for the bilinear
    // compare's footprint and rounding. In world units at the farthest receiver (w = 1 for an
    // orthographic map; a spot's texels grow with the distance).
    const float texels = float(kernelTexels) + normalOffset + 2.0f;
    view.lights = &scene.lights;
    view.reach.receivers = Aabb{};
    for (const Instance& inst : scene.instances)
        if (inst.receivesShadow && inst.mesh < scene.meshes.size())
            view.reach.receivers.extend(transformBounds(scene.meshBoundsOf(inst.mesh), inst.model));
    view.margins.clear();
    for (size_t i = 0; i < lights.viewProj().size(); ++i)
        view.margins.push_back(texels * texelWorld[i] *
                               FlatLightFits::farthestW(lights.viewProj()[i], view.reach.receivers));
}

Defines ShadowMap::lightingDefines(Defines lit, const PropertySet& p, int layers) {
    lit["SHADOW_MAP"] = "";
    lit["LIGHT_COUNT"] = std::to_string(layers);
    if (p.getBool(kHardwareCompare)) lit["HW_COMPARE"] = "";
    const std::string& kernel = p.getEnum(kKernel);
    if (kernel == "grid")
        lit["PCF_SIZE"] = std::to_string(p.getInt(P::kPcf));
    else
        lit[kernel == "poisson" ? "KERNEL_POISSON" : "KERNEL_ROTATED_GRID"] = "";
    if (float(p.getFloat(kNormalOffset)) > 0.0f) lit["NORMAL_OFFSET"] = ""; // as the forms read it
    if (p.getBool(kReceiverPlane)) lit["RECEIVER_PLANE"] = "";
    ContactShadows::addDefines(p, lit);
    return lit;
}

Counters ShadowMap::counters(const SubmitStats& s, int mapSize, const FlatLightFits& lights, size_t culled) {
    return DepthLightingFrame::counters(s, double(mapSize) * mapSize * double(lights.shadowed()),
                                        {{"lights_unshadowed", double(lights.size() - lights.shadowed())},
                                         {"casters_culled", double(culled)},
                                         {"map_covered_pct", lights.coverage().percent()}});
}

} // namespace sb
