#pragma once
// A light's emitter as the ray-traced soft shadows sample it (shaders/raytraced/emitter.glsl): the same
// shapes, frames and maps as the Embree reference's reference/LightSampler, so that `raytraced:mode=soft`
// estimates the quantity the reference computes (the unweighted fraction of the emitter a point sees).
//
// What a shader needs of an emitter that no motion changes (its kind and extent: motion moves lights, it
// does not reshape them) is compiled in, as the lights' colours and cones are (addLightKindDefines,
// techniques/Technique.h): SB_EMITTERS=vec4[4](...), light i's LightEmitter::constant at index i. The
// positions and directions, which motion changes, stay the frame block's uniforms.
#include <glm/glm.hpp>

#include "scenes/Scene.h"
#include "shading/Defines.h"

namespace sb {

/// Which map emitter.glsl applies; the values are emitter.glsl's kEmitter* constants. Point and
/// Direction are delta lights (LightSampler::isDelta): one ray towards the centre, a hard shadow.
enum class EmitterKind : int {
    Point = 0,     ///< positional, no extent: towards Light::position, valid from everywhere
    Direction = 1, ///< directional, no extent: along -Light::direction, infinitely far
    Rect = 2,      ///< one-sided rect of size.x by size.y in the plane through position normal to direction
    Disk = 3,      ///< one-sided disk of radius size.x, same plane
    Sphere = 4,    ///< sphere of radius size.x around position, sampled over the cap a point sees
    Cone = 5,      ///< the sun: directions within angularRadiusDeg of -direction
};

struct LightEmitter {
    EmitterKind kind = EmitterKind::Point;
    /// x: the kind (as a float), y, z: the rect's width and height, or the disk's or sphere's radius in
    /// y; w: the cone's cos(angular radius), computed as LightSampler computes it (bit for bit).
    glm::vec4 constant{0.0f};

    /// The emitter of `light`, delta exactly where LightSampler(light).isDelta() (a zero extent, or a
    /// point shape).
    static LightEmitter of(const Light& light);
    bool delta() const { return kind == EmitterKind::Point || kind == EmitterKind::Direction; }
};

/// SB_EMITTERS=vec4[kMaxLights](...): each light's LightEmitter::constant, zeros (a point) past the scene's
/// lights; emitter.glsl's lightEmitter(i) reads it.
void addEmitterDefines(const Scene& scene, Defines& defines);

} // namespace sb
