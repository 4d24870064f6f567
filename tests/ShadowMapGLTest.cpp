// `shadowmap` against closed forms: the shadow of a sphere on a plane under a directional light is an
// exact ellipse; a ground point p is in it iff the ray p - t*L (towards the light) passes within r of
// the sphere's centre. Every ground pixel's world position comes from the depth buffer, so each pixel
// is judged against the exact answer at its own sample position.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/run/Harness.h"
#include "core/Error.h"
#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "techniques/none/NoneTechnique.h"
#include "techniques/shadowmap/ShadowMapTechnique.h"

using namespace sb;

namespace {

struct SphereShadowCase {
    const char* name;
    const char* techniqueProps; // applied to shadowmap
    SubmitMode submit;
};
// Names the case in gtest output instead of dumping its bytes.
void PrintTo(const SphereShadowCase& c, std::ostream* os) {
    *os << c.name;
}

const SphereShadowCase kCases[] = {
    {"hw_compare_retained", "", SubmitMode::Retained},
    {"shader_compare_pcf1", "hardware_compare=false", SubmitMode::Retained},
    {"pcf3_instanced", "pcf=3", SubmitMode::Instanced},
    {"low_res_512", "resolution=512", SubmitMode::Retained},
};

class SphereShadow : public ::testing::TestWithParam<SphereShadowCase> {};

// Distance from the sphere centre c to the ray from p towards the light, minus the radius: negative
// inside the shadow ellipse, positive outside, in world units perpendicular to the light.
double shadowMargin(const glm::dvec3& p, const glm::dvec3& toLight, const glm::dvec3& c, double r) {
    glm::dvec3 pc = c - p;
    double t = glm::dot(pc, toLight);
    if (t <= 0.0) return 1e9; // the sphere is behind the point (below the plane): no shadow
    return glm::length(pc - t * toLight) - r;
}

TEST_P(SphereShadow, MatchesAnalyticEllipse) {
    const SphereShadowCase& tc = GetParam();
    constexpr int kSize = 384;
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize, tc.submit);
    cfg.sceneOptions.tessellation = 64; // polygonal silhouette within r(1 - cos(pi/64)) = 1.2e-3 r
    cfg.sceneOptions.lightType = LightType::Directional;
    Harness h(cfg);
    ShadowMapTechnique sm;
    TechniqueSpec spec =
        TechniqueSpec::parse(std::string("shadowmap") + (*tc.techniqueProps ? ":" : "") + tc.techniqueProps);
    sm.properties().apply(spec.properties);
    h.prepare(sm);
    h.renderFrame(sm);

    const Scene& scene = h.scene();
    // The sphere: the instance whose mesh is not the ground; centre and radius from its geometry.
    const Instance* sphere = nullptr;
    for (const Instance& i : scene.instances)
        if (i.castsShadow) sphere = &i;
    ASSERT_NE(sphere, nullptr);
    double meshRadius = 0.0;
    for (const glm::vec3& p : scene.meshes[sphere->mesh].positions)
        meshRadius = std::max(meshRadius, double(glm::length(p)));
    glm::dvec3 centre = glm::dvec3(sphere->model * glm::vec4(0, 0, 0, 1));
    double radius = meshRadius * sphere->scale;
    glm::dvec3 toLight = -glm::normalize(glm::dvec3(scene.lights[0].direction));

    // Tolerance band around the ellipse's edge, in world units perpendicular to the light:
    //  - the shadow map's texel (plus PCF half-width, and one texel for bilinear hardware compare);
    //  - the screen pixel's footprint on the ground (the pixel centre decides, the edge may cross it);
    //  - the polygonal sphere's silhouette error r(1 - cos(pi/64)).
    glm::mat4 lightVP = fitLightViewProjection(scene, scene.lights[0]);
    // Orthographic light: row i of proj*view is (2 / extent_i) times a unit axis, so the extent of the
    // map in world units is 2 / |row|.
    auto rowLength = [&](int r) {
        return glm::length(glm::vec3(lightVP[0][r], lightVP[1][r], lightVP[2][r]));
    };
    double orthoWidth = 2.0 / std::min(rowLength(0), rowLength(1));
    int res = int(sm.properties().getInt("resolution"));
    int pcf = int(sm.properties().getInt("pcf"));
    double texel = orthoWidth / res;
    double band = texel * (1.5 + 0.5 * pcf) + radius * (1.0 - std::cos(M_PI / 64.0));

    auto depth = h.targets().readDepth();
    auto vis = h.targets().readVisibilityRGBA32F();
    glm::mat4 viewProj = cameraProjection(h.camera(), 1.0f) * cameraView(h.camera());
    auto world = test::unprojectDepth(depth, kSize, kSize, viewProj);

