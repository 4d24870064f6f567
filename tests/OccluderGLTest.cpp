// `occluder` against closed forms: a square plate at y = 1 over a floor at y = 0, both one mesh (the
// technique shadows a mesh with its own planes), one shadow plane through the plate. A floor point p is
// shadowed iff the ray p + t L towards the light meets y = 1 inside the plate's square: an exact answer
// per pixel from the depth buffer's world position, judged outside a band of one texel plus one pixel
// footprint around the shadow's edge (the bake's raster edge and the pixel centre may fall either way).
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "scenes/Math.h"
#include "techniques/occluder/OccluderGL.h"
#include "techniques/occluder/OccluderTextures.h"

using namespace sb;

namespace {

constexpr int kSize = 256;
const glm::vec3 kLightDir = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f)); // travel direction

/// The scene: plate [-0.5, 0.5]^2 at y = 1, floor [-3, 3]^2 at y = 0 (both facing up), one plane.
std::string writeScene(const std::string& dir, const std::string& planeJson) {
    test::writeFile(dir + "/plate.obj", "v -0.5 1 -0.5\nv 0.5 1 -0.5\nv 0.5 1 0.5\nv -0.5 1 0.5\n"
                                        "v -3 0 -3\nv 3 0 -3\nv 3 0 3\nv -3 0 3\n"
                                        "g plate\nusemtl a\nf 1 4 3\nf 1 3 2\n"
                                        "g floor\nusemtl b\nf 5 8 7\nf 5 7 6\n");
    const std::string path = dir + "/scene.json";
    test::writeFile(path, R"({"name": "plate_floor",
  "meshes": [{"name": "plate", "file": "plate.obj", "shadow_planes": [)" +
                              planeJson + R"(]}],
  "instances": [{"mesh": "plate", "position": [0, 0, 0]}],
  "lights": [{"type": "directional", "direction": [0.3, -1, 0.2]}],
  "cameras": [{"name": "top", "eye": [0, 8, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 60,
               "near": 0.5, "far": 50}]})");
    return path;
}

struct Judged {
    int judged = 0, wrong = 0, shadowed = 0;
};

/// Renders `spec` and judges every floor pixel against `shadowedAt(p)` outside the edge band given by
/// `margin(p)` (world units, negative inside the shadow) and `band`.
template <typename Margin>
Judged judge(const std::string& scene, const std::string& spec, Margin margin, double band,
             std::vector<float>* visibilityOut = nullptr, SubmitMode submit = SubmitMode::Retained) {
    RunConfig cfg = test::quickConfig(scene, "top", kSize, submit);
    Harness h(cfg);
    OccluderGL t;
    t.properties().apply(TechniqueSpec::parse(spec).properties);
    h.prepare(t);
    h.renderFrame(t);
    const std::vector<float> vis = h.targets().readVisibilityRGBA32F();
    const glm::mat4 viewProj = cameraProjection(h.camera(), 1.0f) * cameraView(h.camera());
    const auto world = test::unprojectDepth(h.targets().readDepth(), kSize, kSize, viewProj);
    Judged j;
    for (int y = 1; y < kSize - 1; ++y)
        for (int x = 1; x < kSize - 1; ++x) {
            const size_t i = size_t(y) * kSize + size_t(x);
            if (world[i].w == 0.0f || std::abs(world[i].y) > 1e-3f) continue; // floor pixels only
            const double footprint = glm::length(glm::vec3(world[i + 1]) - glm::vec3(world[i]));
            const double m = margin(glm::dvec3(world[i]));
            const bool got = vis[i * 4] < 0.5f;
            j.shadowed += got;
            if (std::abs(m) <= band + footprint) continue;
            ++j.judged;
            j.wrong += got != (m < 0.0);
        }
    if (visibilityOut) *visibilityOut = vis;
    return j;
}

/// Signed distance (in the plate's plane, max norm) of the floor point's ray hit at y = 1 from the
/// square [lo, hi]^2 in x and z: negative inside.
double squareMargin(const glm::dvec3& p, double lo, double hi) {
    const glm::dvec3 toLight = -glm::dvec3(kLightDir);
    const glm::dvec3 hit = p + toLight * ((1.0 - p.y) / toLight.y);
    return std::max({lo - hit.x, hit.x - hi, lo - hit.z, hit.z - hi});
}

const char* kPlanePlate = R"({"name": "plate", "origin": [-1, 1, 1], "normal": [0, 1, 0],
    "right": [1, 0, 0], "up": [0, 0, -1], "width": 2, "height": 2, "parts": ["plate"]})";

} // namespace

