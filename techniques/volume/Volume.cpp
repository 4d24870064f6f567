#include "techniques/volume/Volume.h"

#include "techniques/Property.h"
#include "techniques/volume/VolumePlanner.h"

namespace sb {

TechniqueInfo Volume::declaration() {
    return {.name = "volume",
            .description = "stencil shadow volumes (GPU Gems ch. 9), each optimisation a switch",
            .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                       Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"ambient", "mark", "lighting"},
            .viewPasses = {"ambient", "lighting"},
            .properties = VolumePlanner::declareProperties(),
            .quality = {}};
}

} // namespace sb
