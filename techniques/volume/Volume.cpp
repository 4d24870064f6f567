#include "techniques/volume/Volume.h"

#include "techniques/Property.h"
#include "techniques/volume/VolumePlanner.h"

namespace sb {

namespace {

/// The GPU silhouette paths the golden matrix judges beside the CPU's (techniques/MatrixVariant.h).
std::vector<MatrixVariant> matrixVariants() {
    const char* why =
        "builds the CPU path's closed-mesh volume triangle for triangle on the device (the same "
        "classification, caps and sides per face: tests/VolumeSilhouetteGLTest.cpp and "
        "VolumeSilhouetteVkTest.cpp hold its count and image to the CPU's), so its stencil counts "
        "and visibility are volume's and it is held to volume's exact rule; a scene with an open "
        "caster mesh is refused (unsupported: the path builds closed-mesh volumes only)";
    return {{"extrusion=geometry", AccuracyRule::Exact, std::string("a geometry shader ") + why},
            {"extrusion=compute", AccuracyRule::Exact, std::string("a compute shader ") + why},
            {"extrusion=mesh", AccuracyRule::Exact, std::string("a mesh shader ") + why,
             "GL has no mesh shaders: extrusion=mesh is a Vulkan form (VK_EXT_mesh_shader), judged on "
             "the driver that offers it"}};
}

} // namespace

TechniqueInfo Volume::declaration() {
    return {.name = "volume",
            .description = "stencil shadow volumes (GPU Gems ch. 9), each optimisation a switch",
            .effects = Effect::HardShadows | Effect::SelfShadowing | Effect::NonPlanarReceivers |
                       Effect::MultipleLights,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"ambient", "mark", "lighting"},
            .viewPasses = {"ambient", "lighting"},
            .properties = VolumePlanner::declareProperties(),
            .quality = {},
            .matrixVariants = matrixVariants()};
}

} // namespace sb
