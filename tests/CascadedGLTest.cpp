// `cascaded` rendered on llvmpipe and judged against independent answers:
//  (a) stability: a top-down view of a sphere over the ground, the camera moved parallel to the ground
//      by exactly one pixel's ground footprint (under a texel of the cascade's map). With stabilize the
//      map's texel grid is fixed in the world, so the new image equals the old one shifted by a pixel:
//      no ground pixel's visibility changes beyond the shadow's edge band. Without it (the tight box
//      that follows the camera) the grid slides and edge pixels change: the negative control;
//  (b) the exact shadow of the sphere on sphere_plane (the ellipse of tests/ShadowMapGLTest.cpp) from
//      above, and the Embree reference (bench/lib/measure/AccuracyEvaluator.h) from an oblique camera whose
//      view spans every cascade;
//  (c) a long, low view down a street of `city`: against the reference, cascaded gets fewer pixels
//      wrong than shadowmap near the camera and over the whole image;
//  (d) fit=sdsm (Lauritzen, Salvi and Lefohn 2011, Sample Distribution Shadow Maps): the GPU reduction of
//      the depth pre-pass equals the min and max the CPU finds in the same depth image read back
//      (exact: both compare the stored floats), and the splits bracket every pixel the lighting pass
//      drew, no wider than their padding;
//  and the refusals (point lights) and spot lights as shadowmap does them.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "bench/lib/measure/AccuracyEvaluator.h"
#include "core/Error.h"
#include "scenes/Math.h"
#include "techniques/ViewDepth.h"
#include "techniques/shadowmap/CascadeSplits.h"
#include "techniques/shadowmap/CascadedGL.h"

using namespace sb;

namespace {

constexpr int kSize = 384;

/// Visibility (channel 0) and world position of every pixel of the harness's last frame.
struct Frame {
    std::vector<float> vis;
    std::vector<glm::vec4> world;
};

Frame render(Harness& h, GlTechnique& t) {
    h.renderFrame(t);
    Frame f;
    const auto rgba = h.targets().readVisibilityRGBA32F();
    f.vis.resize(rgba.size() / 4);
    for (size_t i = 0; i < f.vis.size(); ++i) f.vis[i] = rgba[i * 4];
    f.world = test::unprojectDepth(h.targets().readDepth(), h.targets().width(), h.targets().height(),
                                   h.projection() * h.view());
    return f;
}

std::unique_ptr<CascadedGL> cascaded(const std::string& props) {
    auto t = std::make_unique<CascadedGL>();
    if (!props.empty()) t->properties().apply(TechniqueSpec::parse("cascaded:" + props).properties);
    t->propertiesApplied(); // as the registry's create does: fit=sdsm's passes
    return t;
}

/// The sphere's ellipse on the ground (tests/ShadowMapGLTest.cpp): signed distance, perpendicular to
/// the light, from the ray p -> light to the sphere's surface; negative inside the shadow.
struct SphereShadow {
    glm::dvec3 centre, toLight;
    double radius = 0.0;
    double margin(const glm::vec4& p) const {
        const glm::dvec3 pc = centre - glm::dvec3(p);
        const double t = glm::dot(pc, toLight);
        if (t <= 0.0) return 1e9;
        return glm::length(pc - t * toLight) - radius;
    }
};

SphereShadow sphereShadow(const Scene& scene) {
    SphereShadow s;
    const Instance* sphere = nullptr;
    for (const Instance& i : scene.instances)
        if (i.castsShadow && scene.meshes[i.mesh].name == "sphere") sphere = &i;
    EXPECT_NE(sphere, nullptr);
    if (!sphere) return s;
    for (const glm::vec3& p : scene.meshes[sphere->mesh].positions)
        s.radius = std::max(s.radius, double(glm::length(p)) * sphere->scale);
    s.centre = glm::dvec3(sphere->model * glm::vec4(0, 0, 0, 1));
    s.toLight = -glm::normalize(glm::dvec3(scene.lights[0].direction));
    return s;
}

bool onGround(const glm::vec4& w) {
    return w.w != 0.0f && std::abs(w.y) < 1e-2f;
}

// --- (a) stability under a sub-texel camera move ------------------------------------------------------

// sphere_plane's sphere, ground and light, plus two small boxes 30 units out (far outside the view,
// their shadows too). They widen the casters' bounds, which the cascades are clamped to, beyond the
// view: without them both fits would shrink to the sphere's bounds, a scene constant, and the tight
// fit would not follow the camera either. The ground is 80 wide so the view sees nothing else.
constexpr const char* kShiftScene = R"({
  "name": "cascade_shift",
  "meshes": [
    {"name": "sphere", "generator": "sphere", "radius": 1, "tessellation": 64},
    {"name": "ground", "generator": "plane", "size": 80, "tessellation": 16},
    {"name": "marker", "generator": "box", "half_extent": [0.25, 0.25, 0.25]}
  ],
  "instances": [
    {"mesh": "ground", "position": [0, 0, 0], "casts_shadow": false},
    {"mesh": "sphere", "position": [0, 3, 0]},
    {"mesh": "marker", "position": [-30, 0.25, -30]},
    {"mesh": "marker", "position": [30, 0.25, 30]}
  ],
  "lights": [{"type": "directional", "direction": [0.3, -1.0, 0.2]}],
  "cameras": [{"name": "top", "eye": [0, 30, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 20,
               "near": 1, "far": 100}],
  "effects": ["hard_shadows"]
})";

