#include "techniques/occluder/Occluder.h"

#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        choice(Occluder::kLightSpace, "per_vertex", {"per_vertex", "per_instance", "texture_matrix"},
               "light into model space in every vertex (thesis), once per instance on the CPU (its "
               "proposal), or equations 6 and 8 folded into a matrix per instance and plane (its future "
               "work; directional lights)"),
        integer(Occluder::kPlanes, "16", 0, Occluder::kMaxPlanes,
                "use only the first N shadow planes of each mesh (cost per plane)"),
        integer(Occluder::kResolution, "512", 8, 8192,
                "occluder texture size (texels per side; baked and loaded textures alike)"),
        integer(Occluder::kDilate, "0", 0, 64,
                "texels the baked silhouette grows by (section 5; measured: 1 texel adds false shadows along "
                "edges)"),
        choice(Occluder::kReceivers, "self", {"self", "all"},
               "self: each mesh shadowed by its own planes (the thesis); all: also by other instances' "
               "planes, per fragment in world space (shadows on the ground and other objects)"),
    };
}

} // namespace

TechniqueInfo Occluder::declaration() {
    return {.name = "occluder",
            .description = "occluder textures on shadow planes: single-pass self-shadowing (Coleman 2006)",
            // Self-shadowing from each mesh's own planes only: no shadows on other objects or the
            // ground, and the planes approximate the casters (the thesis's missing shadows).
            .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                       Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"lighting"},
            .properties = declareProperties(),
            .quality = {{kResolution, {"64", "128", "256", "512", "1024"}}},
            .resources = [](const PropertySet& p, const ResourceInputs& in) {
                return squareMaps(p.getInt(kResolution), 1, uint64_t(std::max<int64_t>(1, p.getInt(kPlanes))),
                                  in);
            }};
}

} // namespace sb
