#pragma once
// The scenes and closed forms of the lighting tests on both APIs (tests/LightingRateGLTest.cpp,
// tests/LightingRateVkTest.cpp): `--lighting vertex` evaluates each light at the vertices and
// interpolates (scenes/LightingRate.h); every lit pass adds the scene's ambient, a compile-time constant
// (SB_AMBIENT, techniques/Technique.h).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "scenes/LightingRate.h"

namespace sb::test {

constexpr int kLightingSize = 64;

/// One floor quad (plane of size 4, tessellation 1: its 4 corners are the only vertices) at y = 0, lit
/// by a point light 2 above its centre, ambient 0.1, albedo 0.5; the camera looks down at the centre.
/// Per vertex, the 4 corners see the light alike (n.l = 2 / sqrt(2^2 + 2 * 2^2) = 1 / sqrt(3), no range),
/// so the interpolated term is that constant over the whole quad; per fragment the point below the
/// light gets n.l = 1.
inline std::string pointOverQuadScene() {
    const std::string path = freshTestDir("lighting_rate") + "/point_over_quad.json";
    writeFile(path, R"({"name": "point_over_quad",
  "meshes": [{"name": "floor", "generator": "plane", "size": 4, "tessellation": 1}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false, "color": [0.5, 0.5, 0.5]}],
  "lights": [{"type": "point", "position": [0, 2, 0], "color": [1, 1, 1], "intensity": 1}],
  "cameras": [{"name": "down", "eye": [0, 3, 0.5], "target": [0, 0, 0], "fov": 60}],
  "ambient": [0.1, 0.1, 0.1]})");
    return path;
}

/// The RGBA8 value of pointOverQuadScene's floor: 255 x albedo x (ambient + n.l).
inline double pointOverQuadValue(double ndotl) {
    return 255.0 * 0.5 * (0.1 + ndotl);
}
/// n.l at the quad's corners (the closed form above).
inline double pointOverQuadCornerNdotl() {
    return 1.0 / std::sqrt(3.0);
}

/// The targets a lighting-rate test compares.
struct LitImage {
    std::vector<unsigned char> color;
    std::vector<float> visibility;
};

/// Per vertex equals per fragment where the light's term is affine across every triangle: the colour
/// within 1 of 255 (the interpolation of a constant may round differently in the last bit before the
/// 8-bit store), the visibility bit for bit (shadows do not depend on where the light is evaluated).
inline void expectSameWhereAffine(const LitImage& fragment, const LitImage& vertex) {
    ASSERT_EQ(fragment.color.size(), vertex.color.size());
    int largest = 0;
    for (size_t i = 0; i < fragment.color.size(); ++i)
        largest = std::max(largest, std::abs(int(fragment.color[i]) - int(vertex.color[i])));
    EXPECT_LE(largest, 1);
    EXPECT_EQ(fragment.visibility, vertex.visibility);
}

/// The closed form of pointOverQuadScene for `technique`, rendered by `render(technique, scene, camera,
/// rate)`: per vertex, every pixel around the centre takes the corners' term, 255 x 0.5 x (0.1 +
/// 1/sqrt(3)) = 86.4 (tolerance 1: the store's rounding); per fragment the centre, under the light,
/// 255 x 0.5 x 1.1 = 140.25 (tolerance 2: the centre pixel's sample lies a fraction of a pixel off the
/// point below the light).
template <class Render>
void expectPointOverQuad(const char* technique, Render render) {
    const std::string scene = pointOverQuadScene();
    const LitImage vertex = render(technique, scene, "down", LightingRate::Vertex);
    const LitImage fragment = render(technique, scene, "down", LightingRate::Fragment);
    const int c = kLightingSize / 2;
    const double corner = pointOverQuadValue(pointOverQuadCornerNdotl());
    for (int dy = -8; dy <= 8; dy += 4)
        for (int dx = -8; dx <= 8; dx += 4) {
            const size_t p = (size_t(c + dy) * kLightingSize + size_t(c + dx)) * 4;
            EXPECT_NEAR(vertex.color[p], corner, 1.0) << technique << " at " << dx << "," << dy;
        }
    EXPECT_NEAR(fragment.color[(size_t(c) * kLightingSize + size_t(c)) * 4], pointOverQuadValue(1.0), 2.0)
        << technique;
}

/// Whether `technique` shades with the scene's lights and ambient: all but `synthetic`, whose workloads
/// draw flat colours (shaders/synthetic).
inline bool shadesWithTheScenesLights(const std::string& technique) {
    return technique != "synthetic";
}

/// One floor quad lit by nothing but the ambient (its only light shines from below, n.l = -1 on the
/// floor's upper face), a colour that is not grey and an albedo that is not either, so that each channel
/// of SB_AMBIENT's three-argument form is checked: the floor is 255 x albedo x ambient per channel.
inline std::string ambientOnlyScene() {
    const std::string path = freshTestDir("ambient") + "/ambient_only.json";
    writeFile(path, R"({"name": "ambient_only",
  "meshes": [{"name": "floor", "generator": "plane", "size": 4, "tessellation": 1}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false, "color": [0.8, 0.6, 0.4]}],
  "lights": [{"type": "directional", "direction": [0, 1, 0], "color": [1, 1, 1], "intensity": 1}],
  "cameras": [{"name": "down", "eye": [0, 3, 0.5], "target": [0, 0, 0], "fov": 60}],
  "ambient": [0.1, 0.3, 0.7]})");
    return path;
}

/// ambientOnlyScene's floor, rendered by `technique`: 255 x (0.8 x 0.1, 0.6 x 0.3, 0.4 x 0.7) = (20.4, 45.9,
/// 71.4) at every pixel around the centre (tolerance 1: the 8-bit store's rounding, none of the three is
/// near a half).
inline void expectAmbientOnly(const std::string& technique, const LitImage& image) {
    const double expected[3] = {255.0 * 0.8 * 0.1, 255.0 * 0.6 * 0.3, 255.0 * 0.4 * 0.7};
    const int c = kLightingSize / 2;
    for (int dy = -8; dy <= 8; dy += 8)
        for (int dx = -8; dx <= 8; dx += 8)
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(image.color[(size_t(c + dy) * kLightingSize + size_t(c + dx)) * 4 + size_t(k)],
                            expected[k], 1.0)
                    << technique << " channel " << k << " at " << dx << "," << dy;
}

} // namespace sb::test
