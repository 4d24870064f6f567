#pragma once
// The world-space ShadowProxies of a scene ("ShadowProxies", OpenGL Insights, section 1.3, step 1):
// what `proxy` shades with and what `planar:occluder=proxy` flattens. A scene computation rather than
// a technique's, so two techniques share it without one including the other.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Scene.h"
#include "scenes/ShadowProxy.h"

namespace sb {

struct ProxyCollection {
    /// Per caster instance its mesh's declared proxies through the instance's model, or the fitted one
    /// (`fitAll`: ignore declarations). Frames are made invertible (sanitizeFrame). `owners`, when
    /// given, receives each proxy's instance object id.
    static std::vector<ShadowProxy> collect(const Scene& scene, bool fitAll, std::vector<uint32_t>* owners);
    /// A frame whose columns (the scaled axes) have zero or near-zero length gets `minimum`-long axes
    /// there, perpendicular to the others: a zero-radius sphere becomes a point-sized one, a box with
    /// zero extent on one axis a flat one. Its inverse is then finite. Everything else is unchanged.
    static glm::mat4 sanitizeFrame(const glm::mat4& frame, float minimum);
};

} // namespace sb
