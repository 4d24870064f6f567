// `raytraced` through the bench binary (techniques/raytraced/README.md): its agreement with the Embree
// reference on every built-in scene, its refusals where it cannot run, its counters against a closed
// form, and its ray origins (the offset along the normal, shaders/raytraced/rays.glsl) on two scenes whose
// answer is computed here by hand: a ground under a light 1 degree above the horizon, and a box standing
// on the ground.
//
// Ray queries need lavapipe of Mesa 25.0.7 (`--driver mesa-25.0.7`): the tests that render skip, naming
// the install command, where it is not installed (fail where SHADOWBENCH_REQUIRE_DRIVERS=1). Each run is
// one frame without warm-up or timer check, at 128x128 or smaller: 0.5 to 3 s each.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "PngDecoder.h"
#include "SecondDriver.h"
#include "TestSupport.h"
#include "scenes/SceneLoader.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;
const std::string kOneFrame = " --frames 1 --warmup 0 --no-timer-check -q";

/// The bench on the second driver's Vulkan.
std::string onRayQueries() {
    return kBench + " --driver " + test::kSecondDriver;
}

/// The single row of the CSV at `path`.
std::map<std::string, std::string> onlyRow(const std::string& path) {
    const auto rows = test::csvRowMaps(path);
    EXPECT_EQ(rows.size(), 1u) << path;
    return rows.empty() ? std::map<std::string, std::string>{} : rows.front();
}

double number(const std::map<std::string, std::string>& row, const std::string& column) {
    const auto it = row.find(column);
    EXPECT_NE(it, row.end()) << "no column " << column;
    return it == row.end() || it->second.empty() ? -1.0 : std::stod(it->second);
}

/// Samples out of `evaluated` that a percentage column of 4 decimals stands for.
long samples(double pct, double evaluated) {
    return std::lround(pct * evaluated / 100.0);
}

// ---- (a) every built-in scene against the Embree reference ---------------------------------------------

// Both trace one ray from the same rasterised samples towards the light's centre, from the same origin
// (max(1e-4, 32 sum_i |n_i| spacing(p_i)) along the normal: shaders/raytraced/rays.glsl and
// reference/ReferenceTracer.cpp), so only traversal and geometry differ: the bottom levels hold exact
// object-space triangles, Embree the world-space ones the model transform rounds. Measured (rays.glsl's
// comment): 0 samples differ on every built-in scene at 128x128; at 512x512 0 to 3 of ~2e5, all in the
// edge band (aircraft 3, city 2). Bounds: 1 sample off the edge band (a ray grazing an occluder within
// that rounding, at 128^2 not seen) and 0.05% of the samples in all (20x the worst rate measured at
// 512^2, where edge-band samples are denser).
constexpr long kMaxWrongOffEdge = 1;
constexpr double kMaxWrongPct = 0.05;

class RayTracedAgainstEmbree : public ::testing::TestWithParam<std::string> {};

TEST_P(RayTracedAgainstEmbree, AgreesOutsideTheEdgeBandAt128) {
    REQUIRE_SECOND_DRIVER();
    const std::string dir = test::freshTestDir("raytraced-accuracy");
    const std::string csv = dir + "/acc.csv";
    const auto r =
        runCommand(onRayQueries() + " accuracy --api vulkan --vk-validation -t raytraced:mode=hard --scene " +
                   GetParam() + " --size 128x128 --no-stability --csv " + csv + kOneFrame);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto row = onlyRow(csv);
    const double evaluated = number(row, "acc_evaluated");
    ASSERT_GT(evaluated, 0.0) << "no sample judged";
    EXPECT_EQ(number(row, "acc_nan"), 0.0);
    EXPECT_EQ(number(row, "acc_inf"), 0.0);
    EXPECT_EQ(number(row, "acc_out_of_range"), 0.0);
    EXPECT_LE(samples(number(row, "acc_wrong_no_edge_pct"), evaluated), kMaxWrongOffEdge)
        << number(row, "acc_wrong_no_edge_pct") << "% of " << evaluated << " samples off the edge band";
    EXPECT_LE(number(row, "acc_wrong_pct"), kMaxWrongPct);
}

INSTANTIATE_TEST_SUITE_P(BuiltinScenes, RayTracedAgainstEmbree,
                         ::testing::ValuesIn(SceneLoader::listBuiltinScenes()),
                         [](const auto& p) { return p.param; });

// ---- (b, c) where it cannot run: one line on stderr, exit 3 ----------------------------------------------

/// `command`'s standard error alone (its standard output thrown away) and exit code.
test::CommandResult stderrOf(const std::string& command) {
    return runCommand("(" + command + " >/dev/null)");
}

