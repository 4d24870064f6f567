#pragma once
// What a scene leaves a technique's shadow passes to do (the scene's "casts_shadows" per light,
// "casts_shadow" / "receives_shadow" per instance): a technique asks before each frame and, where the
// answer is "nothing", skips its shadow passes with the reason (PassTimer::skip), so a scene pays only
// for the shadows it asks for. The visibility of the skipped work is 1 (common/lighting.glsl,
// shadowApplies), which is also what the Embree reference computes for it.
#include "scenes/Scene.h"

namespace sb {

class ShadowWork {
public:
    /// Why the scene's lighting programs read no shadow at all, or nullptr when some light may shadow
    /// some receiver: "no light casts shadows" (every light "casts_shadows": false) or "no instance
    /// receives a shadow". Then CompileContext::defines makes common/lighting.glsl's shadowApplies
    /// false for every fragment, and a technique may leave its shadow passes out. (A scene without
    /// casters is not among them: its programs still look shadows up, in maps cleared to "lit".)
    static const char* noneNeeded(const Scene& scene);
    /// Lights (of the first `lightCount`) with castsShadows false: the counter `lights_unshadowed`.
    static size_t unshadowedLights(const Scene& scene, size_t lightCount);
};

} // namespace sb