TEST(OccluderGLTest, BakedPlateShadowMatchesTheClosedForm) {
    const std::string dir = test::freshTestDir("occluder");
    const std::string scene = writeScene(dir, kPlanePlate);
    // One texel of a 2 m plane at 256 texels: 7.8 mm, in the plane; projected along the light onto the
    // floor the band stretches by at most 1 / |L.y| (1.05).
    const double band = 2.0 / 256.0 * 1.1;
    std::vector<float> perVertex, perInstance;
    const Judged a = judge(
        scene, "occluder:resolution=256", [](const glm::dvec3& p) { return squareMargin(p, -0.5, 0.5); },
        band, &perVertex);
    EXPECT_GT(a.judged, 10000);
    // The shadow is there at all: 1 m^2 of the ~85 m^2 view, most of it hidden under the plate from
    // straight above (measured 228 pixels).
    EXPECT_GT(a.shadowed, 100);
    EXPECT_EQ(a.wrong, 0) << "of " << a.judged;
    // The thesis's proposed optimisation must not change the image: the light in model space once per
    // instance gives the same coordinates up to float rounding (the same visibility in all but a few
    // texel-edge pixels).
    const Judged b = judge(
        scene, "occluder:resolution=256:light_space=per_instance",
        [](const glm::dvec3& p) { return squareMargin(p, -0.5, 0.5); }, band, &perInstance);
    EXPECT_EQ(b.wrong, 0);
    size_t differ = 0;
    for (size_t i = 0; i < perVertex.size(); i += 4)
        differ += std::abs(perVertex[i] - perInstance[i]) > 0.02f;
    EXPECT_LE(differ, 20u) << "pixels whose visibility differs between per_vertex and per_instance";
    // The texture matrix (the thesis's future work) folds the same equations into an affine map: the
    // same shadow, judged against the closed form and compared with per_vertex alike.
    std::vector<float> matrix;
    const Judged c = judge(
        scene, "occluder:resolution=256:light_space=texture_matrix",
        [](const glm::dvec3& p) { return squareMargin(p, -0.5, 0.5); }, band, &matrix);
    EXPECT_EQ(c.wrong, 0);
    EXPECT_EQ(c.shadowed > 100, true);
    differ = 0;
    for (size_t i = 0; i < perVertex.size(); i += 4) differ += std::abs(perVertex[i] - matrix[i]) > 0.02f;
    EXPECT_LE(differ, 20u) << "pixels whose visibility differs between per_vertex and texture_matrix";
}

TEST(OccluderGLTest, SolidPlaneShadowsItsRectangle) {
    // The teapot handle's kind: no texture, [0, 1]^2 is shadow. The plane covers the plate exactly.
    const std::string dir = test::freshTestDir("occluder");
    const std::string scene = writeScene(dir, R"({"name": "solid", "origin": [-0.5, 1, 0.5],
        "normal": [0, 1, 0], "right": [1, 0, 0], "up": [0, 0, -1], "width": 1, "height": 1, "solid": true})");
    const Judged j = judge(
        scene, "occluder", [](const glm::dvec3& p) { return squareMargin(p, -0.5, 0.5); }, 0.0);
    EXPECT_GT(j.judged, 10000);
    EXPECT_EQ(j.wrong, 0) << "of " << j.judged;
}

TEST(OccluderGLTest, LoadedTextureShadowsOnlyItsDarkHalf) {
    // An image whose left half (u < 0.5, x < 0 on this plane) is black: only the plate's x < 0 half
    // casts. Written with OccluderTextures::write, read back through the scene's "texture".
    const std::string dir = test::freshTestDir("occluder");
    constexpr int n = 64;
    std::vector<uint8_t> texels(size_t(n) * n, 255);
    for (int v = 0; v < n; ++v)
        for (int u = 0; u < n / 2; ++u) texels[size_t(v) * n + size_t(u)] = 0;
    OccluderTextures::write(dir + "/half.png", texels, n, n);
    const std::string scene = writeScene(dir, R"({"name": "half", "origin": [-0.5, 1, 0.5],
        "normal": [0, 1, 0], "right": [1, 0, 0], "up": [0, 0, -1], "width": 1, "height": 1,
        "texture": "half.png"})");
    // Texel 1/64 m, resampled to 256: the bilinear edge spreads over one source texel.
    const Judged j = judge(
        scene, "occluder:resolution=256",
        [](const glm::dvec3& p) {
            // The dark half u < 0.5 is x < 0 on the plate's plane. Lookups are clamped (Appendix B), and a
            // loaded image keeps its border as drawn: the black left half of every border row and column
            // extends the occluder to infinity towards -x and along z. So the shadow is exactly the half
            // plane hit.x < 0: the clamp made visible (only baked textures get a clear border).
            const glm::dvec3 toLight = -glm::dvec3(kLightDir);
            const glm::dvec3 hit = p + toLight * ((1.0 - p.y) / toLight.y);
            return hit.x;
        },
        1.5 / 64.0);
    EXPECT_GT(j.judged, 10000);
    EXPECT_EQ(j.wrong, 0) << "of " << j.judged;
}

