#pragma once
// The one refusal of a point light by the techniques whose shadow map looks one way (shadowmap, cascaded,
// pcss, vsm, esm; hybrid through its default cast part, which is shadowmap), and the configurations that
// do shade a point light's shadow, which the refusal names and `-t auto` tries
// (bench/lib/select/Calibration.h). A point light casts in every direction: it needs an omni shadow map,
// `cubemap` or `paraboloid`, alone or as hybrid's cast part (`hybrid:cast=cubemap`; hybrid's self part,
// occluder by default, takes a point light as it is). tests/AutoCliTest.cpp runs every configuration the
// message names on a point-lit scene.
#include <string>
#include <vector>

#include "scenes/Scene.h"

namespace sb {

class PointLightRefusal {
public:
    /// The techniques that render a point light's shadow map in every direction around it.
    static const std::vector<std::string>& omniTechniques();
    /// hybrid with each of them as its cast part: "hybrid:cast=cubemap", "hybrid:cast=paraboloid".
    static std::vector<std::string> omniHybrids();
    /// "<technique>: light <index> is a point light, which needs an omni shadow map: use -t cubemap,
    /// -t paraboloid, -t hybrid:cast=cubemap or -t hybrid:cast=paraboloid, or --light directional or
    /// --light spot".
    static std::string message(const std::string& technique, size_t index);
    /// Throws Error(message(technique, index), ExitCode::Unsupported) when `light` is a point light.
    static void refuse(const Light& light, size_t index, const std::string& technique);
    /// Whether some light of `scene` (within the shader's light limit) is a point light that casts
    /// shadows: the lights the techniques above refuse.
    static bool sceneHasOne(const Scene& scene);
};

} // namespace sb
