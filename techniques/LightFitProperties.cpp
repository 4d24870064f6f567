#include "techniques/LightFitProperties.h"

#include <vector>

namespace sb {

PropertyDesc LightFitProperties::fit(const std::string& what, const std::string& otherLights) {
    std::vector<std::string> names;
    for (const auto& e : lightFitBoundsNames().entries()) names.emplace_back(e.name);
    return choice(kFit, "casters", std::move(names),
                  "what a directional light's " + what +
                      " frames: casters (their bounding box: the most texels per unit, the largest depth "
                      "fill), sphere (a square around their bounding sphere, the same size from every "
                      "direction, as glmark2's shadow scene) or scene (every instance, receivers too: the "
                      "fewest texels per unit, the least fill); " +
                      otherLights);
}

PropertyDesc LightFitProperties::fitMargin() {
    return real(kFitMargin, "0.01", 0, 10,
                "margin of the light fit on each side, a share of the framed extent (+ 1e-3 world units): "
                "0.5 doubles the map's side");
}

LightFit LightFitProperties::lightFit(const PropertySet& p) {
    LightFit fit;
    // The property's choices are the table's names, so the parse cannot fail on a validated set.
    fit.bounds = lightFitBoundsNames().parse(p.getEnum(kFit)).value_or(LightFitBounds::Casters);
    fit.margin = float(p.getFloat(kFitMargin));
    return fit;
}

} // namespace sb