TEST(RayTracedRefusal, GlHasNoRayQueries) {
    const auto r = stderrOf(kBench + " -t raytraced --scene sphere_plane --size 32x32" + kOneFrame);
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_EQ(r.output, "bench: error: GL has no ray queries: ray-traced shadows need VK_KHR_ray_query (use "
                        "--api vulkan --driver mesa-25.0.7)\n");
}

// The system's lavapipe (Mesa 22.3.6) offers neither extension: the line names both and the driver entry
// that has them.
TEST(RayTracedRefusal, TheSystemDriverLacksTheExtensions) {
    const auto r =
        stderrOf(kBench + " --api vulkan -t raytraced --scene sphere_plane --size 32x32" + kOneFrame);
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    for (const char* needle :
         {"raytraced needs ", "VK_KHR_acceleration_structure", "VK_KHR_ray_query", "--driver mesa-25.0.7"})
        EXPECT_NE(r.output.find(needle), std::string::npos) << needle << " in: " << r.output;
}

// ---- (d) the counters
// ---------------------------------------------------------------------------------------

// A ground larger than the view, seen from straight above: every pixel is one ground fragment. Two lights
// reach every one of them and cast shadows (a directional light and a point light above the ground); a
// third casts none, so it traces nothing. Closed form: rays_traced = 2 x width x height.
constexpr const char* kCountedScene = R"({
 "name": "counted",
 "meshes": [{"name": "ground", "generator": "plane", "size": 40, "tessellation": 4}],
 "instances": [{"mesh": "ground", "position": [0, 0, 0]}],
 "lights": [
  {"type": "directional", "direction": [0.2, -1, 0.1]},
  {"type": "point", "position": [1, 6, -1]},
  {"type": "directional", "direction": [-0.3, -1, 0], "casts_shadows": false}
 ],
 "cameras": [{"name": "down", "eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 60,
              "near": 1, "far": 100}],
 "effects": ["hard_shadows", "multiple_lights"]
})";

TEST(RayTracedCounters, RaysAreExactAndTheSameEveryRun) {
    REQUIRE_SECOND_DRIVER();
    const std::string dir = test::freshTestDir("raytraced-counters");
    test::writeFile(dir + "/counted.json", kCountedScene);
    constexpr int kWidth = 64, kHeight = 48;
    std::vector<double> rays;
    for (int run = 0; run < 2; ++run) {
        const std::string csv = dir + "/run" + std::to_string(run) + ".csv";
        const auto r = runCommand(onRayQueries() + " --api vulkan -t raytraced --scene " + dir +
                                  "/counted.json --camera down --size " + std::to_string(kWidth) + "x" +
                                  std::to_string(kHeight) + " --csv " + csv + kOneFrame);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const auto row = onlyRow(csv);
        rays.push_back(number(row, "counter_rays_traced"));
        // The census's pipeline statistics count the pass's fragments independently of the shader.
        EXPECT_EQ(number(row, "work_lighting_fragments"), double(kWidth * kHeight));
        EXPECT_GT(number(row, "counter_structure_bytes"), 0.0);
        EXPECT_EQ(number(row, "counter_structures_built"), 0.0) << "a static scene builds before its frames";
        // The builds are timed inside the setup (setScene + compile), which setup_ms times around them.
        const double bottom = number(row, "counter_bottom_levels_build_ms");
        const double top = number(row, "counter_top_level_build_ms");
        EXPECT_GT(bottom, 0.0);
        EXPECT_GT(top, 0.0);
        EXPECT_LT(bottom + top, number(row, "setup_ms"));
    }
    EXPECT_EQ(rays[0], 2.0 * kWidth * kHeight);
    EXPECT_EQ(rays[1], rays[0]);
}

// aircraft_day's casters move every frame: the top level is rebuilt inside each one.
TEST(RayTracedCounters, MovingCastersRebuildTheTopLevelEveryFrame) {
    REQUIRE_SECOND_DRIVER();
    const std::string dir = test::freshTestDir("raytraced-moving");
    const auto r = runCommand(onRayQueries() +
                              " --api vulkan --vk-validation -t raytraced --scene aircraft_day "
                              "--size 32x32 --csv " +
                              dir + "/m.csv" + kOneFrame);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto row = onlyRow(dir + "/m.csv");
    EXPECT_EQ(number(row, "counter_structures_built"), 1.0);
    EXPECT_GT(number(row, "counter_rays_traced"), 0.0);
}

// ---- (e) ray origins: two scenes answered by hand ---------------------------------------------------------

// The box's corners and the camera of the scene below.
const glm::vec3 kBoxLo{-1.0f, 0.0f, -1.0f}, kBoxHi{1.0f, 2.0f, 1.0f};
const glm::vec3 kEye{-2.5f, 5.0f, 4.0f}, kTarget{1.0f, 0.6f, 0.0f};

