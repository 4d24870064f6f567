#include "scenes/Scene.h"

#include <cstring>

#include "core/Fnv1a.h"
#include "scenes/Math.h"
#include "scenes/Motion.h"

namespace sb {
namespace {

constexpr Named<Effect> kEffectNames[] = {
    {Effect::HardShadows, "hard_shadows"},
    {Effect::SoftShadows, "soft_shadows"},
    {Effect::SelfShadowing, "self_shadowing"},
    {Effect::ColourBleeding, "colour_bleeding"},
    {Effect::NonPlanarReceivers, "non_planar_receivers"},
    {Effect::MultipleLights, "multiple_lights"},
};
constexpr NameTable kEffects{kEffectNames};

constexpr Named<LightType> kLightTypeNames[] = {
    {LightType::Directional, "directional"},
    {LightType::Point, "point"},
    {LightType::Spot, "spot"},
};
constexpr NameTable kLightTypes{kLightTypeNames};

constexpr Named<LightShape> kLightShapeNames[] = {
    {LightShape::Point, "point"},
    {LightShape::Rect, "rect"},
    {LightShape::Disk, "disk"},
    {LightShape::Sphere, "sphere"},
};
constexpr NameTable kLightShapes{kLightShapeNames};

void hashLight(Fnv1a& h, const Light& l) {
    h.value(int(l.type));
    h.value(l.direction);
    h.value(l.position);
    h.value(l.color);
    h.value(l.intensity);
    h.value(l.range);
    h.value(l.spotOuterDeg);
    h.value(l.spotInnerDeg);
    h.value(int(l.shape));
    h.value(l.size);
    h.value(l.angularRadiusDeg);
    // Only a shadowless light changes the hash, so the scenes of before the key keep their hash.
    if (!l.castsShadows) h.value(uint8_t(0x5A));
}

void hashCamera(Fnv1a& h, const CameraPreset& c) {
    h.string(c.name);
    h.value(c.eye);
    h.value(c.target);
    h.value(c.up);
    h.value(c.fovYDeg);
    h.value(c.nearZ);
    h.value(c.farZ);
}

void hashInstance(Fnv1a& h, const Instance& i) {
    // The model matrix is derived, but hashing it too catches a forgotten updateTransforms().
    h.value(i.mesh);
    h.value(i.position);
    h.value(i.rotationDeg);
    h.value(i.scale);
    h.value(i.color);
    h.value(uint8_t(i.castsShadow) | uint8_t(i.receivesShadow) << 1 | uint8_t(i.fromLayout) << 2);
    h.value(i.model);
}

} // namespace

const NameTable<Named<Effect>>& effectNames() {
    return kEffects;
}

const char* effectName(Effect e) {
    return kEffects.name(e, "none");
}

std::optional<Effect> parseEffect(const std::string& name) {
    return kEffects.parse(name);
}

std::string effectMaskToString(EffectMask m) {
    std::string out;
    for (Effect e : kAllEffects) {
        if (!hasEffect(m, e)) continue;
        if (!out.empty()) out += '+';
        out += effectName(e);
    }
    return out.empty() ? "none" : out;
}

const NameTable<Named<LightType>>& lightTypeNames() {
    return kLightTypes;
}

const char* lightTypeName(LightType t) {
    return kLightTypes.name(t, "directional");
}

std::optional<LightType> parseLightType(const std::string& name) {
    return kLightTypes.parse(name);
}

const NameTable<Named<LightShape>>& lightShapeNames() {
    return kLightShapes;
}

const char* lightShapeName(LightShape s) {
    return kLightShapes.name(s, "point");
}

std::optional<LightShape> parseLightShape(const std::string& name) {
    return kLightShapes.parse(name);
}

void Scene::updateTransforms() {
    uint32_t id = 1;
    for (auto& instance : instances) {
        instance.model = composeTransform(instance.position, instance.rotationDeg, instance.scale);
        instance.objectId = id++;
    }
}

Aabb Scene::computeBounds(bool castersOnly) const {
    Aabb bounds;
    for (const auto& instance : instances) {
        if (castersOnly && !instance.castsShadow) continue;
        if (instance.mesh >= meshes.size()) continue;
        bounds.extend(transformBounds(meshBoundsOf(instance.mesh), instance.model));
    }
    return bounds;
}

Aabb Scene::meshBoundsOf(size_t mesh) const {
    return meshBounds.size() == meshes.size() ? meshBounds[mesh] : meshes[mesh].computeBounds();
}

void Scene::cacheMeshBounds() {
    meshBounds.clear();
    for (const Mesh& mesh : meshes) meshBounds.push_back(mesh.computeBounds());
}

const CameraPreset* Scene::findCamera(const std::string& cameraName) const {
    for (const auto& camera : cameras)
        if (camera.name == cameraName) return &camera;
    return nullptr;
}

std::string Scene::computeContentHash() const {
    Fnv1a h;
    h.value(uint64_t(meshes.size()));
    for (const auto& mesh : meshes) {
        h.vector(mesh.positions);
        h.vector(mesh.normals);
        h.vector(mesh.indices);
        // A computed closedness follows from the geometry; only a declared one adds (the hashes of
        // scenes without "closed" stay as they were).
        if (mesh.closedDeclared) h.value(mesh.closed ? 1 : 2);
    }
    h.value(uint64_t(instances.size()));
    for (const auto& instance : instances) hashInstance(h, instance);
    h.value(uint64_t(lights.size()));
    for (const auto& light : lights) hashLight(h, light);
    h.value(uint64_t(cameras.size()));
    for (const auto& camera : cameras) hashCamera(h, camera);
    h.value(effects);
    h.value(ambient);
    // Only a scene lit per vertex adds to the hash, so scenes lit per fragment keep theirs.
    if (lighting == LightingRate::Vertex) h.string("lighting=vertex");
    // Only a scene in motion adds to the hash, so static scenes keep the hash they always had.
    if (motion) h.string(motion->canonical());
    return h.hex();
}

size_t Scene::totalTriangles() const {
    size_t total = 0;
    for (const auto& instance : instances)
        if (instance.mesh < meshes.size()) total += meshes[instance.mesh].triangleCount();
    return total;
}

size_t Scene::countLayoutInstances() const {
    size_t n = 0;
    for (const auto& instance : instances) n += instance.fromLayout && instance.object == 0 ? 1 : 0;
    return n;
}

uint32_t Scene::shadowlessLightMask() const {
    uint32_t mask = 0;
    for (size_t i = 0; i < lights.size() && i < 32; ++i)
        if (!lights[i].castsShadows) mask |= 1u << i;
    return mask;
}

bool Scene::hasNonReceivers() const {
    for (const Instance& inst : instances)
        if (!inst.receivesShadow) return true;
    return false;
}

} // namespace sb