    int ground = 0, shadowedExpected = 0, shadowedGot = 0, judged = 0, wrong = 0;
    for (int y = 1; y < kSize - 1; ++y)
        for (int x = 1; x < kSize - 1; ++x) {
            size_t i = size_t(y) * kSize + size_t(x);
            if (world[i].w == 0.0f || std::abs(world[i].y) > 1e-2f) continue; // ground pixels only
            ++ground;
            double footprint = glm::length(glm::vec3(world[i + 1]) - glm::vec3(world[i]));
            double margin = shadowMargin(glm::dvec3(world[i]), toLight, centre, radius);
            bool expectShadow = margin < 0.0;
            bool gotShadow = vis[i * 4] < 0.5f;
            shadowedExpected += expectShadow;
            shadowedGot += gotShadow;
            if (std::abs(margin) <= band + footprint) continue; // the edge band: either answer is right
            ++judged;
            if (expectShadow != gotShadow) {
                ++wrong;
                if (wrong <= 5)
                    ADD_FAILURE() << "pixel (" << x << "," << y << ") world " << world[i].x << ","
                                  << world[i].z << " margin " << margin << " expected "
                                  << (expectShadow ? "shadow" : "lit") << " got visibility " << vis[i * 4];
            }
        }
    // The ellipse must be substantially in view, or the test proves nothing.
    EXPECT_GT(ground, kSize * kSize / 4);
    EXPECT_GT(shadowedExpected, 500) << "the analytic shadow hardly covers any pixel";
    EXPECT_GT(judged, ground * 9 / 10) << "the tolerance band swallowed the image";
    EXPECT_EQ(wrong, 0) << "pixels outside the edge band classified wrongly (band " << band
                        << " world units)";
    // Shadow area agrees with the ellipse's within the band's share of pixels.
    EXPECT_NEAR(double(shadowedGot), double(shadowedExpected), 0.05 * shadowedExpected + 50);
}

INSTANTIATE_TEST_SUITE_P(ShadowMap, SphereShadow, ::testing::ValuesIn(kCases),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(NoneTechnique, VisibilityIsOneEverywhere) {
    Harness h(test::quickConfig("sphere_plane", "top", 128));
    NoneTechnique none;
    h.prepare(none);
    h.renderFrame(none);
    auto vis = h.targets().readVisibilityRGBA32F();
    size_t notOne = 0;
    for (float v : vis) notOne += v != 1.0f; // exact: the shader writes the constant 1.0
    EXPECT_EQ(notOne, 0u);
    // The colour must show lit geometry (not just the clear colour), or the pass drew nothing.
    auto depth = h.targets().readDepth();
    EXPECT_GT(std::count_if(depth.begin(), depth.end(), [](float d) { return d < 1.0f; }), 128 * 128 / 4);
}

TEST(ShadowMapTechnique, PointLightIsRefusedAsUnsupported) {
    RunConfig cfg = test::quickConfig("sphere_plane", "top", 64);
    cfg.sceneOptions.lightType = LightType::Point;
    Harness h(cfg);
    ShadowMapTechnique sm;
    try {
        h.prepare(sm);
        FAIL() << "point light accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Unsupported);
        EXPECT_NE(std::string(e.what()).find("point light"), std::string::npos) << e.what();
    }
}

TEST(ShadowMapTechnique, SpotLightShadowsTheGroundUnderTheSphere) {
    // Spot straight above the sphere: the point on the ground below the centre is shadowed, a point
    // far outside the sphere's projection but inside the cone is lit.
    RunConfig cfg = test::quickConfig("sphere_plane", "top", 256);
    cfg.sceneOptions.lightType = LightType::Spot;
    Harness h(cfg);
    ShadowMapTechnique sm;
    h.prepare(sm);
    h.renderFrame(sm);
    const Scene& scene = h.scene();
    const Light& light = scene.lights[0];
    ASSERT_EQ(light.type, LightType::Spot);
    auto depth = h.targets().readDepth();
    auto vis = h.targets().readVisibilityRGBA32F();
    glm::mat4 viewProj = cameraProjection(h.camera(), 1.0f) * cameraView(h.camera());
    auto world = test::unprojectDepth(depth, 256, 256, viewProj);
    const Instance* sphere = nullptr;
    for (const Instance& i : scene.instances)
        if (i.castsShadow) sphere = &i;
    ASSERT_NE(sphere, nullptr);
    glm::vec3 c = glm::vec3(sphere->model * glm::vec4(0, 0, 0, 1));
    double r = sphere->scale;
    for (const glm::vec3& p : scene.meshes[sphere->mesh].positions)
        r = std::max(r, double(glm::length(p) * sphere->scale));
    int checked = 0, wrong = 0;
    for (size_t i = 0; i < world.size(); ++i) {
        if (world[i].w == 0.0f || std::abs(world[i].y) > 1e-2f) continue;
        glm::dvec3 p(world[i]);
        glm::dvec3 toL = glm::normalize(glm::dvec3(light.position) - p);
        // outside the cone: the light term is zero anyway; skip
        if (glm::dot(-toL, glm::normalize(glm::dvec3(light.direction))) <
            std::cos(glm::radians(light.spotOuterDeg)) + 0.02)
            continue;
        glm::dvec3 pc = glm::dvec3(c) - p;
        double t = glm::dot(pc, toL);
        double margin = glm::length(pc - t * toL) - r;
        if (std::abs(margin) < 0.1 * r) continue; // edge band: perspective texels grow with distance
        ++checked;
        wrong += (margin < 0.0) != (vis[i * 4] < 0.5f);
    }
    EXPECT_GT(checked, 1000);
    EXPECT_EQ(wrong, 0);
}

} // namespace