// A 2-unit box standing on a ground (both cast shadows, so a ray may hit the surface it leaves), one
// directional light at elevation `elevationDeg`, coming from -x and 20 degrees towards -z.
struct BoxOnGround {
    float elevationDeg;
    static constexpr float kAzimuthDeg = 20.0f;
    static constexpr float kGroundHalf = 12.0f;
    static constexpr float kFovDeg = 60.0f;

    /// Unit vector towards the light.
    glm::vec3 towardsLight() const {
        const float e = glm::radians(elevationDeg), a = glm::radians(kAzimuthDeg);
        return {-std::cos(e) * std::cos(a), std::sin(e), -std::cos(e) * std::sin(a)};
    }
    std::string json() const {
        const glm::vec3 d = -towardsLight();
        auto v = [](const glm::vec3& x) {
            return "[" + std::to_string(x.x) + ", " + std::to_string(x.y) + ", " + std::to_string(x.z) + "]";
        };
        return R"({"name": "box_on_ground",
 "meshes": [{"name": "ground", "generator": "plane", "size": 24, "tessellation": 8},
            {"name": "box", "generator": "box", "half_extent": [1, 1, 1], "tessellation": 2}],
 "instances": [{"mesh": "ground", "position": [0, 0, 0]}, {"mesh": "box", "position": [0, 1, 0]}],
 "lights": [{"type": "directional", "direction": )" +
               v(d) + R"(}],
 "cameras": [{"name": "view", "eye": )" +
               v(kEye) + R"(, "target": )" + v(kTarget) +
               R"(, "up": [0, 1, 0], "fov": 60, "near": 0.5, "far": 100}],
 "effects": ["hard_shadows", "self_shadowing"]})";
    }
};

/// The first hit of o + t d (t > 0) with the box: t, and the face's outward normal; t < 0 where none.
float hitBox(const glm::vec3& o, const glm::vec3& d, glm::vec3* normal) {
    float tNear = -INFINITY, tFar = INFINITY;
    int axis = 0;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0f) {
            if (o[i] < kBoxLo[i] || o[i] > kBoxHi[i]) return -1.0f;
            continue;
        }
        float t0 = (kBoxLo[i] - o[i]) / d[i], t1 = (kBoxHi[i] - o[i]) / d[i];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > tNear) tNear = t0, axis = i;
        tFar = std::min(tFar, t1);
    }
    if (tNear > tFar || tFar <= 0.0f) return -1.0f;
    if (normal) {
        *normal = glm::vec3(0.0f);
        (*normal)[axis] = d[axis] > 0.0f ? -1.0f : 1.0f;
    }
    return tNear;
}

/// What the camera sees through one point of the image and what the light does there, by hand.
struct Expected {
    int surface = 0;  ///< 0 nothing, 1 the ground, 2..7 a face of the box (by its normal)
    bool lit = false; ///< visibility 1: the light reaches it and nothing stops the ray towards it
    bool operator!=(const Expected& o) const { return surface != o.surface || lit != o.lit; }
};

Expected expectedAt(const BoxOnGround& scene, const glm::mat4& inverseViewProj, float ndcX, float ndcY) {
    const glm::vec4 nearPoint = inverseViewProj * glm::vec4(ndcX, ndcY, -1.0f, 1.0f);
    const glm::vec4 farPoint = inverseViewProj * glm::vec4(ndcX, ndcY, 1.0f, 1.0f);
    const glm::vec3 o = glm::vec3(nearPoint) / nearPoint.w;
    const glm::vec3 d = glm::normalize(glm::vec3(farPoint) / farPoint.w - o);
    const glm::vec3 l = scene.towardsLight();
    glm::vec3 n;
    if (hitBox(o, d, &n) > 0.0f) {
        // A face of a convex box lies in the light exactly where it faces it: nothing else is above.
        const int face = 2 + (n.x != 0.0f ? 0 : n.y != 0.0f ? 2 : 4) + (n.x + n.y + n.z > 0.0f ? 1 : 0);
        return {face, glm::dot(n, l) > 0.0f};
    }
    if (d.y >= 0.0f) return {};
    const glm::vec3 p = o - d * (o.y / d.y);
    if (std::abs(p.x) > BoxOnGround::kGroundHalf || std::abs(p.z) > BoxOnGround::kGroundHalf) return {};
    return {1, hitBox(p, l, nullptr) < 0.0f}; // the ground faces up, the light is above it
}

struct Judged {
    int litGround = 0, shadowedGround = 0, litBox = 0, wrong = 0;
    std::string where; ///< the first wrong pixels
};

