// Scenes in motion (scenes/Motion.h): a frame reached by moving along the path is the frame of the scene
// frozen at that path time. The independent answer is a second harness that loads the scene already at
// time t (--time t) and prepares every technique from scratch there; the first prepares at t = 0 and
// follows the path frame by frame through Technique::sceneChanged (each technique's per-frame update,
// or setScene again by default), with the instanced submitter streaming the moved casters. Tolerance
// 0 for every technique in every submission mode: both frames run the same programs on the same scene
// state; a technique that kept a light fit, projector, silhouette, caster bound or acceleration structure
// from an earlier frame shows as changed pixels.
//
// Two paths: the built-in aircraft_day (the sun over a day, 40 aircraft flying, the camera flying from
// far over mid to top) and an orbit written here (a point light circling two turning boxes and a sphere
// over a floor, for the omni maps and the point-light paths of every technique).
// Also: the path's own arithmetic against hand values, the scene hash, the per-frame update's CPU time
// in the row, and bad motion blocks refused with their JSON pointer.
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "core/Error.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/Motion.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {

constexpr int kSize = 96;
constexpr int kPathFrames = 8;
constexpr int kStep = 5; ///< frames 0..5 along the path: t = 5/8

std::string orbitScene() {
    const std::string path = test::freshTestDir("motion_orbit") + "/orbit.json";
    test::writeFile(path, R"({"name": "orbit",
  "meshes": [{"name": "box", "generator": "box", "half_extent": [0.6, 0.6, 0.6]},
             {"name": "ball", "generator": "sphere", "radius": 0.7, "tessellation": 16},
             {"name": "floor", "generator": "plane", "size": 16, "tessellation": 4}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "casts_shadow": false},
                {"mesh": "box", "position": [1.5, 0.6, 0], "color": [0.7, 0.4, 0.3]},
                {"mesh": "box", "position": [-1.5, 0.6, 0.5], "color": [0.3, 0.6, 0.4]},
                {"mesh": "ball", "position": [0, 1.6, -1.2]}],
  "lights": [{"type": "point", "position": [4, 5, 0]}],
  "cameras": [{"name": "view", "eye": [0, 9, 7], "target": [0, 0, 0], "fov": 50, "near": 0.5, "far": 60}],
  "effects": ["hard_shadows", "self_shadowing"],
  "motion": {"frames": 8, "orbit": {"light": 0, "centre": [0, 5, 0], "radius": 4, "turns": 0.5},
             "casters": {"instances": "casters", "translate": [0.5, 0, 0.8], "yaw_deg": 70}}})");
    return path;
}

RunConfig config(const std::string& scene, const std::string& camera, SubmitMode mode, double time) {
    RunConfig c = test::quickConfig(scene, camera, kSize, mode);
    c.pathFrames = kPathFrames;
    c.pathTime = time;
    return c;
}

/// Every technique the scene's light suits (the refusals are the same at rest and in motion, and
/// are checked to be).
std::vector<std::string> techniques() {
    std::vector<std::string> out;
    for (const std::string& name : TechniqueRegistry::namesOn(Api::GL))
        if (name != "synthetic") out.push_back(name);
    return out;
}

struct Compared {
    size_t visibility = 0, colour = 0, covered = 0;
};

Compared compare(const test::RenderedFrame& a, const test::RenderedFrame& b) {
    Compared c;
    for (size_t i = 0; i < a.world.size(); ++i) {
        c.covered += a.world[i].w != 0.0f;
        for (int k = 0; k < 4; ++k)
            c.visibility += a.visibility[4 * i + size_t(k)] != b.visibility[4 * i + size_t(k)];
        for (int k = 0; k < 3; ++k) c.colour += a.colour[4 * i + size_t(k)] != b.colour[4 * i + size_t(k)];
    }
    return c;
}