struct ShiftResult {
    int compared = 0;       ///< ground pixels seen in both frames
    int band = 0;           ///< of which in the edge band
    int changedBand = 0;    ///< visibility changed by more than kChange, in the band
    int changedOutside = 0; ///< ... outside it
    double footprint = 0.0, texel = 0.0, bandWidth = 0.0;
};

constexpr float kChange = 0.05f; // bilinear weights are quantised (llvmpipe: 8 bits): a few 1/256 steps

ShiftResult shiftOnePixel(const std::string& props) {
    const std::string dir = test::freshTestDir("cascaded");
    test::writeFile(dir + "/cascade_shift.json", kShiftScene);
    Harness h(test::quickConfig(dir + "/cascade_shift.json", "top", kSize));
    auto t = cascaded(props);
    h.prepare(*t);
    CameraPreset cam = h.camera();
    const Frame before = render(h, *t);
    ShiftResult r;
    // One pixel's footprint on the ground 30 below the eye (fov 20 over kSize pixels); moving the eye
    // and the target by it along +X shifts the ground's image by exactly one pixel to the left.
    r.footprint = 2.0 * 30.0 * std::tan(glm::radians(10.0)) / kSize;
    // The ground lies in the last cascade (all of it at view depth 30).
    r.texel = t->cascades(0).back().texel;
    cam.eye.x += float(r.footprint);
    cam.target.x += float(r.footprint);
    h.setCamera(cam);
    const Frame after = render(h, *t);
    const SphereShadow s = sphereShadow(h.scene());
    // The edge band: two texels of the map (bilinear compare reads a 2x2 footprint) plus a pixel.
    r.bandWidth = 2.0 * r.texel + r.footprint;
    for (int y = 1; y < kSize - 1; ++y)
        for (int x = 1; x < kSize - 2; ++x) {
            const size_t i = size_t(y) * kSize + size_t(x);
            const glm::vec4& p = after.world[i];
            const glm::vec4& q = before.world[i + 1];
            if (!onGround(p) || !onGround(q)) continue;
            EXPECT_LT(glm::length(glm::vec3(p - q)), 1e-3f) << "the image did not shift by one pixel";
            ++r.compared;
            const bool inBand = std::abs(s.margin(p)) <= r.bandWidth;
            const bool changed = std::abs(after.vis[i] - before.vis[i + 1]) > kChange;
            r.band += inBand;
            (inBand ? r.changedBand : r.changedOutside) += changed;
        }
    std::cout << "cascaded:" << props << ": footprint " << r.footprint << ", texel " << r.texel << ", "
              << r.compared << " ground pixels compared, " << r.band
              << " in the band; changed: " << r.changedBand << " in the band, " << r.changedOutside
              << " outside\n";
    return r;
}

