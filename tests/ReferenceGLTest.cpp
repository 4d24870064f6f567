// `reference` against closed forms on sphere_plane seen from the top camera. Hard: under a directional
// point light the shadow of the sphere is an exact ellipse (a ground point p is shadowed iff the ray
// from p towards the light passes within r of the centre); the reference must match it everywhere but
// in an edge band as wide as the tessellated sphere's deviation from the true one plus one pixel.
// Soft: under a directional disk light (angular radius a) the ray bundle from p spreads by
// |c - p| sin(a) at the sphere, so p is fully lit or fully shadowed outside that band and partly lit
// inside it.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "reference/ReferenceGL.h"
#include "scenes/Math.h"

using namespace sb;

namespace {

/// The sphere instance of sphere_plane, its centre, its true radius (vertices lie on it) and the
/// radius of the largest ball inside the tessellated sphere (the smallest face-plane distance).
struct SphereGeometry {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
    double inscribed = 0.0;
};

SphereGeometry sphereOf(const Scene& scene) {
    SphereGeometry s;
    for (const Instance& inst : scene.instances) {
        if (!inst.castsShadow) continue;
        const Mesh& mesh = scene.meshes[inst.mesh];
        s.centre = glm::dvec3(inst.model * glm::vec4(0, 0, 0, 1));
        s.inscribed = 1e9;
        for (const glm::vec3& p : mesh.positions) s.radius = std::max(s.radius, double(glm::length(p)));
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]), b(mesh.positions[mesh.indices[3 * t + 1]]),
                c(mesh.positions[mesh.indices[3 * t + 2]]);
            glm::dvec3 n = glm::cross(b - a, c - a);
            if (glm::length(n) < 1e-12) continue;
            s.inscribed = std::min(s.inscribed, std::abs(glm::dot(glm::normalize(n), a)));
        }
        s.radius *= inst.scale;
        s.inscribed *= inst.scale;
    }
    return s;
}

/// Distance from the sphere centre to the ray from p towards the light, minus the radius: negative
/// inside the shadow, positive outside, in world units perpendicular to the light.
double shadowMargin(const glm::dvec3& p, const glm::dvec3& toLight, const SphereGeometry& s) {
    glm::dvec3 pc = s.centre - p;
    double t = glm::dot(pc, toLight);
    if (t <= 0.0) return 1e9;
    return glm::length(pc - t * toLight) - s.radius;
}

struct Frame {
    std::vector<glm::vec4> world; ///< depth-unprojected, w = 0 off geometry
    std::vector<float> visibility;
};

Frame renderReference(Harness& h, ReferenceGL& ref) {
    h.prepare(ref);
    h.renderFrame(ref);
    Frame f;
    const int w = h.targets().width(), hh = h.targets().height();
    glm::mat4 viewProj = cameraProjection(h.camera(), float(w) / float(hh)) * cameraView(h.camera());
    f.world = test::unprojectDepth(h.targets().readDepth(), w, hh, viewProj);
    f.visibility = h.targets().readVisibilityRGBA32F();
    return f;
}

class HardShadow : public ::testing::TestWithParam<SubmitMode> {};

TEST_P(HardShadow, MatchesAnalyticEllipse) {
    constexpr int kSize = 384;
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize, GetParam());
    cfg.sceneOptions.tessellation = 64;
    Harness h(cfg);
    ReferenceGL ref;
    Frame f = renderReference(h, ref);
    const Scene& scene = h.scene();
    SphereGeometry sphere = sphereOf(scene);
    ASSERT_GT(sphere.radius, 0.0);
    glm::dvec3 toLight = -glm::normalize(glm::dvec3(scene.lights[0].direction));
    // The tessellated sphere lies between the inscribed ball and the true one (r - r_in = 1.2e-3 r at
    // 64 rings): its shadow edge lies between theirs. The pixel footprint covers the distance between
    // the depth-unprojected position and the G-buffer sample the reference traced (< 3e-4).
    const double tessellationError = sphere.radius - sphere.inscribed;

    int ground = 0, shadowedExpected = 0, judged = 0, wrong = 0, notBinary = 0;
    for (int y = 1; y < kSize - 1; ++y)
        for (int x = 1; x < kSize - 1; ++x) {
            size_t i = size_t(y) * kSize + size_t(x);
            float v = f.visibility[i * 4];
            notBinary += v != 0.0f && v != 1.0f;
            if (f.world[i].w == 0.0f || std::abs(f.world[i].y) > 1e-2f) continue;
            ++ground;
            double footprint = glm::length(glm::vec3(f.world[i + 1]) - glm::vec3(f.world[i]));
            double margin = shadowMargin(glm::dvec3(f.world[i]), toLight, sphere);
            bool expectShadow = margin < 0.0;
            shadowedExpected += expectShadow;
            if (std::abs(margin) <= tessellationError + footprint) continue;
            ++judged;
            if (expectShadow != (v < 0.5f) && ++wrong <= 5)
                ADD_FAILURE() << "pixel (" << x << "," << y << ") margin " << margin << " visibility " << v;
        }
    EXPECT_GT(ground, kSize * kSize / 4);
    EXPECT_GT(shadowedExpected, 500);
    EXPECT_GT(judged, ground * 98 / 100) << "the edge band must be a thin line";
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(notBinary, 0) << "a point light casts only 0 or 1";

    Counters c = ref.counters();
    EXPECT_GT(test::counter(c, "rays"), 0.0);
    EXPECT_GT(test::counter(c, "rays_per_second_per_thread"), 0.0);
    EXPECT_EQ(test::counter(c, "samples_per_pixel"), 1.0);
    EXPECT_EQ(test::counter(c, "noise_bound"), 0.0);
    // Both passes draw the whole scene, in every submission mode (the G-buffer's own draws included).
    EXPECT_EQ(test::counter(c, "triangles"), 2.0 * double(scene.totalTriangles()));
    ASSERT_EQ(ref.lastVisibility().size(), 1u);
    EXPECT_EQ(ref.lastGBuffer().width, kSize);
    EXPECT_EQ(ref.lastVisibility()[0].value.size(), size_t(kSize) * kSize);
}