void checkPath(const std::string& scene, const std::string& camera) {
    const double t = double(kStep) / double(kPathFrames);
    for (SubmitMode mode : kAllSubmitModes) {
        Harness moving(config(scene, camera, mode, -1.0));
        Harness frozen(config(scene, camera, mode, t));
        ASSERT_TRUE(moving.moving());
        ASSERT_FALSE(frozen.moving());
        for (const std::string& name : techniques()) {
            SCOPED_TRACE(name + " " + submitModeName(mode) + " on " + scene);
            auto a = TechniqueRegistry::create(name);
            auto b = TechniqueRegistry::create(name);
            bool refusedAtRest = false, refusedAtT = false;
            try {
                moving.seekPath(0);
                moving.prepare(*a);
            } catch (const Error&) {
                refusedAtRest = true;
            }
            try {
                frozen.prepare(*b);
            } catch (const Error&) {
                refusedAtT = true;
            }
            EXPECT_EQ(refusedAtRest, refusedAtT);
            if (refusedAtRest || refusedAtT) continue;
            for (int f = 0; f < kStep; ++f) moving.renderFrame(*a);
            moving.renderFrame(*a); // frame kStep, at t
            EXPECT_FLOAT_EQ(moving.pathTime(), float(t));
            test::RenderedFrame m;
            m.visibility = moving.targets().readVisibilityRGBA32F();
            m.colour = moving.targets().readColorRGBA8();
            m.world.assign(m.visibility.size() / 4, glm::vec4(0.0f));
            const std::vector<float> depth = moving.targets().readDepth();
            for (size_t i = 0; i < depth.size(); ++i) m.world[i].w = depth[i] < 1.0f ? 1.0f : 0.0f;
            frozen.renderFrame(*b);
            test::RenderedFrame s;
            s.visibility = frozen.targets().readVisibilityRGBA32F();
            s.colour = frozen.targets().readColorRGBA8();
            const Compared c = compare(m, s);
            EXPECT_EQ(c.visibility, 0u) << "visibility values differ from the frame frozen at t";
            EXPECT_EQ(c.colour, 0u) << "colour values differ from the frame frozen at t";
            EXPECT_GT(c.covered, size_t(kSize * kSize / 4));
        }
    }
}

} // namespace

TEST(Motion, AFrameAlongThePathIsTheFrameFrozenThere_Day) {
    checkPath("aircraft_day", "path");
}

TEST(Motion, AFrameAlongThePathIsTheFrameFrozenThere_Orbit) {
    checkPath(orbitScene(), "view");
}

TEST(Motion, TheFrameReallyMoves) {
    // Not vacuous: the frame at t differs from the frame at rest, for the sun and the flight alike.
    Harness rest(config("aircraft_day", "mid", SubmitMode::Retained, 0.0));
    Harness later(config("aircraft_day", "mid", SubmitMode::Retained, double(kStep) / kPathFrames));
    auto a = TechniqueRegistry::create("shadowmap");
    auto b = TechniqueRegistry::create("shadowmap");
    const test::RenderedFrame r = test::renderOnce(rest, *a);
    const test::RenderedFrame l = test::renderOnce(later, *b);
    const Compared c = compare(r, l);
    EXPECT_GT(c.visibility, 200u);
    EXPECT_GT(c.colour, 200u);
}

