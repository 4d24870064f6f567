#include "techniques/synthetic/Synthetic.h"

#include "techniques/Property.h"

namespace sb {

namespace {

/// The knobs, one maker call each (techniques/Property.h): what --list shows and -t name:k=v sets.
std::vector<PropertyDesc> declareProperties() {
    return {
        integer(Synthetic::kFragmentIterations, "0", 0, 100000,
                "arithmetic steps per pixel of a full-screen pass (0: no pass)"),
        integer(Synthetic::kVertexIterations, "0", 0, 100000,
                "extra arithmetic steps per vertex of the scene pass"),
        flag(Synthetic::kDrawScene, "true", "draw the scene's triangles"),
    };
}

} // namespace

TechniqueInfo Synthetic::declaration() {
    return {.name = "synthetic",
            .description = "calibration workload of known bottleneck (no shadows): full-screen fill loop, "
                           "vertex loop, or the scene's draws",
            .effects = 0,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"scene", "fill"},
            .properties = declareProperties()};
}

} // namespace sb
