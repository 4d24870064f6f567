// `projective` against closed forms. A ball of radius R at (0, H, 0) over a floor that casts nothing:
// under a directional light a floor point p is in the ball's shadow iff the ray from p towards the
// light passes within R of the centre (the shadow is the exact ellipse, and projective texturing has
// no depth, so nothing else matters). Every floor pixel is judged at the world position unprojected
// from the depth buffer. Tolerance: an edge band of
//   1.5 projective texels: the silhouette is rasterised at texel centres (up to half a texel diagonal,
//       0.71 texel, of edge displacement) and read back bilinearly, whose 0.5 crossing moves the edge
//       by up to another half texel;
// + the screen pixel's footprint on the floor (the pixel centre decides, the edge may cross the pixel);
// + 2 R (1 - cos(pi / tessellation)): the polygonal ball's silhouette lies inside the sphere's.
// Off the band there must be no mismatch at all.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "scenes/Math.h"
#include "techniques/projective/ProjectiveGL.h"

using namespace sb;

namespace {

constexpr int kSize = 160;
constexpr int kTessellation = 48;
constexpr double kRadius = 0.5, kHeight = 1.2;
const glm::dvec3 kCentre(0.0, kHeight, 0.0);

/// Floor [-3, 3]^2 at y = 0 (casts nothing) and a ball at (0, kHeight, 0), seen from above.
/// `instances` adds further instances (a JSON fragment starting with a comma), `lights` is an array.
std::string writeScene(const std::string& dir, const std::string& lights, const std::string& instances = "") {
    const std::string path = dir + "/scene.json";
    test::writeFile(path, R"({"name": "ball_floor",
  "meshes": [{"name": "ball", "generator": "sphere", "radius": 0.5, "tessellation": )" +
                              std::to_string(kTessellation) + R"(},
             {"name": "floor", "generator": "plane", "size": 6, "tessellation": 1}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false, "color": [0.5, 0.5, 0.5]},
                {"mesh": "ball", "position": [0, 1.2, 0], "color": [0.9, 0.2, 0.1]})" +
                              instances + R"(],
  "lights": )" + lights + R"(,
  "cameras": [{"name": "top", "eye": [0, 5, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
               "near": 0.5, "far": 50}]})");
    return path;
}

struct Frame {
    std::vector<float> visibility; ///< 4 per pixel
    std::vector<glm::vec4> world;  ///< w = 0: background
    Counters counters;
    std::vector<glm::mat4> projectors; ///< per light: computeProjector's viewProj
    int resolution = 0, blur = 0;
};

Frame render(const std::string& scene, const std::string& props) {
    Harness h(test::quickConfig(scene, "top", kSize));
    ProjectiveGL t;
    t.properties().apply(TechniqueSpec::parse("projective" + (props.empty() ? "" : ":" + props)).properties);
    test::RenderedFrame r = test::renderOnce(h, t);
    Frame f;
    f.visibility = std::move(r.visibility);
    f.world = std::move(r.world);
    f.counters = std::move(r.counters);
    for (const Light& l : h.scene().lights)
        f.projectors.push_back(ProjectiveGL::computeProjector(h.scene(), l).viewProj);
    f.resolution = int(t.properties().getInt("resolution"));
    f.blur = int(t.properties().getInt("blur"));
    return f;
}

bool isFloor(const glm::vec4& w) {
    return w.w != 0.0f && std::abs(w.y) < 1e-3f;
}

/// Distance from the ball's centre to the ray from p towards the light, minus R: negative inside the
/// shadow, in world units perpendicular to the light.
double shadowMargin(const glm::dvec3& p, const glm::dvec3& toLight) {
    const glm::dvec3 pc = kCentre - p;
    const double t = glm::dot(pc, toLight);
    if (t <= 0.0) return 1e9;
    return glm::length(pc - t * toLight) - kRadius;
}

/// World size of one texel of an orthographic projector: row i of proj * view is (2 / extent_i) times
/// a unit axis.
double orthoTexel(const glm::mat4& viewProj, int resolution) {
    auto row = [&](int r) { return glm::length(glm::vec3(viewProj[0][r], viewProj[1][r], viewProj[2][r])); };
    return 2.0 / std::min(row(0), row(1)) / resolution;
}

