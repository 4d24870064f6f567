#pragma once
// Which instances a draw covers (docs/ARCHITECTURE.md, "Submission"), a question about the scene that
// both APIs' submitters and the culling that narrows their draws (scenes/InstanceCulling.h) ask.
#include <cstddef>
#include <cstdint>
#include <span>

#include "scenes/Scene.h"

namespace sb {

/// Shadow casters, shadow receivers, or all; NonCasters are the instances that cast no shadow (grounds,
/// walls): what `projective` textures, its casters staying lit.
enum class DrawSet { All, Casters, Receivers, NonCasters, NonReceivers };
constexpr size_t kDrawSetCount = 5;

/// The instances a draw keeps, indexed like Scene::instances (non-zero = drawn): what a technique's
/// per-frustum culling leaves (scenes/InstanceCulling.h), applied on top of the DrawSet. Empty keeps every
/// instance of the set.
using InstanceMask = std::span<const uint8_t>;

/// Whether `inst` belongs to `set`.
constexpr bool inDrawSet(const Instance& inst, DrawSet set) {
    switch (set) {
    case DrawSet::All:
        return true;
    case DrawSet::Casters:
        return inst.castsShadow;
    case DrawSet::Receivers:
        return inst.receivesShadow;
    case DrawSet::NonCasters:
        return !inst.castsShadow;
    case DrawSet::NonReceivers:
        return !inst.receivesShadow;
    }
    return false;
}

/// Whether `keep` keeps instance `instance` (an empty mask keeps all).
constexpr bool keptBy(InstanceMask keep, size_t instance) {
    return keep.empty() || keep[instance] != 0;
}

/// The w the shaders get with the instance colour, on every API and in every submission mode: the object
/// id, negated for an instance that receives no shadow. The sign costs no attribute, uniform or call of
/// its own; shaders read the id as abs(w) (common/instance.glsl) and the sign only under SB_NON_RECEIVERS
/// (common/lighting.glsl).
inline float shadowSignedId(const Instance& inst) {
    return inst.receivesShadow ? float(inst.objectId) : -float(inst.objectId);
}

} // namespace sb