TEST(CascadedStability, SubTexelCameraMoveKeepsShadowsPut) {
    // resolution 256: the last cascade's texel (~0.06) is twice the pixel's footprint (0.0276), so the
    // one-pixel move is a sub-texel move in the map, the case snapping is for.
    const ShiftResult r = shiftOnePixel("resolution=256");
    ASSERT_LT(r.footprint, r.texel) << "not a sub-texel move";
    EXPECT_GT(r.compared, kSize * kSize / 2);
    EXPECT_GT(r.band, 200) << "the shadow's edge is hardly in view";
    EXPECT_EQ(r.changedOutside, 0);
    // The grid is fixed in the world: the same samples read the same texels, so even the band stays
    // (measured: 0); a few pixels are allowed for rounding of the sample positions at texel edges.
    EXPECT_LE(r.changedBand, r.band / 100);
}

TEST(CascadedStability, TightFitShimmersUnderTheSameMove) {
    // The negative control: the tight box follows the camera, its grid slides by a fraction of a texel
    // and the staircase of the ellipse's edge moves. Nothing changes off the band here either (the
    // map's content is the same shape), so the edge band is where the control must see it.
    const ShiftResult stable = shiftOnePixel("resolution=256");
    const ShiftResult r = shiftOnePixel("resolution=256:stabilize=false");
    ASSERT_LT(r.footprint, r.texel) << "not a sub-texel move";
    EXPECT_EQ(r.changedOutside, 0);
    EXPECT_GT(r.changedBand, std::max(20, 10 * stable.changedBand))
        << "the unsnapped fit must make edge pixels change where the snapped one does not";
}

// --- (b) against the exact answers --------------------------------------------------------------------

struct EllipseCase {
    const char* name;
    const char* props;
    SubmitMode submit;
};
void PrintTo(const EllipseCase& c, std::ostream* os) {
    *os << c.name;
}
const EllipseCase kEllipseCases[] = {
    {"defaults_retained", "", SubmitMode::Retained},
    {"tight_fit", "stabilize=false", SubmitMode::Retained},
    {"pcf3_instanced", "pcf=3", SubmitMode::Instanced},
    {"one_cascade_uniform", "cascades=1:lambda=0", SubmitMode::Immediate},
    {"res512_no_blend", "resolution=512:blend=0", SubmitMode::DisplayList},
};
class CascadedEllipse : public ::testing::TestWithParam<EllipseCase> {};

TEST_P(CascadedEllipse, MatchesAnalyticEllipse) {
    const EllipseCase& c = GetParam();
    RunConfig cfg = test::quickConfig("sphere_plane", "top", kSize, c.submit);
    cfg.sceneOptions.tessellation = 64; // polygonal silhouette within r(1 - cos(pi/64)) = 1.2e-3 r
    Harness h(cfg);
    auto t = cascaded(c.props);
    h.prepare(*t);
    const Frame f = render(h, *t);
    const SphereShadow s = sphereShadow(h.scene());
    // The band: the largest cascade texel (1.5 texels for bilinear compare plus the PCF half-width),
    // the pixel's footprint and the polygonal sphere's silhouette error; either answer is right in it.
    double texel = 0.0;
    for (const Cascade& k : t->cascades(0)) texel = std::max(texel, double(k.texel));
    const double band = texel * (1.5 + 0.5 * double(t->properties().getInt("pcf"))) +
                        s.radius * (1.0 - std::cos(M_PI / 64.0));
    int ground = 0, judged = 0, wrong = 0, expected = 0, got = 0;
    for (int y = 1; y < kSize - 1; ++y)
        for (int x = 1; x < kSize - 1; ++x) {
            const size_t i = size_t(y) * kSize + size_t(x);
            if (!onGround(f.world[i])) continue;
            ++ground;
            const double footprint = glm::length(glm::vec3(f.world[i + 1]) - glm::vec3(f.world[i]));
            const double m = s.margin(f.world[i]);
            expected += m < 0.0;
            got += f.vis[i] < 0.5f;
            if (std::abs(m) <= band + footprint) continue;
            ++judged;
            wrong += (m < 0.0) != (f.vis[i] < 0.5f);
        }
    std::cout << c.name << ": texel " << texel << ", band " << band << ", judged " << judged << " of "
              << ground << ", wrong " << wrong << ", shadow " << got << " px vs " << expected << " exact\n";
    EXPECT_GT(ground, kSize * kSize / 4);
    EXPECT_GT(expected, 500);
    EXPECT_GT(judged, ground * 9 / 10) << "the tolerance band swallowed the image";
    EXPECT_EQ(wrong, 0) << "pixels outside the edge band classified wrongly (band " << band << ")";
    EXPECT_NEAR(double(got), double(expected), 0.05 * expected + 50);
}