double tessellationError() {
    return 2.0 * kRadius * (1.0 - std::cos(M_PI / kTessellation));
}

struct Judgement {
    int floor = 0, judged = 0, wrong = 0, expectedShadow = 0;
};

/// Channel `light` against the ellipse of a directional light travelling along `travel`.
Judgement judge(const Frame& f, int light, const glm::dvec3& travel) {
    const glm::dvec3 toLight = -glm::normalize(travel);
    const double band = 1.5 * orthoTexel(f.projectors[size_t(light)], f.resolution) + tessellationError();
    Judgement j;
    for (int y = 1; y < kSize - 1; ++y)
        for (int x = 1; x < kSize - 1; ++x) {
            const size_t i = size_t(y) * kSize + size_t(x);
            if (!isFloor(f.world[i]) || !isFloor(f.world[i + 1])) continue;
            ++j.floor;
            const double footprint = glm::length(glm::vec3(f.world[i + 1]) - glm::vec3(f.world[i]));
            const double margin = shadowMargin(glm::dvec3(f.world[i]), toLight);
            j.expectedShadow += margin < 0.0;
            if (std::abs(margin) <= band + footprint) continue;
            ++j.judged;
            const float v = f.visibility[i * 4 + size_t(light)];
            // Off the band the bilinear lookup reads only black or only white texels: 0 or 1 exactly.
            const bool ok = margin < 0.0 ? v == 0.0f : v == 1.0f;
            if (!ok && ++j.wrong <= 5)
                ADD_FAILURE() << "light " << light << " pixel (" << x << "," << y << ") world "
                              << f.world[i].x << "," << f.world[i].z << " margin " << margin
                              << " got visibility " << v;
        }
    return j;
}

const glm::dvec3 kTravelA(0.8, -1.0, 0.2);
const glm::dvec3 kTravelB(-0.7, -1.0, -0.5);
std::string directional(const glm::dvec3& d) {
    return "{\"type\": \"directional\", \"direction\": [" + std::to_string(d.x) + ", " + std::to_string(d.y) +
           ", " + std::to_string(d.z) + "]}";
}

class ProjectiveEllipse : public ::testing::TestWithParam<const char*> {};

// 1. The floor's visibility is the exact shadow ellipse off the edge band, at the default resolution
// and at a coarse one where the texel term dominates the band.
TEST_P(ProjectiveEllipse, DirectionalShadowMatchesTheClosedForm) {
    const std::string scene = writeScene(test::freshTestDir("projective"), "[" + directional(kTravelA) + "]");
    const Frame f = render(scene, GetParam());
    const Judgement j = judge(f, 0, kTravelA);
    EXPECT_GT(j.floor, kSize * kSize / 2);
    EXPECT_GT(j.expectedShadow, 500) << "the analytic shadow hardly covers any pixel";
    EXPECT_GT(j.judged, j.floor * 9 / 10) << "the tolerance band swallowed the image";
    EXPECT_EQ(j.wrong, 0);
    EXPECT_EQ(test::counter(f.counters, "projective_texels"), double(f.resolution) * f.resolution);
    EXPECT_EQ(test::counter(f.counters, "blur_passes"), 0.0);
    EXPECT_EQ(test::counter(f.counters, "projector_clamped"), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Projective, ProjectiveEllipse, ::testing::Values("", "resolution=64"),
                         [](const auto& p) { return std::string(*p.param ? "res64" : "default"); });

// 2. No self-shadowing: every pixel of the ball, its side away from the light included, is lit in
// every channel (the shader writes the constant 1.0: exact).
TEST(ProjectiveGLTest, CastersAreNeverShadowed) {
    const std::string scene = writeScene(test::freshTestDir("projective"), "[" + directional(kTravelA) + "]");
    const Frame f = render(scene, "");
    int ball = 0, notOne = 0;
    for (size_t i = 0; i < f.world.size(); ++i) {
        if (f.world[i].w == 0.0f || f.world[i].y < 0.05f) continue;
        ++ball;
        for (int c = 0; c < 4; ++c) notOne += f.visibility[i * 4 + size_t(c)] != 1.0f;
    }
    EXPECT_GT(ball, 500);
    EXPECT_EQ(notOne, 0);
}

// 3. q > 0: a point light at height 2 below the ball at height 4 looks up at it; the floor lies behind
// the projector, where a lookup without the q test reads the mirrored silhouette (a disc of radius
// ~0.5 under the light). With the test the floor is lit everywhere (exact: the shader returns 1.0).
TEST(ProjectiveGLTest, NothingIsProjectedBehindAPointLight) {
    const std::string dir = test::freshTestDir("projective");
    const std::string path = dir + "/scene.json";
    test::writeFile(path, R"({"name": "ball_above_light",
  "meshes": [{"name": "ball", "generator": "sphere", "radius": 0.5, "tessellation": 24},
             {"name": "floor", "generator": "plane", "size": 6, "tessellation": 1}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false},
                {"mesh": "ball", "position": [0.3, 4, 0.2]}],
  "lights": [{"type": "point", "position": [0, 2, 0]}],
  "cameras": [{"name": "top", "eye": [0, 8, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
               "near": 0.5, "far": 50}]})");
    const Frame f = render(path, "");
    int floor = 0, notLit = 0;
    for (size_t i = 0; i < f.world.size(); ++i) {
        if (!isFloor(f.world[i])) continue;
        ++floor;
        notLit += f.visibility[i * 4] != 1.0f;
    }
    EXPECT_GT(floor, kSize * kSize / 4);
    EXPECT_EQ(notLit, 0) << "the silhouette was back-projected behind the projector";
    EXPECT_EQ(test::counter(f.counters, "projector_clamped"), 0.0);
    // The projector does look at the ball: its centre projects to the texture's centre, in front.
    const glm::vec4 c = f.projectors[0] * glm::vec4(0.3f, 4.0f, 0.2f, 1.0f);
    EXPECT_GT(c.w, 0.0f);
    EXPECT_NEAR(c.x / c.w, 0.0, 1e-4);
    EXPECT_NEAR(c.y / c.w, 0.0, 1e-4);
}

