#include "techniques/proxy/Proxy.h"

#include <cstdint>
#include <string>

#include "techniques/Property.h"
#include "techniques/PropertySet.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        real(Proxy::kOffset, "1", 0, 1e6,
             "ProxyOffset: how far (world units) beyond the proxy's surface its influence reaches"),
        real(Proxy::kShadow, "1", 0, 1, "shadow factor: the shadow at the surface"),
        real(Proxy::kFalloff, "1", 0.01, 64, "falloff exponent of the attenuation"),
        choice(Proxy::kExponentOn, "attenuation", {"attenuation", "factor"},
               "attenuation: pow(1 - d/offset, falloff) (section 1.2's text); factor: Listing 1.3 as "
               "printed, (1 - d/offset) * pow(shadow, falloff)"),
        real(Proxy::kStart, "0", 0, 1e6,
             "distance from the surface where the falloff starts (section 1.2's offset between surface and "
             "falloff)"),
        real(Proxy::kCutoff, "0", -1, 1,
             "Listing 1.4's lower clamp of dot(light, normal): above 0 the shadow wraps round the lit side"),
        real(Proxy::kBleed, "0.5", 0, 1, "amount of colour bleeding at the surface"),
        choice(Proxy::kBleeding, "auto", {"auto", "on", "off"},
               "colour bleeding compiled in: auto = when the scene asks for colour_bleeding"),
        choice(Proxy::kModulate, "auto", {"auto", "rays", "on", "off"},
               "egg-shaped volumes towards/away from each light (Listing 1.4): on = as printed; rays = kept "
               "where the ray towards the light passes the proxy (a low light's long thin shadow); auto = "
               "rays when the scene has lights"),
        real(Proxy::kPenumbra, "10", 0.01, 45,
             "modulate=rays: the penumbra's half-angle (degrees) round the ray towards the light"),
        flag(Proxy::kGrid, "true",
             "screen-space IndexMap (true) or every proxy in view tested by every fragment"),
        integer(Proxy::kCells, "64", 1, 1024, "IndexMap grid cells along x and along y"),
        integer(Proxy::kCapacity, "16", 1, 4096,
                "proxy indices per cell; more are counted as grid_overflow, never silently dropped"),
        choice(Proxy::kProxies, "scene", {"scene", "fit"},
               "scene: the meshes' declared proxies, fitted where none are declared; fit: fit every caster "
               "(the tightest of sphere, box and cylinder)"),
    };
}

/// The IndexMap (techniques/proxy/ProxyIndexGrid.h) is dense: every cell holds `capacity` 32-bit
/// entries whether or not they are used, once in the CPU grid and once in the GPU buffer it is uploaded
/// to. Without the grid one cell holds every proxy in view, which the scene's size bounds.
ResourceEstimate indexMap(const PropertySet& p, const ResourceInputs&) {
    if (!p.getBool(Proxy::kGrid)) return {};
    const uint64_t cells = uint64_t(p.getInt(Proxy::kCells)), capacity = uint64_t(p.getInt(Proxy::kCapacity));
    return {cells * cells * capacity * sizeof(uint32_t) * 2,
            std::to_string(cells) + "^2 cells x " + std::to_string(capacity) +
                " entries x 4 B, in the CPU grid and in the GPU buffer"};
}

} // namespace

TechniqueInfo Proxy::declaration() {
    return {.name = "proxy",
            .description =
                "ShadowProxies: analytic sphere/box/cylinder volumes, screen-space index grid, soft "
                "shadows and colour bleeding (van der Spek, OpenGL Insights)",
            // Soft halos around proxies: not exact hard shadows, no self-shadowing (the proxy of the
            // fragment's own object is skipped), any receiver shape.
            .effects = Effect::SoftShadows | Effect::ColourBleeding | Effect::NonPlanarReceivers |
                       Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"index_map", "lighting"},
            .properties = declareProperties(),
            .quality = {{kOffset, {"0.25", "0.5", "1", "2", "4"}}, {kFalloff, {"0.5", "1", "2", "4"}}},
            .resources = indexMap};
}

} // namespace sb
