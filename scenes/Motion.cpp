#include "scenes/Motion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "scenes/Math.h"

namespace sb {

namespace {

glm::vec3 mix3(const glm::vec3& a, const glm::vec3& b, float f) {
    return a + (b - a) * f;
}

float mix1(float a, float b, float f) {
    return a + (b - a) * f;
}

std::string text(const glm::vec3& v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "[%.9g,%.9g,%.9g]", double(v.x), double(v.y), double(v.z));
    return buf;
}

std::string text(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", double(v));
    return buf;
}

/// The unit direction from the scene towards a sun at azimuth `azimuth` and elevation `elevation`
/// (radians): azimuth 0 is +X, 90 degrees +Z.
glm::vec3 towardsSun(float azimuth, float elevation) {
    return {std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
            std::cos(elevation) * std::sin(azimuth)};
}

} // namespace

float Motion::timeOfFrame(uint64_t frame) const {
    const uint32_t n = std::max<uint32_t>(1, frames);
    return float(frame % n) / float(n);
}

uint32_t Motion::changes(bool cameraFollows) const {
    uint32_t c = 0;
    if (sun || orbit) c |= kLightsMoved;
    if (casters) c |= kCastersMoved;
    if (camera && cameraFollows) c |= kCameraMoved;
    return c;
}

void Motion::apply(const Scene& rest, Scene& scene, float t) const {
    if (sun) {
        const float pi = std::numbers::pi_v<float>;
        const float azimuth = glm::radians(mix1(sun->azimuthDeg.x, sun->azimuthDeg.y, t));
        const float elevation = glm::radians(sun->elevationDeg.x +
                                             (sun->elevationDeg.y - sun->elevationDeg.x) * std::sin(pi * t));
        const glm::vec3 towards = towardsSun(azimuth, elevation);
        Light& light = scene.lights[sun->light];
        light.direction = -towards;
        if (light.type != LightType::Directional) light.position = sun->centre + towards * sun->distance;
    }
    if (orbit) {
        const float angle = 2.0f * std::numbers::pi_v<float> * orbit->turns * t;
        Light& light = scene.lights[orbit->light];
        light.position = orbit->centre + orbit->radius * glm::vec3(std::cos(angle), 0.0f, std::sin(angle));
        if (light.type != LightType::Point) light.direction = glm::normalize(orbit->target - light.position);
    }
    if (casters) {
        for (uint32_t i : casters->instances) {
            const Instance& from = rest.instances[i];
            Instance& inst = scene.instances[i];
            inst.position = from.position + casters->translate * t;
            inst.rotationDeg = from.rotationDeg + glm::vec3(0.0f, casters->yawDeg * t, 0.0f);
            inst.model = composeTransform(inst.position, inst.rotationDeg, inst.scale);
        }
    }
}

CameraPreset Motion::cameraAt(float t) const {
    const std::vector<CameraPreset>& keys = camera->keys;
    const float along = std::clamp(t, 0.0f, 1.0f) * float(keys.size() - 1);
    const size_t first = std::min(size_t(along), keys.size() - 2);
    const float f = along - float(first);
    const CameraPreset& a = keys[first];
    const CameraPreset& b = keys[first + 1];
    CameraPreset c = a;
    c.name = kCameraName;
    c.eye = mix3(a.eye, b.eye, f);
    c.target = mix3(a.target, b.target, f);
    c.up = glm::normalize(mix3(a.up, b.up, f));
    c.fovYDeg = mix1(a.fovYDeg, b.fovYDeg, f);
    c.nearZ = mix1(a.nearZ, b.nearZ, f);
    c.farZ = mix1(a.farZ, b.farZ, f);
    return c;
}

std::string Motion::describe() const {
    std::string out;
    auto add = [&](bool on, const char* what) {
        if (!on) return;
        if (!out.empty()) out += "+";
        out += what;
    };
    add(sun.has_value(), "sun");
    add(orbit.has_value(), "orbit");
    add(camera.has_value(), "camera");
    add(casters.has_value(), "casters");
    return out;
}

std::string Motion::canonical() const {
    std::string out = "frames=" + std::to_string(frames);
    if (sun)
        out += ";sun=" + std::to_string(sun->light) + "," + text(sun->azimuthDeg.x) + "," +
               text(sun->azimuthDeg.y) + "," + text(sun->elevationDeg.x) + "," + text(sun->elevationDeg.y);
    if (orbit)
        out += ";orbit=" + std::to_string(orbit->light) + "," + text(orbit->centre) + "," +
               text(orbit->radius) + "," + text(orbit->turns) + "," + text(orbit->target);
    if (camera)
        for (const CameraPreset& k : camera->keys)
            out += ";key=" + text(k.eye) + text(k.target) + text(k.up) + "," + text(k.fovYDeg) + "," +
                   text(k.nearZ) + "," + text(k.farZ);
    if (casters) {
        out += ";casters=" + text(casters->translate) + "," + text(casters->yawDeg) + ":";
        for (uint32_t i : casters->instances) out += std::to_string(i) + ",";
    }
    return out;
}

} // namespace sb
