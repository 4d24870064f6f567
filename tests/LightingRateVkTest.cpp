// `--lighting vertex` on Vulkan (lavapipe, validation layer on), as tests/LightingRateGLTest.cpp on GL:
// every technique with a Vulkan form equals its per-fragment image where the light's term is affine
// across every triangle (the city), and a point light over one quad gives the closed form of per-vertex
// shading (tests/LightingRateScenes.h).
#include <string>

#include <gtest/gtest.h>

#include "LightingRateScenes.h"
#include "TestSupport.h"
#include "VulkanFrame.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

test::LitImage render(const std::string& technique, const std::string& scene, const std::string& camera,
                      LightingRate rate) {
    RunConfig cfg = test::quickConfig(scene, camera, test::kLightingSize);
    cfg.api = RunConfig::Api::Vulkan;
    cfg.vulkan.validation = true;
    cfg.sceneOptions.lighting = rate;
    VulkanHarness h(cfg);
    auto t = TechniqueRegistry::createVulkan(TechniqueSpec::parse(technique));
    h.prepare(*t);
    h.renderFrame(*t);
    return {h.targets().readColorRGBA8(), h.targets().readVisibilityRGBA32F()};
}

class LightingRateVkEveryTechnique : public ::testing::TestWithParam<std::string> {};

TEST_P(LightingRateVkEveryTechnique, VertexEqualsFragmentWhereTheTermIsAffine) {
    if (const std::string refusal = test::vulkanRefusal(GetParam()); !refusal.empty())
        GTEST_SKIP() << refusal;
    test::expectSameWhereAffine(render(GetParam(), "city", "mid", LightingRate::Fragment),
                                render(GetParam(), "city", "mid", LightingRate::Vertex));
}

TEST_P(LightingRateVkEveryTechnique, AmbientIsTheScenesColour) {
    if (const std::string refusal = test::vulkanRefusal(GetParam()); !refusal.empty())
        GTEST_SKIP() << refusal;
    if (!test::shadesWithTheScenesLights(GetParam())) GTEST_SKIP() << GetParam() << " draws flat colours";
    test::expectAmbientOnly(GetParam(),
                            render(GetParam(), test::ambientOnlyScene(), "down", LightingRate::Fragment));
}

INSTANTIATE_TEST_SUITE_P(AllTechniques, LightingRateVkEveryTechnique,
                         ::testing::ValuesIn(TechniqueRegistry::namesOn(Api::Vulkan)),
                         [](const auto& info) { return info.param; });

TEST(LightingRateVk, PointLightOverOneQuadTakesTheCornersTerm) {
    for (const char* technique : {"none", "cubemap"}) test::expectPointOverQuad(technique, render);
}

} // namespace