// 4. Blur: a band of fractional visibility around the edge that widens with the radius, 0 and 1 far
// inside and outside. At 96 texels the texel is ~1/96 of the ball's shadow width, so 8 texels span
// several screen pixels. "Far": beyond the edge band plus the kernel's reach (radius texels per axis,
// radius * sqrt(2) diagonally); R8 storage rounds a sum of normalised weights of 1 back to exactly 1.
TEST(ProjectiveGLTest, BlurWidensTheEdgeAndKeepsTheInterior) {
    const std::string scene = writeScene(test::freshTestDir("projective"), "[" + directional(kTravelA) + "]");
    const glm::dvec3 toLight = -glm::normalize(kTravelA);
    int previous = -1;
    for (int blur : {0, 2, 8}) {
        const Frame f = render(scene, "resolution=96:blur=" + std::to_string(blur));
        const double texel = orthoTexel(f.projectors[0], f.resolution);
        const double reach = (1.5 + std::sqrt(2.0) * blur) * texel + tessellationError();
        int fractional = 0, farInside = 0, farOutside = 0, wrong = 0;
        for (int y = 1; y < kSize - 1; ++y)
            for (int x = 1; x < kSize - 1; ++x) {
                const size_t i = size_t(y) * kSize + size_t(x);
                if (!isFloor(f.world[i]) || !isFloor(f.world[i + 1])) continue;
                const float v = f.visibility[i * 4];
                fractional += v > 0.05f && v < 0.95f;
                const double footprint = glm::length(glm::vec3(f.world[i + 1]) - glm::vec3(f.world[i]));
                const double margin = shadowMargin(glm::dvec3(f.world[i]), toLight);
                if (margin < -(reach + footprint)) {
                    ++farInside;
                    wrong += v > 0.01f;
                } else if (margin > reach + footprint) {
                    ++farOutside;
                    wrong += v < 0.99f;
                }
            }
        SCOPED_TRACE("blur " + std::to_string(blur));
        EXPECT_GT(fractional, previous) << "the fractional band did not widen";
        EXPECT_GT(farInside, 100);
        EXPECT_GT(farOutside, 1000);
        EXPECT_EQ(wrong, 0);
        EXPECT_EQ(test::counter(f.counters, "blur_passes"), blur > 0 ? 2.0 : 0.0);
        previous = fractional;
    }
}

