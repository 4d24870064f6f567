#pragma once
// The scene of `volume`'s GPU silhouette tests on GL and Vulkan (tests/VolumeSilhouetteGLTest.cpp,
// tests/VolumeSilhouetteVkTest.cpp): two instances of a closed built-in mesh, the second smaller and
// turned, over a ground that casts nothing, a point light and an oblique directional light in general
// position (no face plane through them), seen from an oblique camera (or every given mesh at once, each
// in its own place, for a test that must cover them all in one frame); and the count of samples in which
// two visibility images differ.
#include <cmath>
#include <string>
#include <vector>

#include "TestSupport.h"

namespace sb::test {

/// The scene's file from its meshes' and casters' JSON entries.
inline std::string writeSilhouetteSceneFile(const std::string& path, const std::string& name,
                                            const std::string& meshes, const std::string& casters) {
    writeFile(path, R"({"name": ")" + name + R"(",
  "meshes": [)" + meshes +
                        R"(
             {"name": "ground", "generator": "plane", "size": 12, "tessellation": 2}],
  "instances": [{"mesh": "ground", "position": [0, 0, 0], "casts_shadow": false},)" +
                        casters + R"(],
  "lights": [{"type": "point", "position": [2.3, 4.1, 1.7]},
             {"type": "directional", "direction": [-0.35, -1, -0.21]}],
  "cameras": [{"name": "oblique", "eye": [-4.2, 3.3, 5.1], "target": [0.3, 0.6, -0.2], "up": [0, 1, 0],
               "fov": 50, "near": 0.1, "far": 100}]})");
    return path;
}

/// Writes the scene of `generator` into `dir` and returns its path (camera "oblique").
inline std::string writeSilhouetteScene(const std::string& dir, const std::string& generator) {
    return writeSilhouetteSceneFile(dir + "/" + generator + ".json", generator,
                                    R"({"name": "caster", "generator": ")" + generator + R"("},)",
                                    R"(
                {"mesh": "caster", "position": [0, 1.3, 0]},
                {"mesh": "caster", "position": [2.1, 0.9, -1.4], "scale": 0.6, "rotation": [10, 35, 5]})");
}

/// Writes one scene with every mesh of `generators`, each once, on a circle of radius 1.8 around the
/// scene's centre at rising heights, scaled 0.55 and turned, and returns its path (camera "oblique").
inline std::string writeSilhouetteSceneOfAll(const std::string& dir,
                                             const std::vector<std::string>& generators) {
    std::string meshes, casters;
    for (size_t k = 0; k < generators.size(); ++k) {
        const double a = 6.283185307179586 * double(k) / double(generators.size());
        const std::string name = "caster" + std::to_string(k);
        meshes += R"({"name": ")" + name + R"(", "generator": ")" + generators[k] + R"("},)";
        casters += std::string(k ? "," : "") + R"(
                {"mesh": ")" +
                   name + R"(", "position": [)" + std::to_string(1.8 * std::cos(a)) + ", " +
                   std::to_string(0.9 + 0.2 * double(k)) + ", " + std::to_string(1.8 * std::sin(a)) +
                   R"(], "scale": 0.55, "rotation": [10, )" + std::to_string(35 + 20 * int(k)) + ", 5]}";
    }
    return writeSilhouetteSceneFile(dir + "/all.json", "all", meshes, casters);
}

/// Samples (floats) that differ between `a` and `b`, a size difference counted in full.
inline int differingSamples(const std::vector<float>& a, const std::vector<float>& b) {
    int n = 0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) n += a[i] != b[i];
    return n + int(a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
}

} // namespace sb::test
