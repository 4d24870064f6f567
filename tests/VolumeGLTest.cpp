// `volume`'s visibility target against the Embree reference where the light passes do not run. The
// target means shadowing only (1 lit, 0 shadowed): beyond a point light's range, outside the scissor
// rectangle of section 9.6.2, no volume is counted and nothing is shadowed; the light's range is a
// lighting term (the colour gets no light there), not a shadow. The reference ray-casts without the
// range, so on the lit ground there it says 1, and so must the technique. And the closed form on GL
// (tests/SphereShadowJudge.h), as tests/ShadowMapVkTest.cpp runs it on Vulkan.
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "SphereShadowJudge.h"
#include "TestSupport.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/Math.h"
#include "techniques/volume/VolumeGeometry.h"

using namespace sb;

namespace {

constexpr int kSize = 256;

/// Ground [-20, 20]^2 (receives, casts nothing), a box 0.8 on a side on it at the origin, light 0 a
/// point light at (0.8, 2, 0) with range 3 (its range cube covers the middle of the view; the box's
/// shadow, x in [-1.2, -0.4], lies within 2.83 of the light, inside the range), light 1 a point light
/// far off screen (range 3 around (40, 2, 0): its scissor rectangle is empty, its pass never runs).
std::string writeScene(const std::string& dir) {
    const std::string path = dir + "/scissor.json";
    test::writeFile(path, R"({"name": "scissor",
  "meshes": [{"name": "box", "generator": "box", "half_extent": [0.4, 0.4, 0.4], "tessellation": 1},
             {"name": "ground", "generator": "plane", "size": 40, "tessellation": 4}],
  "instances": [{"mesh": "ground", "position": [0, 0, 0], "casts_shadow": false},
                {"mesh": "box", "position": [0, 0.4, 0]}],
  "lights": [{"type": "point", "position": [0.8, 2, 0], "range": 3},
             {"type": "point", "position": [40, 2, 0], "range": 3}],
  "cameras": [{"name": "top", "eye": [0, 30, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 40,
               "near": 0.5, "far": 100}]})");
    return path;
}

bool isGround(const glm::vec4& w) {
    return w.w != 0.0f && std::abs(w.y) < 1e-3f;
}

} // namespace

