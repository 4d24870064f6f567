#include "techniques/none/None.h"

#include "techniques/Property.h"

namespace sb {

TechniqueInfo None::declaration() {
    return {.name = "none",
            .description = "lit, unshadowed: the baseline of every overhead ratio",
            .effects = 0,
            .capabilities = {{Api::GL, "GL 4.5", 4, 5, ""}},
            .passes = {"lighting"},
            .properties = {}};
}

} // namespace sb