TEST(OccluderGLTest, ReceiversAllCastsOntoOtherInstances) {
    // The plate alone is one mesh (with the plane), the floor another instance of a generated plane:
    // with receivers=self the floor gets no shadow at all (the thesis's self-shadowing), with
    // receivers=all it gets the plate's, judged against the same closed form in world space.
    const std::string dir = test::freshTestDir("occluder");
    test::writeFile(dir + "/plate.obj", "v -0.5 1 -0.5\nv 0.5 1 -0.5\nv 0.5 1 0.5\nv -0.5 1 0.5\n"
                                        "g plate\nf 1 4 3\nf 1 3 2\n");
    const std::string scene = dir + "/scene.json";
    test::writeFile(scene, std::string(R"({"name": "plate_ground",
  "meshes": [{"name": "plate", "file": "plate.obj", "shadow_planes": [)") +
                               kPlanePlate + R"(]},
             {"name": "ground", "generator": "plane", "size": 6, "tessellation": 4}],
  "instances": [{"mesh": "plate", "position": [0, 0, 0]},
                {"mesh": "ground", "position": [0, 0, 0], "casts_shadow": false}],
  "lights": [{"type": "directional", "direction": [0.3, -1, 0.2]}],
  "cameras": [{"name": "top", "eye": [0, 8, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 60,
               "near": 0.5, "far": 50}]})");
    auto margin = [](const glm::dvec3& p) { return squareMargin(p, -0.5, 0.5); };
    const double band = 2.0 / 256.0 * 1.1;
    const Judged self = judge(scene, "occluder:resolution=256", margin, band);
    EXPECT_EQ(self.shadowed, 0) << "receivers=self must not shadow another instance";
    const Judged all = judge(scene, "occluder:resolution=256:receivers=all", margin, band);
    EXPECT_GT(all.judged, 10000);
    EXPECT_GT(all.shadowed, 100);
    EXPECT_EQ(all.wrong, 0) << "of " << all.judged;
}

TEST(OccluderGLTest, ReceiverSectionsLimitWhichPartsAPlaneShadows) {
    // The thesis's receiver sections (section 5): a plane shadows only the parts it names as receivers.
    // The plate's plane with receivers ["floor"] casts the closed-form shadow on the floor; with
    // receivers ["plate"] the floor (another part of the same mesh) gets none. The vertex stage finds
    // its section by the position's bits (techniques/occluder/ReceiverSections.h), which must hold in
    // every submission mode: retained, instanced, display lists (a compiled glBegin/glEnd stream) and
    // immediate (whose last draw once lost its texture to a Mesa flush bug, ImmediateSubmitter.h).
    const std::string dir = test::freshTestDir("occluder");
    const std::string plane = R"({"name": "plate", "origin": [-1, 1, 1], "normal": [0, 1, 0],
        "right": [1, 0, 0], "up": [0, 0, -1], "width": 2, "height": 2, "parts": ["plate"], "receivers": [)";
    auto margin = [](const glm::dvec3& p) { return squareMargin(p, -0.5, 0.5); };
    const double band = 2.0 / 256.0 * 1.1;
    for (SubmitMode mode : kAllSubmitModes) {
        SCOPED_TRACE(submitModeName(mode));
        const Judged floor = judge(writeScene(dir, plane + R"("floor"]})"), "occluder:resolution=256", margin,
                                   band, nullptr, mode);
        EXPECT_GT(floor.judged, 10000);
        EXPECT_GT(floor.shadowed, 100);
        EXPECT_EQ(floor.wrong, 0) << "of " << floor.judged;
        const Judged plate = judge(writeScene(dir, plane + R"("plate"]})"), "occluder:resolution=256", margin,
                                   band, nullptr, mode);
        EXPECT_EQ(plate.shadowed, 0) << "the floor is not a receiver of the plate's plane";
    }
}
