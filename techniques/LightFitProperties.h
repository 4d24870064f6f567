#pragma once
// The light fit's two knobs (scenes/LightFit.h), one name, maker and reading for every technique whose
// directional light camera is that fit: the flat maps of the shadow-map family (`shadowmap`, `pcss`,
// `vsm`, `esm`, through techniques/ShadowMapProperties.h) and `projective`'s projector. It
// lives below the technique folders because no technique folder includes another.
#include <string>

#include "scenes/LightFit.h"
#include "techniques/Property.h"
#include "techniques/PropertySet.h"

namespace sb {

class LightFitProperties {
public:
    static constexpr const char* kFit = "fit";
    static constexpr const char* kFitMargin = "fit_margin";

    /// `fit`: what a directional light's map (`what` names it: "map", "projector") frames, one of the
    /// fits of scenes/LightFit.h (casters, sphere, scene), default casters; `otherLights` says what the
    /// technique's other lights take instead.
    static PropertyDesc fit(const std::string& what, const std::string& otherLights);
    /// `fit_margin`: the fit's margin on each side, a share of the framed extent: 0 to 10, default
    /// 0.01 (LightFit::kDefaultMargin).
    static PropertyDesc fitMargin();
    /// The light fit `p` asks for (its `fit` and `fit_margin`).
    static LightFit lightFit(const PropertySet& p);
};

} // namespace sb
