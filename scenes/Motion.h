#pragma once
// A scene in motion (scene file "motion", scenes/SceneLoader.h): paths over a path time t in [0, 1] for
// a light (the sun over a day, a point or spot light on an orbit), the camera (a fly-through of key
// cameras) and the casters (moved and turned). A run measures its frames along the path, frame f at
// t = (f mod frames) / frames, so the per-frame work a static frame lets a technique do once (light
// fits, projectors, silhouettes, occluder light transforms, cascade refits, acceleration structures)
// is paid in every frame, as an application that animates pays it. Receivers never move: only lights,
// the camera and instances that cast a shadow.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/Scene.h"

namespace sb {

/// What changed between two frames of a scene in motion (Technique::sceneChanged): bit flags.
enum SceneChange : uint32_t {
    kLightsMoved = 1u << 0,
    kCastersMoved = 1u << 1,
    kCameraMoved = 1u << 2,
};

/// A light over a day: azimuth from `azimuthDeg[0]` to `[1]` (degrees in the ground plane, 0 = +X,
/// 90 = +Z), elevation low + (high - low) sin(pi t): low at both ends of the path (long shadows at
/// sunrise and sunset), highest at noon. A directional light takes the sun's direction; a point or spot
/// light (a scene's sun under --light point) moves on the sphere of its distance around the casters'
/// centre, a spot aiming at that centre.
struct SunPath {
    uint32_t light = 0;
    glm::vec2 azimuthDeg{-60.0f, 60.0f};
    glm::vec2 elevationDeg{15.0f, 70.0f}; ///< low, high
    glm::vec3 centre{0.0f};               ///< the casters' centre (SceneLoader fills it)
    float distance = 0.0f;                ///< a point or spot light's distance from the centre at rest
};

/// A light on a horizontal circle: position = centre + radius (cos, 0, sin) of 2 pi turns t; a spot
/// aims at `target`, and a directional light (a scene's orbit under --light directional) shines from
/// the position towards it.
struct OrbitPath {
    uint32_t light = 0;
    glm::vec3 centre{0.0f, 5.0f, 0.0f};
    float radius = 5.0f;
    float turns = 1.0f;
    glm::vec3 target{0.0f};
};

/// The camera through key cameras, piecewise linear in eye, target, up, field of view and planes, the
/// keys equally spaced in t. Selected with `--camera path`.
struct CameraPath {
    std::vector<CameraPreset> keys; ///< at least two
};

/// Casters moved by `translate` and turned by `yawDeg` about their own origin over the whole path.
struct CasterPath {
    std::vector<uint32_t> instances; ///< indices into Scene::instances; every one casts a shadow
    glm::vec3 translate{0.0f};
    float yawDeg = 0.0f;
};

class Motion {
public:
    /// The name of the camera that follows the camera path ("path").
    static constexpr const char* kCameraName = "path";

    uint32_t frames = 60; ///< frames per pass along the path
    std::optional<SunPath> sun;
    std::optional<OrbitPath> orbit;
    std::optional<CameraPath> camera;
    std::optional<CasterPath> casters;

    /// Path time of frame `frame`: (frame mod frames) / frames.
    float timeOfFrame(uint64_t frame) const;
    /// What moves along the path (SceneChange bits; the camera only where `cameraFollows`).
    uint32_t changes(bool cameraFollows) const;
    /// Sets `scene`'s moving lights and casters to their state at path time `t`, starting from `rest`
    /// (the scene as loaded; same instances and lights). Model matrices of the moved casters are
    /// recomputed; nothing else is touched.
    void apply(const Scene& rest, Scene& scene, float t) const;
    /// The camera path at `t` (requires `camera`).
    CameraPreset cameraAt(float t) const;
    /// "sun+casters", "orbit+camera" ...: what moves, for the CSV's `motion` column.
    std::string describe() const;
    /// A stable text of every parameter, for the scene's content hash.
    std::string canonical() const;
};

} // namespace sb
