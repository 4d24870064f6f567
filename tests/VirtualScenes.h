#pragma once
// The scene `virtual`'s cache tests walk on both APIs (tests/VirtualGLTest.cpp, tests/VirtualVkTest.cpp):
// boxes and a ball over a floor under a directional light; the casters slide and turn over 8 frames, so
// the light's map stays put and only the pages under the casters' old and new places are invalidated.
#include <string>

#include "TestSupport.h"

namespace sb::test {

inline std::string virtualMovingCastersScene() {
    const std::string path = freshTestDir("virtual_moving") + "/moving.json";
    writeFile(path, R"({"name": "virtual_moving",
  "meshes": [{"name": "box", "generator": "box", "half_extent": [0.6, 0.6, 0.6]},
             {"name": "ball", "generator": "sphere", "radius": 0.7, "tessellation": 16},
             {"name": "floor", "generator": "plane", "size": 16, "tessellation": 4}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false},
                {"mesh": "box", "position": [1.5, 0.6, 0], "color": [0.7, 0.4, 0.3]},
                {"mesh": "box", "position": [-1.5, 0.6, 0.5], "color": [0.3, 0.6, 0.4]},
                {"mesh": "ball", "position": [0, 1.6, -1.2]}],
  "lights": [{"type": "directional", "direction": [-0.4, -1, -0.3]}],
  "cameras": [{"name": "view", "eye": [0, 9, 7], "target": [0, 0, 0], "fov": 50, "near": 0.5, "far": 60}],
  "effects": ["hard_shadows", "self_shadowing"],
  "motion": {"frames": 8, "casters": {"instances": "casters", "translate": [0.5, 0, 0.8], "yaw_deg": 70}}})");
    return path;
}

} // namespace sb::test
