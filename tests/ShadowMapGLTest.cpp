// `shadowmap` against closed forms: the sphere's shadow on the plane is an exact ellipse
// (tests/SphereShadowJudge.h, which tests/ShadowMapVkTest.cpp runs on Vulkan as well).
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "NonReceiverScene.h"
#include "RenderedFrame.h"
#include "SphereShadowJudge.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "core/Error.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/LightFit.h"
#include "scenes/Math.h"
#include "techniques/none/NoneGL.h"
#include "techniques/shadowmap/ShadowMapGL.h"

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

TEST_P(SphereShadow, MatchesAnalyticEllipse) {
    const SphereShadowCase& tc = GetParam();
    constexpr int kSize = 384;
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize, tc.submit);
    cfg.sceneOptions.tessellation = 64; // polygonal silhouette within r(1 - cos(pi/64)) = 1.2e-3 r
    cfg.sceneOptions.lightType = LightType::Directional;
    Harness h(cfg);
    ShadowMapGL sm;
    TechniqueSpec spec =
        TechniqueSpec::parse(std::string("shadowmap") + (*tc.techniqueProps ? ":" : "") + tc.techniqueProps);
    sm.properties().apply(spec.properties);
    h.prepare(sm);
    h.renderFrame(sm);
    glm::mat4 viewProj = cameraProjection(h.camera(), 1.0f) * cameraView(h.camera());
    test::judgeSphereShadow(h.scene(), test::shadowMapBand(h.scene(), sm.properties()),
                            h.targets().readDepth(), h.targets().readVisibilityRGBA32F(), viewProj, kSize);
}

INSTANTIATE_TEST_SUITE_P(ShadowMap, SphereShadow, ::testing::ValuesIn(kCases),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(NoneGL, VisibilityIsOneEverywhere) {
    Harness h(test::quickConfig("sphere_plane", "top", 128));
    NoneGL none;
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

TEST(ShadowMapGL, PointLightIsRefusedAsUnsupported) {
    RunConfig cfg = test::quickConfig("sphere_plane", "top", 64);
    cfg.sceneOptions.lightType = LightType::Point;
    Harness h(cfg);
    ShadowMapGL sm;
    try {
        h.prepare(sm);
        FAIL() << "point light accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Unsupported);
        EXPECT_NE(std::string(e.what()).find("point light"), std::string::npos) << e.what();
    }
}

TEST(ShadowMapGL, SpotLightShadowsTheGroundUnderTheSphere) {
    // Spot straight above the sphere: the point on the ground below the centre is shadowed, a point
    // far outside the sphere's projection but inside the cone is lit.
    RunConfig cfg = test::quickConfig("sphere_plane", "top", 256);
    cfg.sceneOptions.lightType = LightType::Spot;
    Harness h(cfg);
    ShadowMapGL sm;
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

/// How many samplers the program that drew the frame's last draw reads: a sampler is an active uniform
/// only where the compiled code reads it, so a program without the lookup has none.
int lastProgramSamplers() {
    GLint program = 0, uniforms = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);
    EXPECT_NE(program, 0);
    glGetProgramiv(GLuint(program), GL_ACTIVE_UNIFORMS, &uniforms);
    int samplers = 0;
    for (GLint u = 0; u < uniforms; ++u) {
        GLint size = 0;
        GLenum type = 0;
        char name[128];
        glGetActiveUniform(GLuint(program), GLuint(u), sizeof name, nullptr, &size, &type, name);
        const bool sampler = (type >= GL_SAMPLER_1D && type <= GL_SAMPLER_2D_SHADOW) ||
                             (type >= GL_SAMPLER_1D_ARRAY && type <= GL_SAMPLER_CUBE_SHADOW) ||
                             (type >= GL_INT_SAMPLER_1D && type <= GL_UNSIGNED_INT_SAMPLER_2D_ARRAY) ||
                             type == GL_SAMPLER_CUBE_MAP_ARRAY || type == GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW;
        samplers += sampler;
    }
    return samplers;
}

// Every member of the family whose lighting pass looks its map up per fragment draws the non-receivers
// apart (techniques/ReceiverSplit.h, techniques/gl/LitPrograms.h).
TEST(ShadowMapGL, NonReceiversDrawnLastSkipTheLookupWithTheSameImage) {
    for (const char* spec : test::kNonReceiverSplitSpecs) {
        // shadowmap in every mode; the others where the draw order differs (scene order, mesh by mesh).
        const bool all = std::string(spec) == "shadowmap";
        for (SubmitMode mode : kAllSubmitModes) {
            if (!all && mode != SubmitMode::Retained && mode != SubmitMode::Instanced) continue;
            SCOPED_TRACE(std::string(spec) + " " + submitModeName(mode));
            Harness apart(test::quickConfig(test::nonReceiverScene(true), "view", 128, mode));
            std::unique_ptr<GlTechnique> split = TechniqueRegistry::create(TechniqueSpec::parse(spec));
            const test::RenderedFrame f = test::renderOnce(apart, *split);
            // The exact measure of the saving: the non-receivers' program reads no texture.
            EXPECT_EQ(lastProgramSamplers(), 0) << f.permutation;
            EXPECT_NE(f.permutation.find("SB_NON_RECEIVER_DRAWS"), std::string::npos) << f.permutation;

            Harness together(test::quickConfig(test::nonReceiverScene(false), "view", 128, mode));
            std::unique_ptr<GlTechnique> one = TechniqueRegistry::create(TechniqueSpec::parse(spec));
            const test::RenderedFrame control = test::renderOnce(together, *one);
            EXPECT_GT(lastProgramSamplers(), 0) << "the control's one program looks the map up";
            EXPECT_EQ(control.permutation.find("SB_NON_RECEIVER_DRAWS"), std::string::npos);

            // The same image, bit for bit: the same draws in the same order, the same arithmetic per pixel.
            EXPECT_TRUE(f.colour == control.colour);
            EXPECT_TRUE(f.visibility == control.visibility);
            // Not vacuous: the floor is shadowed somewhere, the ball (y > 1.3 on its upper half) nowhere.
            size_t floorShadowed = 0, ball = 0, ballShadowed = 0;
            for (size_t i = 0; i < f.world.size(); ++i) {
                if (f.world[i].w == 0.0f) continue;
                const float v = f.visibility[4 * i];
                if (std::abs(f.world[i].y) < 1e-3f) floorShadowed += v < 0.5f;
                if (f.world[i].y > 1.3f) ++ball, ballShadowed += v != 1.0f;
            }
            EXPECT_GT(floorShadowed, 100u);
            EXPECT_GT(ball, 100u);
            EXPECT_EQ(ballShadowed, 0u);
        }
    }
}

} // namespace
