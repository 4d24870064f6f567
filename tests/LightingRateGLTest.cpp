// `--lighting vertex` on GL (scenes/LightingRate.h, shaders/common/lighting.glsl): every technique's lit
// passes evaluate the lights per vertex and interpolate. Where the light's term is affine across every
// triangle (a directional light on flat faces: the city's boxes and ground) the image equals per
// fragment's; where it is not, it is the closed form of per-vertex shading (a point light over a single
// quad, tests/LightingRateScenes.h).
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "LightingRateScenes.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"
#include "techniques/Technique.h"

using namespace sb;

namespace {

test::LitImage render(const std::string& technique, const std::string& scene, const std::string& camera,
                      LightingRate rate) {
    RunConfig cfg = test::quickConfig(scene, camera, test::kLightingSize);
    cfg.sceneOptions.lighting = rate;
    Harness h(cfg);
    auto t = TechniqueRegistry::create(TechniqueSpec::parse(technique));
    h.prepare(*t);
    h.renderFrame(*t);
    return {h.targets().readColorRGBA8(), h.targets().readVisibilityRGBA32F()};
}

class LightingRateEveryTechnique : public ::testing::TestWithParam<std::string> {};

TEST_P(LightingRateEveryTechnique, VertexEqualsFragmentWhereTheTermIsAffine) {
    test::expectSameWhereAffine(render(GetParam(), "city", "mid", LightingRate::Fragment),
                                render(GetParam(), "city", "mid", LightingRate::Vertex));
}

TEST_P(LightingRateEveryTechnique, AmbientIsTheScenesColour) {
    if (!test::shadesWithTheScenesLights(GetParam())) GTEST_SKIP() << GetParam() << " draws flat colours";
    test::expectAmbientOnly(GetParam(),
                            render(GetParam(), test::ambientOnlyScene(), "down", LightingRate::Fragment));
}

INSTANTIATE_TEST_SUITE_P(AllTechniques, LightingRateEveryTechnique,
                         ::testing::ValuesIn(TechniqueRegistry::namesOn(Api::GL)),
                         [](const auto& info) { return info.param; });

TEST(LightingRateGL, PointLightOverOneQuadTakesTheCornersTerm) {
    for (const char* technique : {"none", "cubemap"}) test::expectPointOverQuad(technique, render);
}

// SB_AMBIENT's floats parse back to the uniform's floats bit for bit: the constant and the uniform path
// (a program compiled without the scene's defines) shade alike.
TEST(AmbientDefine, EveryFloatParsesBackToItself) {
    for (float v : {0.0f, 1.0f, 0.15f, 0.1f, 1.0f / 3.0f, 1e-7f, 12345.678f}) {
        const std::string text = ambientDefine(glm::vec3(v));
        ASSERT_EQ(text.rfind("vec3(", 0), 0u) << text;
        const std::string literal = text.substr(5, text.size() - 6);
        EXPECT_NE(literal.find_first_of(".e"), std::string::npos) << text << ": not a float literal";
        EXPECT_EQ(std::strtof(literal.c_str(), nullptr), v) << text;
    }
    EXPECT_EQ(ambientDefine({0.1f, 0.3f, 0.7f}), "vec3(0.1,0.3,0.7)");
    EXPECT_EQ(ambientDefine(glm::vec3(0.0f)), "vec3(0.0)");
}

} // namespace