/// The technique's light-0 visibility (8-bit PNG, top row first) against the hand-computed answer at every
/// pixel whose 3x3 neighbourhood agrees on the surface and its answer: the 1-px band around an edge,
/// where a sample may fall on either side, is not judged.
Judged judge(const BoxOnGround& scene, const test::DecodedPng& png) {
    const int w = png.width, h = png.height;
    const glm::mat4 viewProj =
        glm::perspective(glm::radians(BoxOnGround::kFovDeg), float(w) / float(h), 0.5f, 100.0f) *
        glm::lookAt(kEye, kTarget, glm::vec3(0, 1, 0));
    const glm::mat4 inverse = glm::inverse(viewProj);
    auto at = [&](int x, int y) { // y from the bottom, as the target's rows
        return expectedAt(scene, inverse, (float(x) + 0.5f) / float(w) * 2.0f - 1.0f,
                          (float(y) + 0.5f) / float(h) * 2.0f - 1.0f);
    };
    Judged j;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const Expected e = at(x, y);
            bool band = e.surface == 0;
            for (int dy = -1; dy <= 1 && !band; ++dy)
                for (int dx = -1; dx <= 1 && !band; ++dx) band = at(x + dx, y + dy) != e;
            if (band) continue;
            const bool lit = png.pixels[size_t(h - 1 - y) * size_t(w) + size_t(x)] >= 128;
            if (e.surface == 1) (e.lit ? j.litGround : j.shadowedGround)++;
            if (e.surface > 1 && e.lit) ++j.litBox;
            if (lit == e.lit) continue;
            if (++j.wrong <= 5)
                j.where += " (" + std::to_string(x) + ", " + std::to_string(y) + ") surface " +
                           std::to_string(e.surface) + (e.lit ? " lit" : " shadowed");
        }
    return j;
}

Judged renderAndJudge(const BoxOnGround& scene) {
    const std::string dir = test::freshTestDir("raytraced-offset");
    test::writeFile(dir + "/box.json", scene.json());
    const auto r =
        runCommand(onRayQueries() + " --api vulkan --vk-validation -t raytraced --scene " + dir +
                   "/box.json --camera view --size 96x96 --visibility " + dir + "/vis.png" + kOneFrame);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const test::DecodedPng png = test::decodePng(dir + "/vis.png");
    EXPECT_TRUE(png.ok) << png.why;
    EXPECT_EQ(png.channels, 1);
    return png.ok ? judge(scene, png) : Judged{};
}

// Negative controls, run by hand with the constants of shaders/raytraced/rays.glsl changed: without the
// offset 2909 and 3110 of the judged pixels of the scenes below are wrong (acne), with a floor of 1e-7
// (spacings 0) 180 and 225, with 1e-6 none: these scenes' coordinates are exact, so they bound the offset
// from below by little. From above they do not bound it (a floor of 5e-2 passes: a lift under a pixel,
// about 0.1 here, moves the contact shadow's start within the edge band the judge leaves out): the
// Embree comparison above does, failing 7 of the 12 scenes with a floor of 1e-2, and room and
// synthetic_draws with 8192 spacings instead of 32 (shadow outlines move).

// The light 1 degree above the horizon: n.L = 0.017 on the ground and the box's top, whose rays leave
// them almost along their own plane, the case a too small offset shadows at random (acne). Every judged
// pixel must be the hand-computed answer: the ground lit but for the box's 115-unit shadow, the faces
// that face the light lit, the others not.
TEST(RayTracedOffset, GrazingLightLeavesNoAcne) {
    REQUIRE_SECOND_DRIVER();
    const Judged j = renderAndJudge(BoxOnGround{1.0f});
    EXPECT_EQ(j.wrong, 0) << "first wrong pixels:" << j.where;
    // The view holds what the case is about (measured at 96x96: 5238 lit and 738 shadowed ground pixels,
    // 536 lit box pixels judged): a view that lost the box or its shadow would judge nothing.
    EXPECT_GT(j.litGround, 2000);
    EXPECT_GT(j.shadowedGround, 300);
    EXPECT_GT(j.litBox, 200);
}

// The box stands on the ground: its shadow starts at its foot, where the ground's rays pass through the
// box's lowest part, within the offset of where the two touch, and the lit side is lit up to the foot.
TEST(RayTracedOffset, ContactShadowStartsAtTheFoot) {
    REQUIRE_SECOND_DRIVER();
    const Judged j = renderAndJudge(BoxOnGround{35.0f});
    EXPECT_EQ(j.wrong, 0) << "first wrong pixels:" << j.where;
    // Measured at 96x96: 5625 lit and 383 shadowed ground pixels, 536 lit box pixels judged.
    EXPECT_GT(j.litGround, 2000);
    EXPECT_GT(j.shadowedGround, 150);
    EXPECT_GT(j.litBox, 200);
}

} // namespace