TEST(Motion, PathArithmeticMatchesHandValues) {
    const Scene scene = SceneLoader::load("aircraft_day");
    ASSERT_TRUE(scene.motion);
    const Motion& m = *scene.motion;
    EXPECT_EQ(m.frames, 60u);
    EXPECT_EQ(m.describe(), "sun+camera+casters");
    EXPECT_FLOAT_EQ(m.timeOfFrame(0), 0.0f);
    EXPECT_FLOAT_EQ(m.timeOfFrame(15), 0.25f);
    EXPECT_FLOAT_EQ(m.timeOfFrame(61), 1.0f / 60.0f); // the path repeats
    Scene moved = scene;
    // Noon (t = 0.5): azimuth 0 (+X), elevation 65 degrees: the light comes down from +X.
    m.apply(scene, moved, 0.5f);
    const float e = glm::radians(65.0f);
    const glm::vec3 noon = -glm::vec3(std::cos(e), std::sin(e), 0.0f);
    EXPECT_NEAR(moved.lights[0].direction.x, noon.x, 1e-6f);
    EXPECT_NEAR(moved.lights[0].direction.y, noon.y, 1e-6f);
    EXPECT_NEAR(moved.lights[0].direction.z, noon.z, 1e-6f);
    // Sunrise (t = 0): azimuth -70, elevation 12.
    m.apply(scene, moved, 0.0f);
    const float a0 = glm::radians(-70.0f), e0 = glm::radians(12.0f);
    EXPECT_NEAR(moved.lights[0].direction.z, -std::cos(e0) * std::sin(a0), 1e-6f);
    // Casters: the layout flies 12 units along -z over the path; the ground stays.
    m.apply(scene, moved, 0.25f);
    for (size_t i = 0; i < scene.instances.size(); ++i) {
        const glm::vec3 d = moved.instances[i].position - scene.instances[i].position;
        if (scene.instances[i].fromLayout)
            EXPECT_NEAR(d.z, -3.0f, 1e-5f);
        else
            EXPECT_EQ(d, glm::vec3(0.0f));
        EXPECT_NEAR(moved.instances[i].model[3].z, moved.instances[i].position.z, 1e-5f);
    }
    // The camera path: far at 0, mid at 0.5, top at 1, halfway between far and mid at 0.25.
    const CameraPreset* far = scene.findCamera("far");
    const CameraPreset* mid = scene.findCamera("mid");
    const CameraPreset quarter = m.cameraAt(0.25f);
    EXPECT_NEAR(quarter.eye.z, 0.5f * (far->eye.z + mid->eye.z), 1e-5f);
    EXPECT_NEAR(m.cameraAt(1.0f).eye.y, scene.findCamera("top")->eye.y, 1e-5f);
    ASSERT_TRUE(scene.findCamera("path"));
    EXPECT_EQ(scene.findCamera("path")->eye, far->eye);
}

TEST(Motion, TheHashCoversTheMotionAndStaysAtRest) {
    Harness a(config("aircraft_day", "mid", SubmitMode::Retained, -1.0));
    const std::string atRest = a.contentHash();
    auto t = TechniqueRegistry::create("none");
    a.prepare(*t);
    for (int f = 0; f < 3; ++f) a.renderFrame(*t);
    EXPECT_EQ(a.contentHash(), atRest) << "the row's hash describes the scene at rest, not the last frame";
    EXPECT_NE(a.scene().computeContentHash(), atRest) << "the scene itself did move";
    Scene still = SceneLoader::load("aircraft_day");
    still.motion.reset();
    EXPECT_NE(still.computeContentHash(), atRest) << "the motion is part of the hash";
}

TEST(Motion, BadMotionIsRefusedWithItsPointer) {
    const std::string dir = test::freshTestDir("motion_bad");
    struct Case {
        const char* motion;
        const char* expect;
    };
    const Case cases[] = {
        {R"({"sun": {"light": 1}})", "/motion/sun/light"},
        {R"({"orbit": {"light": 0, "centre": [0, 5, 0], "radius": 2}})",
         "an orbit moves a point or spot light"},
        {R"({"camera": ["far"]})", "at least two key cameras"},
        {R"({"camera": ["far", "nowhere"]})", "/motion/camera/1"},
        {R"({"casters": {"instances": [0]}})", "only casters move"},
        {R"({"frames": 1, "sun": {"light": 0}})", "/motion/frames"},
        {R"({})", "expected at least one of"},
        {R"({"sun": {"light": 0, "elevation_deg": [50, 10]}})", "low <= high"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.motion);
        const std::string path = dir + "/bad.json";
        test::writeFile(path, std::string(R"({"name": "bad",
  "meshes": [{"name": "box", "generator": "box"}, {"name": "floor", "generator": "plane", "size": 10}],
  "instances": [{"mesh": "floor", "casts_shadow": false}, {"mesh": "box", "position": [0, 2, 0]}],
  "cameras": [{"name": "far", "eye": [0, 5, 8], "target": [0, 0, 0]}],
  "motion": )") + c.motion + "}");
        try {
            SceneLoader::load(path);
            ADD_FAILURE() << "accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::BadInput);
            EXPECT_NE(std::string(e.what()).find(c.expect), std::string::npos) << e.what();
        }
    }
}
