// `shadowmap` and `volume` on Vulkan against the same closed form as on GL (tests/SphereShadowJudge.h:
// the sphere's shadow on the plane is an exact ellipse; tests/ShadowMapGLTest.cpp and
// tests/VolumeGLTest.cpp on GL), in the same cases, with the validation layer on: no validation error in
// any of them.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "NonReceiverScene.h"
#include "SphereShadowJudge.h"
#include "TestSupport.h"
#include "VulkanFrame.h"
#include "bench/lib/harness/VulkanHarness.h"

using namespace sb;

namespace {

struct Case {
    const char* name;
    const char* spec;
    SubmitMode submit;
};
void PrintTo(const Case& c, std::ostream* os) {
    *os << c.name;
}

const Case kCases[] = {
    {"hw_compare_retained", "shadowmap", SubmitMode::Retained},
    {"shader_compare_pcf1", "shadowmap:hardware_compare=false", SubmitMode::Retained},
    {"pcf3_instanced", "shadowmap:pcf=3", SubmitMode::Instanced},
    {"low_res_512", "shadowmap:resolution=512", SubmitMode::Retained},
};

/// Renders one frame of `tc` on sphere_plane seen from the top, with the validation layer on, and judges
/// its shadow against the analytic ellipse within the technique's band (`band` of the scene and the
/// technique's properties); no validation error either.
template <typename Band>
void judgeOnSphere(const Case& tc, Band band) {
    constexpr int kSize = 384;
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize, tc.submit);
    cfg.sceneOptions.tessellation = 64;
    cfg.sceneOptions.lightType = LightType::Directional;
    test::VulkanFrame frame(cfg, tc.spec);
    VulkanHarness& h = frame.harness();
    test::judgeSphereShadow(h.scene(), band(h.scene(), frame.technique().properties()),
                            h.targets().readDepth(), h.targets().readVisibilityRGBA32F(),
                            h.projection() * h.view(), kSize);
}

class SphereShadowVulkan : public ::testing::TestWithParam<Case> {};

TEST_P(SphereShadowVulkan, MatchesAnalyticEllipse) {
    judgeOnSphere(GetParam(), [](const Scene& scene, const PropertySet& properties) {
        return test::shadowMapBand(scene, properties);
    });
}

INSTANTIATE_TEST_SUITE_P(ShadowMap, SphereShadowVulkan, ::testing::ValuesIn(kCases),
                         [](const auto& p) { return std::string(p.param.name); });

// `volume` is exact: its band is the polygonal silhouette and the pixel footprint alone. The camera's own
// far plane (far=depth_clamp) keeps the depth buffer unprojectable with the camera's matrices.
const Case kVolumeCases[] = {
    {"volume_cpu_retained", "volume:far=depth_clamp", SubmitMode::Retained},
    {"volume_vertex_instanced", "volume:far=depth_clamp:extrusion=vertex", SubmitMode::Instanced},
    {"volume_zfail", "volume:far=depth_clamp:mode=zfail", SubmitMode::Retained},
};

class VolumeSphereShadowVulkan : public ::testing::TestWithParam<Case> {};

TEST_P(VolumeSphereShadowVulkan, MatchesAnalyticEllipse) {
    judgeOnSphere(GetParam(), [](const Scene&, const PropertySet&) { return 0.0; });
}

INSTANTIATE_TEST_SUITE_P(Volume, VolumeSphereShadowVulkan, ::testing::ValuesIn(kVolumeCases),
                         [](const auto& p) { return std::string(p.param.name); });

// The non-receivers drawn apart on Vulkan by every member of the family whose lighting pass looks its
// map up per fragment (tests/ShadowMapGLTest.cpp has the GL form and the exact measure): the pipeline
// without the lookup is used, and the image equals the one-pipeline control's, bit for bit, in both
// Vulkan submission modes.
TEST(ShadowMapVulkan, NonReceiversDrawnLastGiveTheSameImage) {
    for (const char* spec : test::kNonReceiverSplitSpecs)
        for (SubmitMode mode : {SubmitMode::Retained, SubmitMode::Instanced}) {
            SCOPED_TRACE(std::string(spec) + " " + submitModeName(mode));
            test::VulkanFrame apart(test::quickConfig(test::nonReceiverScene(true), "view", 128, mode), spec);
            test::VulkanFrame together(test::quickConfig(test::nonReceiverScene(false), "view", 128, mode),
                                       spec);
            EXPECT_NE(apart.technique().permutationKey().find("SB_NON_RECEIVER_DRAWS"), std::string::npos);
            EXPECT_EQ(together.technique().permutationKey().find("SB_NON_RECEIVER_DRAWS"), std::string::npos);
            const std::vector<float> visibility = apart.harness().targets().readVisibilityRGBA32F();
            EXPECT_TRUE(apart.harness().targets().readColorRGBA8() ==
                        together.harness().targets().readColorRGBA8());
            EXPECT_TRUE(visibility == together.harness().targets().readVisibilityRGBA32F());
            // Not vacuous: some of the floor is in the ball's shadow.
            size_t shadowed = 0;
            for (size_t i = 0; i < visibility.size(); i += 4) shadowed += visibility[i] < 0.5f;
            EXPECT_GT(shadowed, 100u);
        }
}

} // namespace