INSTANTIATE_TEST_SUITE_P(Cascaded, CascadedEllipse, ::testing::ValuesIn(kEllipseCases),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(CascadedReference, ObliqueViewAcrossEveryCascadeMatchesEmbree) {
    // sphere_plane's "far" camera sees the ground from 0.5 to beyond 40 units: all four cascades and
    // their blend bands are on screen. Bound: 0.02% wrong off the 1-px edge band (measured 0%);
    // everything else is the staircase on the edge band, bounded at 0.5% (measured below).
    Harness h(test::quickConfig("sphere_plane", "far", kSize));
    auto t = cascaded("");
    h.prepare(*t);
    AccuracyEvaluator evaluator(h);
    AccuracyOptions o;
    o.stability = false;
    const AccuracyResult r = evaluator.evaluate(*t, o);
    const std::vector<float>& splits = t->splits();
    std::cout << "far: splits " << splits[0] << " " << splits[1] << " " << splits[2] << " " << splits[3]
              << " " << splits[4] << "; evaluated " << r.hard.evaluated << ", wrong " << r.hard.wrongPct
              << "%, off edge " << r.hard.wrongNoEdgePct << "%\n";
    EXPECT_GT(r.hard.evaluated, uint64_t(kSize * kSize / 4));
    EXPECT_EQ(r.sanity.total(), 0u);
    // The camera sees 0.5 to 200; the receivers' boxes (the ground's corners (+-20, 0, +-20), the
    // sphere's) lie 8.844 to 43.281 along its view axis (hand-computed from the preset), so the
    // splits span that plus 1% of it and 1e-5 of the far plane each side: 8.497 to 43.627.
    EXPECT_NEAR(splits.front(), 8.497, 0.005);
    EXPECT_NEAR(splits.back(), 43.627, 0.005);
    EXPECT_LE(r.hard.wrongNoEdgePct, 0.02);
    EXPECT_LE(r.hard.wrongPct, 0.5);
}

// --- (c) a long view: near shadows sharper than one map's ---------------------------------------------

struct Wrong {
    uint64_t nearJudged = 0, nearWrong = 0, allJudged = 0, allWrong = 0;
};

/// Wrong pixels against the reference; "near": view depth below `nearDepth`.
Wrong countWrong(Harness& h, GlTechnique& t, AccuracyEvaluator& evaluator, float nearDepth) {
    h.prepare(t);
    AccuracyOptions o;
    o.stability = false;
    const AccuracyEvaluator::Sample s = evaluator.judgeFrame(t, o, nullptr);
    const auto world = test::unprojectDepth(h.targets().readDepth(), kSize, kSize, h.projection() * h.view());
    Wrong w;
    for (size_t i = 0; i < s.mask.size(); ++i) {
        if (!s.mask[i]) continue;
        const bool wrong = (s.technique[i] < 0.5f) != (s.reference[i] < 0.5f);
        const float depth = -(h.view() * glm::vec4(glm::vec3(world[i]), 1.0f)).z;
        ++w.allJudged;
        w.allWrong += wrong;
        if (depth < nearDepth) {
            ++w.nearJudged;
            w.nearWrong += wrong;
        }
    }
    return w;
}

TEST(CascadedLongView, NearShadowEdgesSharperThanShadowmap) {
    // 4 units above a street of `city` (the street x in [-2, 2]), 12 units outside the city's edge,
    // looking down the street over 120 units of blocks. shadowmap's one 2048^2 map spans the whole
    // city (~0.08 units a texel), so the first blocks' shadows on the street, 12-30 units away, are
    // stair-steps several pixels wide; cascaded's nearer cascades are a few units across.
    Harness h(test::quickConfig("city", "far", kSize));
    CameraPreset cam = h.camera();
    cam.eye = {0.5f, 4.0f, 70.0f};
    cam.target = {0.0f, 0.0f, -40.0f};
    cam.up = {0, 1, 0};
    cam.fovYDeg = 50.0f;
    cam.nearZ = 0.5f;
    cam.farZ = 400.0f;
    h.setCamera(cam);
    AccuracyEvaluator evaluator(h);
    constexpr float kNear = 30.0f;
    auto sm = TechniqueRegistry::create("shadowmap");
    auto csm = cascaded("");
    const Wrong a = countWrong(h, *sm, evaluator, kNear);
    const Wrong b = countWrong(h, *csm, evaluator, kNear);
    std::cout << "long view: shadowmap wrong " << a.nearWrong << " of " << a.nearJudged << " near, "
              << a.allWrong << " of " << a.allJudged << " in all; cascaded " << b.nearWrong << " near, "
              << b.allWrong << " in all\n";
    ASSERT_GT(a.nearJudged, uint64_t(kSize * kSize / 20)) << "the near part is hardly in view";
    ASSERT_GT(a.nearWrong, 100u) << "shadowmap's near staircase must be visible, or this proves nothing";
    // The near cascades' texels are several times smaller (measured: shadowmap 244 of 39008 judged
    // pixels nearer than 30 wrong, 249 of 42778 in all; cascaded 45 and 46): at most half of
    // shadowmap's near errors, and fewer over the whole image.
    EXPECT_LT(2 * b.nearWrong, a.nearWrong);
    EXPECT_LT(b.allWrong, a.allWrong);
}

// --- lights -------------------------------------------------------------------------------------------

TEST(CascadedGL, PointLightIsRefusedNamingTheOmniTechniques) {
    RunConfig cfg = test::quickConfig("sphere_plane", "top", 64);
    cfg.sceneOptions.lightType = LightType::Point;
    Harness h(cfg);
    CascadedGL t;
    try {
        h.prepare(t);
        FAIL() << "point light accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::Unsupported);
        const std::string what = e.what();
        EXPECT_NE(what.find("point light"), std::string::npos) << what;
        EXPECT_NE(what.find("cubemap"), std::string::npos) << what;
        EXPECT_NE(what.find("paraboloid"), std::string::npos) << what;
    }
}

TEST(CascadedGL, SpotLightShadowsTheGroundUnderTheSphere) {
    // One perspective map as shadowmap's: under the sphere shadowed, off its projection lit (the
    // closed form of ShadowMapGLTest's spot case), with a 10% radius band for perspective texels.
    RunConfig cfg = test::quickConfig("sphere_plane", "top", 256);
    cfg.sceneOptions.lightType = LightType::Spot;
    Harness h(cfg);
    CascadedGL t;
    h.prepare(t);
    const Frame f = render(h, t);
    const Light& light = h.scene().lights[0];
    ASSERT_EQ(light.type, LightType::Spot);
    SphereShadow s = sphereShadow(h.scene());
    int checked = 0, wrong = 0;
    for (size_t i = 0; i < f.world.size(); ++i) {
        if (!onGround(f.world[i])) continue;
        const glm::dvec3 p(f.world[i]);
        const glm::dvec3 toL = glm::normalize(glm::dvec3(light.position) - p);
        if (glm::dot(-toL, glm::normalize(glm::dvec3(light.direction))) <
            std::cos(glm::radians(light.spotOuterDeg)) + 0.02)
            continue; // outside the cone the light term is zero anyway
        s.toLight = toL;
        const double m = s.margin(f.world[i]);
        if (std::abs(m) < 0.1 * s.radius) continue;
        ++checked;
        wrong += (m < 0.0) != (f.vis[i] < 0.5f);
    }
    EXPECT_GT(checked, 1000);
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(test::counter(t.counters(), "cascades"), 0.0); // no directional light, no cascade
}

TEST(CascadedGL, CountersAndCulling) {
    // city from "mid" (oblique, 0.5 to ~150 units): four cascades of one directional light, each culling
    // the blocks outside its sides and far plane (casters towards the light are kept); the culled
    // count is summed over the maps drawn, the texels are those of the maps drawn.
    Harness h(test::quickConfig("city", "mid", 128));
    auto t = cascaded("resolution=256");
    test::RenderedFrame f = test::renderOnce(h, *t);
    const double maps = test::counter(f.counters, "shadow_map_texels") / (256.0 * 256.0);
    std::cout << "city mid: maps drawn " << maps << ", casters culled "
              << test::counter(f.counters, "casters_culled") << "\n";
    EXPECT_EQ(test::counter(f.counters, "cascades"), 4.0);
    EXPECT_GE(maps, 2.0);
    EXPECT_LE(maps, 4.0);
    EXPECT_GT(test::counter(f.counters, "casters_culled"), 0.0);
    EXPECT_LT(test::counter(f.counters, "casters_culled"), maps * 144);
    EXPECT_GT(test::counter(f.counters, "draw_calls"), 0.0);
    EXPECT_GT(test::counter(f.counters, "triangles"), 0.0);
}

TEST(CascadedGL, IdenticalCascadesShareOneMap) {
    // city from straight above (190 up, every receiver 162-190 away): each slice's sphere is wider than
    // the blocks, so every cascade is clamped to the casters' whole bounds, the four fits are equal and
    // one map is drawn; the image must still match the reference as shadowmap's one map does.
    Harness h(test::quickConfig("city", "top", 256));
    auto t = cascaded("");
    h.prepare(*t);
    AccuracyEvaluator evaluator(h);
    AccuracyOptions o;
    o.stability = false;
    const AccuracyResult r = evaluator.evaluate(*t, o);
    const auto& c = t->cascades(0);
    for (size_t i = 1; i < c.size(); ++i) EXPECT_EQ(c[i].viewProj, c[0].viewProj) << "cascade " << i;
    EXPECT_EQ(test::counter(t->counters(), "shadow_map_texels"), 2048.0 * 2048.0);
    EXPECT_EQ(test::counter(t->counters(), "cascades"), 4.0);
    std::cout << "city top: wrong " << r.hard.wrongPct << "%, off edge " << r.hard.wrongNoEdgePct << "%\n";
    // The one map's staircase on the edge band (measured below); nothing off it.
    EXPECT_LE(r.hard.wrongNoEdgePct, 0.01);
}

/// The pre-pass's depth texture of `t`'s last frame, read back (GL_FLOAT: the stored 32-bit floats).
std::vector<float> readPrePass(const CascadedGL& t, int width, int height) {
    std::vector<float> depth(size_t(width) * size_t(height));
    glGetTextureImage(t.viewDepth().texture(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      GLsizei(depth.size() * sizeof(float)), depth.data());
    return depth;
}

struct SdsmView {
    const char* scene;
    const char* camera;
};
const SdsmView kSdsmViews[] = {{"sphere_plane", "top"}, {"city", "mid"}, {"aircraft", "mid"}};

TEST(CascadedSdsm, ReductionEqualsTheCpuMinMaxOfTheSameDepthImage) {
    for (const SdsmView& v : kSdsmViews) {
        Harness h(test::quickConfig(v.scene, v.camera, 200));
        auto t = cascaded("fit=sdsm:resolution=256");
        test::renderOnce(h, *t);
        const std::vector<float> depth = readPrePass(*t, h.targets().width(), h.targets().height());
        float lo = 1.0f, hi = 0.0f;
        size_t covered = 0;
        for (float d : depth)
            if (d < 1.0f) {
                lo = std::min(lo, d);
                hi = std::max(hi, d);
                ++covered;
            }
        const glm::vec2 gpu = t->depthRange().latestWindowRange();
        std::cout << v.scene << " " << v.camera << ": " << covered << " covered pixels, window depth [" << lo
                  << ", " << hi << "]\n";
        ASSERT_GT(covered, 0u) << v.scene;
        // The same stored floats, min and max: no tolerance.
        EXPECT_EQ(gpu.x, lo) << v.scene << " " << v.camera;
        EXPECT_EQ(gpu.y, hi) << v.scene << " " << v.camera;
    }
}

TEST(CascadedSdsm, SplitsBracketEveryPixelTheLightingPassDrew) {
    for (const SdsmView& v : kSdsmViews) {
        Harness h(test::quickConfig(v.scene, v.camera, 200));
        auto t = cascaded("fit=sdsm:resolution=256");
        const test::RenderedFrame f = test::renderOnce(h, *t);
        // The view depth of every pixel the lighting pass drew, from its own depth buffer: independent of
        // the pre-pass and the reduction.
        double lo = 1e30, hi = -1e30;
        for (const glm::vec4& p : f.world) {
            if (p.w == 0.0f) continue;
            const double d = -double((h.view() * glm::vec4(glm::vec3(p), 1.0f)).z);
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
        ASSERT_LT(lo, hi) << v.scene;
        const std::vector<float>& s = t->splits();
        ASSERT_EQ(s.size(), 5u);
        // The harness's depth buffer is 24-bit: its depths round to 2^-24 of the window range, which
        // near the far end of a 1:1000 perspective is worth up to ~1e-3 relative; the padding is 1% of
        // the interval plus 1e-5 of far, so the splits must still hold every pixel.
        std::cout << v.scene << " " << v.camera << ": pixels at view depth [" << lo << ", " << hi
                  << "], splits [" << s.front() << ", " << s.back() << "]\n";
        EXPECT_LE(s.front(), lo * (1.0 + 1e-3)) << v.scene;
        EXPECT_GE(s.back(), hi * (1.0 - 1e-3)) << v.scene;
        // No wider than the padding (2% of the interval plus 2e-5 of far) and the depth rounding.
        const double far = CascadeSplits::nearFar(h.projection()).y;
        EXPECT_LE(double(s.back()) - double(s.front()), 1.02 * (hi - lo) + 2e-5 * far + 2e-3 * hi) << v.scene;
        EXPECT_EQ(test::counter(f.counters, "depth_min"),
                  double(ViewDepth::viewDepths(t->depthRange().windowRange(), h.projection()).x));
    }
}

// A near camera looking at a small region (tests/hard/scenes/cascade_transition.json, camera "closeup":
// 2.7 above the ground, a 12 degree lens on a patch ~0.6 wide across the wall shadow's straight edge,
// tilted so the ground's far corners lie ~30 deep). The practical split spans the receivers' [near, ~30]
// (the ground's box reaches under the camera: its near end is the camera's 0.05), so the patch, 2.7 to
// 2.9 deep, falls in its second cascade, [2.1, 4.7]; fit=sdsm splits the patch's own depths, slices
// ~0.04 long whose spheres are the frustum's width there. At 256^2 per cascade the practical texel covers
// several pixels and its staircase leaves the edge band; sdsm's must not. Both are judged against the
// Embree reference on the same pixels. Measured on llvmpipe: practical [0.05, 30.07], 0.63% wrong, 0.39%
// off the edge band; sdsm [2.706, 2.866], 0.16% and 0.005%.
TEST(CascadedSdsm, NearCameraOnASmallRegionHasFewerWrongPixelsThanPractical) {
    Harness h(test::quickConfig(std::string(SB_SOURCE_DIR) + "/tests/hard/scenes/cascade_transition.json",
                                "closeup", kSize));
    AccuracyEvaluator evaluator(h);
    AccuracyOptions o;
    o.stability = false;
    double wrong[2], offEdge[2];
    float spanNear[2], spanFar[2];
    const char* forms[2] = {"resolution=256", "resolution=256:fit=sdsm"};
    for (int i = 0; i < 2; ++i) {
        auto t = cascaded(forms[i]);
        h.prepare(*t);
        const AccuracyResult r = evaluator.evaluate(*t, o);
        wrong[i] = r.hard.wrongPct;
        offEdge[i] = r.hard.wrongNoEdgePct;
        spanNear[i] = t->splits().front();
        spanFar[i] = t->splits().back();
        std::cout << "closeup " << forms[i] << ": splits [" << spanNear[i] << ", " << spanFar[i]
                  << "], wrong " << wrong[i] << "%, off the edge band " << offEdge[i] << "%\n";
    }
    // The split intervals the comment above works out: practical's reaches the ground's far corners,
    // sdsm's is the patch's (2.7 to 3, padded).
    EXPECT_GT(spanFar[0], 20.0f);
    EXPECT_GT(spanNear[1], 2.5f);
    EXPECT_LT(spanFar[1], 3.3f);
    ASSERT_GT(wrong[0], 0.0) << "practical's staircase must be visible here, or this proves nothing";
    // Smaller texels, fewer wrong pixels: at most half of practical's.
    EXPECT_LT(2.0 * wrong[1], wrong[0]);
    EXPECT_LE(offEdge[1], offEdge[0]);
}

} // namespace