// 5. A point light inside the casters' bounds must still cast the shadows the exact reference has,
// and stay finite. The projector cannot enclose casters all around the light, so it looks from the
// light at the receivers (what can shadow them lies in between). Judged against Embree at the same
// pixels (bench accuracy's evaluator), off the 1-px band around the reference's edges:
//  - overlap: of the reference's shadowed samples, the share the technique also shadows, at least
//    0.97 (measured 1.0 in all three cases: every visible floor point lies inside the frustum; 3% is
//    room for the silhouette's staircase, a 512^2 texel spread over up to 80 degrees covering more
//    than a pixel);
//  - false shadow: at most 1% of the judged samples (measured 10 of 24845, 0.04%, with the pillars:
//    the texel staircase just off the band; 0 inside the ball).
// Before, the projector looked from the light at the bounds' centre (above it, or sideways) through
// an 80-degree frustum: overlap 0 with the pillars (the floor lay behind the projector), 0.48 inside
// the ball off its centre.
struct InsideCase {
    const char* name;
    const char* casters;    ///< instances besides the floor
    const char* light;      ///< position
    double clamped;         ///< the projector_clamped counter, by hand
    const char* clampedWhy; ///< how that number was worked out
};

const InsideCase kInsideCases[] = {
    {"pillars_straddle_the_light",
     R"({"mesh": "pillar", "position": [-1.2, 2, 0.3]}, {"mesh": "pillar", "position": [1.0, 2, -0.9]},
        {"mesh": "ball", "position": [0.6, 0.5, 0.9]})",
     "[0, 1.2, 0]", 0.0,
     "the casters' bounds reach y = 4 over the light at 1.2; straight down from it, the floor's corners "
     "lie atan(3 sqrt 2 / 1.2) = 74.2 degrees off the axis, 75.2 padded: not clamped"},
    {"inside_a_ball_off_centre", R"({"mesh": "ball", "position": [0, 1.2, 0]})", "[0.2, 1.2, 0.1]", 1.0,
     "the axis points from the light to the floor's centre; the floor corner (3, 0, 3) is 83.4 degrees "
     "off it: clamped to 80"},
    {"inside_a_ball_at_its_centre", R"({"mesh": "ball", "position": [0, 1.2, 0]})", "[0, 1.2, 0]", 0.0,
     "straight down over the floor's centre, corners 74.2 degrees off the axis: 75.2 padded, not clamped"},
};

void PrintTo(const InsideCase& c, std::ostream* os) {
    *os << c.name;
}

class ProjectiveInside : public ::testing::TestWithParam<InsideCase> {};

