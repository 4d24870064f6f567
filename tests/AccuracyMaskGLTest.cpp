// The accuracy evaluator's mask (bench/lib/measure/AccuracyEvaluator.h) under a spot light: samples outside
// the outer cone receive no light, so they are not judged, exactly as samples beyond a light's range
// are not. The answer is computed here from each pixel's world position (depth read back and
// unprojected) and the cone's half-angle, independently of the evaluator; before the cone was left
// out, every technique, exact ones included, came out about 85% wrong on this view.
#include <cmath>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "reference/AccuracyMetrics.h"
#include "scenes/Math.h"
#include "techniques/shadowmap/ShadowMapGL.h"

using namespace sb;

TEST(AccuracyMask, SpotLightJudgesOnlyInsideItsCone) {
    constexpr int kSize = 192;
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize);
    cfg.sceneOptions.lightType = LightType::Spot;
    Harness h(cfg);
    ShadowMapGL t;
    h.prepare(t);
    AccuracyEvaluator evaluator(h);
    AccuracyOptions options;
    options.stability = false;
    const AccuracyEvaluator::Sample s = evaluator.judgeFrame(t, options, nullptr);

    const Light& light = h.scene().lights[0];
    ASSERT_EQ(light.type, LightType::Spot);
    FrameTargets& targets = h.targets();
    const glm::mat4 viewProj = cameraProjection(h.camera(), 1.0f) * cameraView(h.camera());
    const std::vector<glm::vec4> world =
        test::unprojectDepth(targets.readDepth(), targets.width(), targets.height(), viewProj);
    // A judged sample outside the cone, or an unjudged lit ground sample well inside it, would be the
    // evaluator's fault. The cone's rim is left out by 1 degree either way: the mask's positions are
    // the G-buffer's, the test's are from the depth buffer, a hair apart.
    const float cosInside = std::cos(glm::radians(light.spotOuterDeg - 1.0f));
    const float cosOutside = std::cos(glm::radians(light.spotOuterDeg + 1.0f));
    size_t judgedOutside = 0, missedInside = 0, outside = 0, judged = 0;
    for (size_t i = 0; i < world.size(); ++i) {
        if (world[i].w == 0.0f) continue;
        const glm::vec3 d = glm::normalize(glm::vec3(world[i]) - light.position);
        const float c = glm::dot(d, glm::normalize(light.direction));
        const bool ground = std::abs(world[i].y) < 1e-3f; // n = +y, facing the light above it
        judged += s.mask[i] ? 1 : 0;
        if (c < cosOutside) {
            ++outside;
            judgedOutside += s.mask[i] ? 1 : 0;
        }
        if (ground && c > cosInside && !s.mask[i]) ++missedInside;
    }
    ASSERT_GT(outside, world.size() / 4) << "the view must show ground outside the cone for the test to bite";
    ASSERT_GT(judged, 1000u);
    EXPECT_EQ(judgedOutside, 0u) << "of " << outside << " samples outside the cone";
    EXPECT_EQ(missedInside, 0u);

    // And what the fix is for: the shadow map is exact up to its texels here, so off the edge band
    // almost nothing is wrong (the bound of the matrix's map rule, 1.5%).
    const HardMetrics m = AccuracyMetrics::hard(s.technique, s.reference, s.mask, kSize, kSize);
    EXPECT_LT(m.wrongNoEdgePct, 1.5);
}
