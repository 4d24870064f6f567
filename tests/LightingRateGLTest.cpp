// `--lighting vertex` on GL (scenes/LightingRate.h, shaders/common/lighting.glsl): every technique's lit
// passes evaluate the lights per vertex and interpolate. Where the light's term is affine across every
// triangle (a directional light on flat faces: the city's boxes and ground) the image equals per
// fragment's; where it is not, it is the closed form of per-vertex shading (a point light over a single
// quad, tests/LightingRateScenes.h).
#include <string>

#include <gtest/gtest.h>

#include "LightingRateScenes.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"

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

INSTANTIATE_TEST_SUITE_P(AllTechniques, LightingRateEveryTechnique,
                         ::testing::ValuesIn(TechniqueRegistry::namesOn(Api::GL)),
                         [](const auto& info) { return info.param; });

TEST(LightingRateGL, PointLightOverOneQuadTakesTheCornersTerm) {
    for (const char* technique : {"none", "cubemap"}) test::expectPointOverQuad(technique, render);
}

} // namespace