TEST_P(ProjectiveInside, ShadowsWhereTheReferenceDoesAndStaysFinite) {
    const InsideCase& c = GetParam();
    const std::string path = test::freshTestDir("projective") + "/scene.json";
    test::writeFile(path, std::string(R"({"name": "light_inside",
  "meshes": [{"name": "ball", "generator": "sphere", "radius": 0.5, "tessellation": 32},
             {"name": "pillar", "generator": "box", "half_extent": [0.25, 2, 0.25]},
             {"name": "floor", "generator": "plane", "size": 6, "tessellation": 1}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false}, )") +
                              c.casters + R"(],
  "lights": [{"type": "point", "position": )" +
                              c.light + R"(}],
  "cameras": [{"name": "top", "eye": [0, 5, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
               "near": 0.5, "far": 50}]})");
    Harness h(test::quickConfig(path, "top", kSize));
    ProjectiveGL t;
    h.prepare(t);
    AccuracyEvaluator evaluator(h);
    AccuracyOptions options;
    options.stability = false;
    const AccuracyEvaluator::Sample s = evaluator.judgeFrame(t, options, nullptr);
    const std::vector<uint8_t> edge = AccuracyMetrics::edgeMask(s.reference, kSize, kSize);
    int referenceShadow = 0, both = 0, judged = 0, falseShadow = 0;
    for (size_t i = 0; i < s.mask.size(); ++i) {
        if (!s.mask[i] || edge[i]) continue;
        ++judged;
        const bool refShadow = s.reference[i] < 0.5f, shadow = s.technique[i] < 0.5f;
        referenceShadow += refShadow;
        both += refShadow && shadow;
        falseShadow += !refShadow && shadow;
    }
    std::cout << c.name << ": judged " << judged << ", reference shadow " << referenceShadow << ", overlap "
              << double(both) / std::max(referenceShadow, 1) << ", false shadow " << falseShadow << "\n";
    EXPECT_GT(judged, kSize * kSize / 4);
    ASSERT_GT(referenceShadow, 1000) << "the reference has hardly any shadow to overlap";
    EXPECT_GE(double(both) / referenceShadow, 0.97) << both << " of " << referenceShadow;
    EXPECT_LE(falseShadow, judged / 100);
    EXPECT_EQ(test::counter(t.counters(), "projector_clamped"), c.clamped) << c.clampedWhy;
    const ProjectiveGL::Projector p = ProjectiveGL::computeProjector(h.scene(), h.scene().lights[0]);
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) EXPECT_TRUE(std::isfinite(p.viewProj[col][row]));
    const NumericSanity sanity = AccuracyMetrics::sanity(s.techniqueRgba);
    EXPECT_EQ(sanity.total(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Projective, ProjectiveInside, ::testing::ValuesIn(kInsideCases),
                         [](const auto& p) { return std::string(p.param.name); });

// 6. Two directional lights: each channel is its own ellipse, judged independently as in test 1.
TEST(ProjectiveGLTest, TwoLightsMatchTheirOwnClosedForms) {
    const std::string scene = writeScene(test::freshTestDir("projective"),
                                         "[" + directional(kTravelA) + ", " + directional(kTravelB) + "]");
    const Frame f = render(scene, "");
    for (int light = 0; light < 2; ++light) {
        SCOPED_TRACE("light " + std::to_string(light));
        const Judgement j = judge(f, light, light == 0 ? kTravelA : kTravelB);
        EXPECT_GT(j.expectedShadow, 500);
        EXPECT_GT(j.judged, j.floor * 9 / 10);
        EXPECT_EQ(j.wrong, 0);
    }
    // The two shadows are different places: each channel must differ from the other somewhere.
    int differ = 0;
    for (size_t i = 0; i < f.world.size(); ++i)
        differ += std::abs(f.visibility[i * 4] - f.visibility[i * 4 + 1]) > 0.5f;
    EXPECT_GT(differ, 500);
    // Unused channels stay lit.
    size_t unusedNotOne = 0;
    for (size_t i = 0; i < f.world.size(); ++i)
        unusedNotOne += f.visibility[i * 4 + 2] != 1.0f || f.visibility[i * 4 + 3] != 1.0f;
    EXPECT_EQ(unusedNotOne, 0u);
    EXPECT_EQ(test::counter(f.counters, "projective_texels"), 2.0 * 512 * 512);
}

// What the technique declares: honest effects (no self-shadowing, no soft shadows), its passes, knobs.
TEST(ProjectiveGLTest, DeclaresItsEffectsPassesAndKnobs) {
    ProjectiveGL t;
    const TechniqueInfo& info = t.info();
    EXPECT_EQ(info.name, "projective");
    EXPECT_EQ(info.effects,
              EffectMask(Effect::HardShadows | Effect::NonPlanarReceivers | Effect::MultipleLights));
    EXPECT_EQ(info.passes, (std::vector<std::string>{"texture", "blur", "lighting"}));
    EXPECT_EQ(t.properties().getInt("resolution"), 512);
    EXPECT_EQ(t.properties().getInt("blur"), 0);
    ASSERT_EQ(info.quality.size(), 2u);
}

// No casters: nothing is drawn into a texture and everything is lit.
TEST(ProjectiveGLTest, NoCastersMeansEverythingLit) {
    const std::string dir = test::freshTestDir("projective");
    const std::string path = dir + "/scene.json";
    test::writeFile(path, R"({"name": "floor_only",
  "meshes": [{"name": "floor", "generator": "plane", "size": 6, "tessellation": 1}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false}],
  "lights": [{"type": "directional", "direction": [0.4, -1, 0.1]}],
  "cameras": [{"name": "top", "eye": [0, 5, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 50,
               "near": 0.5, "far": 50}]})");
    const Frame f = render(path, "");
    size_t notOne = 0;
    for (float v : f.visibility) notOne += v != 1.0f;
    EXPECT_EQ(notOne, 0u);
    EXPECT_EQ(test::counter(f.counters, "projective_texels"), 0.0);
}

} // namespace