TEST(VolumeGLTest, OutsideTheScissorRectangleIsUnshadowed) {
    const std::string scene = writeScene(test::freshTestDir("volume"));
    const test::RenderedFrame reference = test::renderSpec(scene, "top", kSize, "reference:hard=true");
    // Light 0's scissor rectangle, from the same camera the harness uses (square target).
    Harness h(test::quickConfig(scene, "top", kSize));
    const glm::mat4 viewProj = cameraProjection(h.camera(), 1.0f) * cameraView(h.camera());
    const auto rect = VolumeGeometry::scissorRect(h.scene().lights[0], viewProj, kSize, kSize);
    ASSERT_TRUE(rect.has_value());
    ASSERT_LT(rect->z * rect->w, kSize * kSize / 2) << "the case needs ground outside the rectangle";
    // The defaults (scissor, range and frustum culling on), and the other paths that skip work beyond
    // the range: no scissor (the light pass runs everywhere), finite volumes (extruded by the range),
    // no culling at all. Each must mean the same: 1 unless a volume covers the pixel.
    for (const char* spec : {"volume", "volume:scissor=false", "volume:finite_volumes=true",
                             "volume:range_cull=false:frustum_cull=false"}) {
        const test::RenderedFrame volume = test::renderSpec(scene, "top", kSize, spec);
        int outside = 0, outsideWrong = 0, inside = 0, insideWrong = 0, insideShadowed = 0, far = 0,
            farWrong = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const size_t i = size_t(y) * kSize + size_t(x);
                // The reference's depth (the camera's projection; volume's far plane is at infinity).
                if (!isGround(reference.world[i])) continue;
                const float v0 = volume.visibility[i * 4], r0 = reference.visibility[i * 4];
                const bool in =
                    x >= rect->x && x < rect->x + rect->z && y >= rect->y && y < rect->y + rect->w;
                if (!in) {
                    // The reference sees the light from every ground point out there (the box's shadow
                    // lies within the range): 1, exactly; the technique must say the same.
                    ++outside;
                    outsideWrong += v0 != r0;
                } else {
                    ++inside;
                    insideWrong += v0 != r0;
                    insideShadowed += r0 == 0.0f;
                }
                // Light 1's rectangle is empty: no pass, no shadow anywhere in its channel. The
                // reference is 1 on the ground except the box's long shadow towards -x (compared
                // where it is 1).
                if (reference.visibility[i * 4 + 1] == 1.0f) {
                    ++far;
                    farWrong += volume.visibility[i * 4 + 1] != 1.0f;
                }
            }
        std::cout << spec << ": rect " << rect->x << " " << rect->y << " " << rect->z << " " << rect->w
                  << ": outside " << outside << " (" << outsideWrong << " wrong), inside " << inside << " ("
                  << insideWrong << " wrong, " << insideShadowed << " shadowed), off-screen light " << far
                  << " (" << farWrong << " wrong)\n";
        EXPECT_GT(outside, kSize * kSize / 4) << spec;
        EXPECT_EQ(outsideWrong, 0) << spec << ": " << outside << " ground pixels outside the rectangle";
        EXPECT_GT(far, kSize * kSize / 2) << spec;
        EXPECT_EQ(farWrong, 0) << spec << ": " << far << " ground pixels the off-screen light lights";
        // Inside, the volumes are exact up to rasterisation: at most the shadow's outline may differ
        // (~3.5 units at 0.085 units per pixel, ~40 px, doubled); the shadow (~0.9 square units, ~120
        // px) must be there.
        EXPECT_GT(insideShadowed, 60) << spec;
        EXPECT_LT(insideWrong, 80) << spec << ": " << inside << " ground pixels inside";
    }
}

namespace {

struct SphereCase {
    const char* name;
    const char* spec;
    SubmitMode submit;
};
void PrintTo(const SphereCase& c, std::ostream* os) {
    *os << c.name;
}

// The same cases tests/ShadowMapVkTest.cpp runs on Vulkan. `volume` is exact: its band is the polygonal
// silhouette and the pixel footprint alone; far=depth_clamp keeps the camera's own far plane, so the
// depth buffer unprojects with the camera's matrices.
const SphereCase kSphereCases[] = {
    {"volume_cpu_retained", "volume:far=depth_clamp", SubmitMode::Retained},
    {"volume_vertex_instanced", "volume:far=depth_clamp:extrusion=vertex", SubmitMode::Instanced},
    {"volume_zfail", "volume:far=depth_clamp:mode=zfail", SubmitMode::Retained},
};

class VolumeSphereShadow : public ::testing::TestWithParam<SphereCase> {};

} // namespace

TEST_P(VolumeSphereShadow, MatchesAnalyticEllipse) {
    const SphereCase& tc = GetParam();
    constexpr int kSphereSize = 384;
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSphereSize, tc.submit);
    cfg.sceneOptions.tessellation = 64;
    cfg.sceneOptions.lightType = LightType::Directional;
    Harness h(cfg);
    auto volume = TechniqueRegistry::create(TechniqueSpec::parse(tc.spec));
    h.prepare(*volume);
    h.renderFrame(*volume);
    test::judgeSphereShadow(h.scene(), 0.0, h.targets().readDepth(), h.targets().readVisibilityRGBA32F(),
                            h.projection() * h.view(), kSphereSize);
}

INSTANTIATE_TEST_SUITE_P(Volume, VolumeSphereShadow, ::testing::ValuesIn(kSphereCases),
                         [](const auto& p) { return std::string(p.param.name); });