INSTANTIATE_TEST_SUITE_P(Reference, HardShadow,
                         ::testing::Values(SubmitMode::Retained, SubmitMode::Immediate,
                                           SubmitMode::Instanced),
                         [](const auto& p) { return std::string(submitModeName(p.param)); });

/// sphere_plane with its directional light turned into a sun disk of `angularRadiusDeg`, as a file.
std::string softScenePath(double angularRadiusDeg) {
    std::string text = test::readFile(std::string(SB_SOURCE_DIR) + "/scenes/data/sphere_plane.json");
    const std::string light = R"("intensity": 1.0})";
    size_t at = text.find(light);
    EXPECT_NE(at, std::string::npos) << "sphere_plane.json changed: update this test";
    text.replace(at, light.size(),
                 R"("intensity": 1.0, "shape": "disk", "angular_radius_deg": )" +
                     std::to_string(angularRadiusDeg) + "}");
    std::string path = test::freshDir("reference-soft") + "/sphere_plane_sun.json";
    std::ofstream(path) << text;
    return path;
}

TEST(ReferenceGL, SoftShadowOfASunDisk) {
    constexpr int kSize = 192;
    constexpr double kAngularRadiusDeg = 5.0;
    RunConfig cfg = test::quickConfig(softScenePath(kAngularRadiusDeg), "top", kSize);
    cfg.sceneOptions.tessellation = 64;
    Harness h(cfg);
    ASSERT_TRUE(h.scene().lights[0].isArea());
    ReferenceGL ref;
    Frame f = renderReference(h, ref);
    SphereGeometry sphere = sphereOf(h.scene());
    glm::dvec3 toLight = -glm::normalize(glm::dvec3(h.scene().lights[0].direction));
    const double sinA = std::sin(kAngularRadiusDeg * M_PI / 180.0);

    int penumbra = 0, umbra = 0, lit = 0, wrong = 0;
    for (int y = 1; y < kSize - 1; ++y)
        for (int x = 1; x < kSize - 1; ++x) {
            size_t i = size_t(y) * kSize + size_t(x);
            if (f.world[i].w == 0.0f || std::abs(f.world[i].y) > 1e-2f) continue;
            glm::dvec3 p(f.world[i]);
            float v = f.visibility[i * 4];
            penumbra += v > 0.0f && v < 1.0f;
            // Every ray of the bundle passes the centre within margin +- |c - p| sin(a).
            double spread = glm::length(sphere.centre - p) * sinA;
            double band = (sphere.radius - sphere.inscribed) +
                          glm::length(glm::vec3(f.world[i + 1]) - glm::vec3(f.world[i]));
            double margin = shadowMargin(p, toLight, sphere);
            if (margin > spread + band) {
                ++lit;
                if (v != 1.0f && ++wrong <= 5) ADD_FAILURE() << "lit pixel (" << x << "," << y << "): " << v;
            } else if (margin < -spread - band) {
                ++umbra;
                if (v != 0.0f && ++wrong <= 5)
                    ADD_FAILURE() << "umbra pixel (" << x << "," << y << "): " << v;
            }
        }
    EXPECT_GT(penumbra, 100) << "no partly lit pixels";
    EXPECT_GT(umbra, 100);
    EXPECT_GT(lit, kSize * kSize / 2);
    EXPECT_EQ(wrong, 0);

    // The umbra's centre (the sphere centre projected along the light onto y = 0) is 0; far ground is 1.
    auto visibilityAt = [&](const glm::dvec3& world) {
        glm::mat4 viewProj = cameraProjection(h.camera(), 1.0f) * cameraView(h.camera());
        glm::vec4 clip = viewProj * glm::vec4(glm::vec3(world), 1.0f);
        int px = int((clip.x / clip.w * 0.5f + 0.5f) * kSize),
            py = int((clip.y / clip.w * 0.5f + 0.5f) * kSize);
        return f.visibility[(size_t(py) * kSize + size_t(px)) * 4];
    };
    glm::dvec3 shadowCentre = sphere.centre + toLight * (-sphere.centre.y / toLight.y);
    EXPECT_EQ(visibilityAt(shadowCentre), 0.0f);
    EXPECT_EQ(visibilityAt({-4.0, 0.0, -4.0}), 1.0f);

    Counters c = ref.counters();
    EXPECT_GT(test::counter(c, "rays"), double(lit));
    EXPECT_GE(test::counter(c, "samples_per_pixel"), 64.0);
    EXPECT_GT(test::counter(c, "noise_bound"), 0.0);
}

TEST(ReferenceGL, HardPropertyTreatsAreaLightsAsPoints) {
    constexpr int kSize = 96;
    Harness h(test::quickConfig(softScenePath(5.0), "top", kSize));
    ReferenceGL ref;
    ref.properties().apply(TechniqueSpec::parse("reference:hard=true:samples=16").properties);
    Frame f = renderReference(h, ref);
    int shadowed = 0, fractional = 0;
    for (size_t i = 0; i < f.world.size(); ++i) {
        float v = f.visibility[i * 4];
        shadowed += v == 0.0f;
        fractional += v != 0.0f && v != 1.0f;
    }
    EXPECT_GT(shadowed, 0);
    EXPECT_EQ(fractional, 0);
    EXPECT_EQ(test::counter(ref.counters(), "samples_per_pixel"), 1.0);
}

} // namespace
