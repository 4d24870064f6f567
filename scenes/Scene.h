#pragma once
// The scene model (docs/ARCHITECTURE.md, "Scenes"): meshes, instances, lights, named cameras and the effects
// the scene asks for. Built by SceneLoader from a JSON file; techniques only read it.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/NameTable.h"
#include "scenes/LightingRate.h"
#include "scenes/Mesh.h"

namespace sb {

/// Effects a scene can ask for and a technique can produce (docs/ARCHITECTURE.md, "The technique contract").
/// Bit flags.
enum class Effect : uint32_t {
    None = 0,
    HardShadows = 1u << 0,
    SoftShadows = 1u << 1,
    SelfShadowing = 1u << 2,
    ColourBleeding = 1u << 3,
    NonPlanarReceivers = 1u << 4,
    MultipleLights = 1u << 5,
};
using EffectMask = uint32_t;
constexpr EffectMask operator|(Effect a, Effect b) {
    return uint32_t(a) | uint32_t(b);
}
constexpr EffectMask operator|(EffectMask a, Effect b) {
    return a | uint32_t(b);
}
constexpr bool hasEffect(EffectMask m, Effect e) {
    return (m & uint32_t(e)) != 0;
}
/// "hard_shadows", "soft_shadows", "self_shadowing", "colour_bleeding", "non_planar_receivers",
/// "multiple_lights": the names used in scene files, --list and CSV.
const NameTable<Named<Effect>>& effectNames();
const char* effectName(Effect e);
std::optional<Effect> parseEffect(const std::string& name);
std::string effectMaskToString(EffectMask m); ///< "hard_shadows+self_shadowing"
constexpr Effect kAllEffects[] = {Effect::HardShadows,    Effect::SoftShadows,        Effect::SelfShadowing,
                                  Effect::ColourBleeding, Effect::NonPlanarReceivers, Effect::MultipleLights};

struct Instance {
    uint32_t mesh = 0; ///< index into Scene::meshes
    glm::vec3 position{0.0f};
    glm::vec3 rotationDeg{0.0f}; ///< Euler XYZ, applied Z then Y then X (R = Rx * Ry * Rz)
    float scale = 1.0f;          ///< uniform only: normals transform with mat3(model) / scale
    glm::vec3 color{0.8f};
    bool castsShadow = true;
    bool receivesShadow = true;
    bool fromLayout = false; ///< placed by the random layout (these are what --scale scales)
    glm::mat4 model{1.0f};   ///< derived from the above by Scene::updateTransforms()
    uint32_t objectId = 0;   ///< 1-based, unique, written into the G-buffer (0 = background)
    /// Which object of a multi-object model file this instance draws (0 for every other mesh): a
    /// file's objects are separate meshes placed by one instance each, all with the same transform
    /// (SceneLoader), so the "instances" a user asked for are those with object 0.
    uint32_t object = 0;
};

enum class LightType { Directional, Point, Spot };
/// "directional", "point", "spot": scene files, --light, the CSV.
const NameTable<Named<LightType>>& lightTypeNames();
const char* lightTypeName(LightType t);
std::optional<LightType> parseLightType(const std::string& name);

/// The emitter's extent, for soft shadows (the reference's area sampling, soft techniques). `Point`
/// is a delta light: hard shadows. Rect and disk lie in the plane through `position` perpendicular
/// to `direction`; a sphere is centred at `position`. For a directional light, `Disk` with
/// `angularRadiusDeg` is the sun's disk seen from the scene.
enum class LightShape { Point, Rect, Disk, Sphere };
/// "point", "rect", "disk", "sphere": scene files' light "shape".
const NameTable<Named<LightShape>>& lightShapeNames();
const char* lightShapeName(LightShape s);
std::optional<LightShape> parseLightShape(const std::string& name);

struct Light {
    LightType type = LightType::Directional;
    glm::vec3 direction{0.0f, -1.0f, 0.0f}; ///< unit, from the light into the scene (directional, spot)
    glm::vec3 position{0.0f, 10.0f, 0.0f};  ///< point, spot
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    float range = 0.0f;         ///< point/spot: distance of zero contribution; 0 = unlimited
    float spotOuterDeg = 30.0f; ///< half-angle of the spot cone
    float spotInnerDeg = 25.0f; ///< half-angle of full intensity
    LightShape shape = LightShape::Point;
    /// rect: width and height (width along the rect's u axis, see reference/LightSampler.h);
    /// disk and sphere: radius in x.
    glm::vec2 size{0.0f};
    float angularRadiusDeg = 0.0f; ///< directional + disk: angular radius of the emitter
    /// false: the light illuminates but casts no shadow (scene file "casts_shadows": false, a fill
    /// light): no technique renders a shadow pass for it and its visibility is 1 everywhere.
    bool castsShadows = true;
    bool isArea() const { return shape != LightShape::Point; }
};

struct CameraPreset {
    std::string name;
    glm::vec3 eye{0.0f, 5.0f, 10.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDeg = 45.0f;
    float nearZ = 0.1f;
    float farZ = 1000.0f;
};

class Motion;

struct Scene {
    std::string name;       ///< "aircraft", or the file stem
    std::string sourcePath; ///< the JSON file it came from ("" for purely built-in)
    std::vector<Mesh> meshes;
    std::vector<Instance> instances;
    std::vector<Light> lights;
    std::vector<CameraPreset> cameras;
    EffectMask effects = uint32_t(Effect::HardShadows);
    glm::vec3 ambient{0.15f};
    /// Where the lit passes evaluate the lights: the file's "lighting", replaced by `--lighting`.
    LightingRate lighting = LightingRate::Fragment;
    /// The scene file's "motion" (scenes/Motion.h), or null for a static scene. Shared: copies of a
    /// scene (the harness keeps one at rest) move along the same paths.
    std::shared_ptr<const Motion> motion;
    /// Each mesh's model-space bounds, filled at load (SceneLoader: cacheMeshBounds) because meshes never
    /// change afterwards; motion moves instances, not vertices. Then every bounds query of a frame in
    /// motion (light fits, culling) transforms 8 corners per instance instead of reading every vertex.
    /// Empty, or not one per mesh (a scene built or extended in code): meshBoundsOf reads the vertices.
    /// Code that edits a loaded mesh's vertices clears it.
    std::vector<Aabb> meshBounds;

    /// Recomputes Instance::model and objectId from position/rotation/scale.
    void updateTransforms();
    /// World-space bounds of all instances (or only casters).
    Aabb computeBounds(bool castersOnly = false) const;
    /// Mesh `mesh`'s model-space bounds: meshBounds's entry where it holds one per mesh, else computed.
    Aabb meshBoundsOf(size_t mesh) const;
    /// Fills meshBounds from the meshes' vertices.
    void cacheMeshBounds();
    const CameraPreset* findCamera(const std::string& name) const;
    /// Hash over everything that changes an image (geometry, instances, lights, cameras, motion), hex
    /// string. Of a scene in motion, hash the scene at rest (the harness's Harness::contentHash()).
    /// Recorded in every CSV row so two rows can be trusted to describe the same content.
    std::string computeContentHash() const;
    size_t totalTriangles() const; ///< over all instances
    /// Layout instances as the user counts them (--instances): one per placement, however many
    /// objects its model file has.
    size_t countLayoutInstances() const;
    /// The lights with castsShadows false as a bit mask (bit i = light i, the first 32 lights).
    uint32_t shadowlessLightMask() const;
    /// Whether some instance has receivesShadow false.
    bool hasNonReceivers() const;
};

} // namespace sb
