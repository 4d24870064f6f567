// The scene's shadow exceptions, honoured by every technique and by the Embree reference: a light with
// "casts_shadows": false shadows nothing (its visibility channel is 1 on every lit surface), an instance
// with "receives_shadow": false is shadowed by no light, and a scene whose only light casts no shadow
// runs no shadow pass (the pass is skipped, with its reason, and does no GL work).
//
// The scene: a floor (casts nothing), a box on it (half extent 0.5 at (1, 0.5, 0): top face y = 1) and
// a sphere of radius 0.7 at (0.5, 3, 0) over the box. Light 0 shines along (0.5, -1, 0): the sphere's
// shadow falls on the box's top (its centre lands at (1.5, 1, 0), its disk covers the top's half
// x > 0.8) and the box's on the floor beyond it (x in [1.5, 2]). Light 1 (along (-0.3, -1, 0.2)) casts
// no shadow. Judged only on upward-facing surfaces (the floor, y = 0, and the box's top, y = 1), where
// both lights arrive, so "lit" means visibility 1 for every technique and for the reference alike.
// Tolerance 1e-3: the RGBA16F visibility target holds 1 exactly; the soft techniques' partial values
// are what the non-vacuity checks look for, never compared with it.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "RenderedFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

constexpr int kSize = 128;

std::string writeScene(const std::string& name, bool boxReceives, const std::string& lights) {
    const std::string path = test::freshTestDir("exceptions_" + name) + "/scene.json";
    test::writeFile(path, R"({"name": ")" + name + R"(",
  "meshes": [{"name": "box", "generator": "box", "half_extent": [0.5, 0.5, 0.5]},
             {"name": "ball", "generator": "sphere", "radius": 0.7, "tessellation": 24},
             {"name": "floor", "generator": "plane", "size": 10, "tessellation": 4}],
  "instances": [{"mesh": "floor", "position": [0, 0, 0], "color": [0.5, 0.5, 0.5], "casts_shadow": false},
                {"mesh": "box", "position": [1, 0.5, 0], "color": [0.6, 0.4, 0.3], "receives_shadow": )" +
                              std::string(boxReceives ? "true" : "false") + R"(},
                {"mesh": "ball", "position": [0.5, 3, 0], "color": [0.3, 0.4, 0.6]}],
  "lights": )" + lights + R"(, "ambient": [0.2, 0.2, 0.2],
  "effects": ["hard_shadows", "self_shadowing", "non_planar_receivers", "multiple_lights"],
  "cameras": [{"name": "view", "eye": [1.2, 9, 0.001], "target": [1.2, 0, 0], "up": [0, 0, -1], "fov": 40,
               "near": 0.5, "far": 50}]})");
    return path;
}

const std::string kTwoLights =
    R"([{"type": "directional", "direction": [0.5, -1, 0]},
        {"type": "directional", "direction": [-0.3, -1, 0.2], "casts_shadows": false}])";
const std::string kUnshadowedOnly =
    R"([{"type": "directional", "direction": [0.5, -1, 0], "casts_shadows": false}])";

bool onFloor(const glm::vec4& w) {
    return w.w != 0.0f && std::abs(w.y) < 1e-3f;
}
bool onBoxTop(const glm::vec4& w) {
    // The top face, away from its edges (where the rasterised depth could belong to the side).
    return w.w != 0.0f && std::abs(w.y - 1.0f) < 1e-3f && std::abs(w.x - 1.0f) < 0.45f &&
           std::abs(w.z) < 0.45f;
}

/// Techniques that draw shadows of this scene's casters on its floor (the rest: `none` draws none,
/// `occluder` has no shadow planes for generated boxes and spheres, `synthetic` is not a shadow technique).
bool shadowsTheFloor(const std::string& name) {
    return name != "none" && name != "occluder" && name != "synthetic";
}

/// `volume` with the camera's own far plane: its default infinite one writes other depths, and the
/// judging here unprojects with the camera's.
std::string specOf(const std::string& name) {
    return name == "volume" ? "volume:far=depth_clamp" : name;
}

std::vector<std::string> techniques() {
    std::vector<std::string> out;
    for (const std::string& name : TechniqueRegistry::namesOn(Api::GL))
        if (name != "synthetic") out.push_back(name);
    return out;
}

struct Judged {
    double minFloor0 = 1.0;  ///< darkest floor pixel, light 0
    double minBoxTop0 = 1.0; ///< darkest box-top pixel, light 0
    double minLight1 = 1.0;  ///< darkest upward pixel, light 1
    size_t floor = 0, boxTop = 0;
};

Judged judge(const test::RenderedFrame& f) {
    Judged j;
    for (size_t i = 0; i < f.world.size(); ++i) {
        const float v0 = f.visibility[4 * i], v1 = f.visibility[4 * i + 1];
        if (onFloor(f.world[i])) {
            ++j.floor;
            j.minFloor0 = std::min(j.minFloor0, double(v0));
            j.minLight1 = std::min(j.minLight1, double(v1));
        } else if (onBoxTop(f.world[i])) {
            ++j.boxTop;
            j.minBoxTop0 = std::min(j.minBoxTop0, double(v0));
            j.minLight1 = std::min(j.minLight1, double(v1));
        }
    }
    return j;
}

} // namespace

TEST(ShadowExceptions, EveryTechniqueLeavesAnUnshadowedLightAndANonReceiverLit) {
    const std::string scene = writeScene("exceptions", false, kTwoLights);
    for (SubmitMode mode : kAllSubmitModes) {
        Harness h(test::quickConfig(scene, "view", kSize, mode));
        for (const std::string& name : techniques()) {
            SCOPED_TRACE(name + " " + submitModeName(mode));
            std::unique_ptr<GlTechnique> t = TechniqueRegistry::create(TechniqueSpec::parse(specOf(name)));
            const Judged j = judge(test::renderOnce(h, *t));
            ASSERT_GT(j.floor, 1000u);
            ASSERT_GT(j.boxTop, 100u);
            EXPECT_GT(j.minLight1, 1.0 - 1e-3) << "light 1 casts no shadow";
            EXPECT_GT(j.minBoxTop0, 1.0 - 1e-3) << "the box receives no shadow";
            // Not vacuous: light 0 still shadows the floor behind the box.
            // (The proxies' halo is soft: its darkest point here is 0.59.)
            if (shadowsTheFloor(name)) {
                EXPECT_LT(j.minFloor0, name == "proxy" ? 0.9 : 0.5) << "light 0 shadows the floor";
            }
        }
    }
}

TEST(ShadowExceptions, TheBoxTopIsShadowedWhenItReceives) {
    // The control of the test above: the same scene with the box receiving, where the sphere's shadow
    // on its top is real (for the techniques that shadow other casters: not the planar family, which
    // shadows the floor only, nor projective, whose casters are drawn unshadowed).
    const std::string scene = writeScene("control", true, kTwoLights);
    Harness h(test::quickConfig(scene, "view", kSize));
    for (const std::string name : {"shadowmap", "cascaded", "pcss", "vsm", "esm", "evsm", "msm", "cubemap",
                                   "paraboloid", "volume", "reference"}) {
        SCOPED_TRACE(name);
        std::unique_ptr<GlTechnique> t = TechniqueRegistry::create(TechniqueSpec::parse(specOf(name)));
        const Judged j = judge(test::renderOnce(h, *t));
        EXPECT_LT(j.minBoxTop0, 0.5);
        EXPECT_GT(j.minLight1, 1.0 - 1e-3);
    }
}

TEST(ShadowExceptions, ALightThatCastsNoShadowRunsNoShadowPass) {
    const std::string scene = writeScene("unshadowed", true, kUnshadowedOnly);
    Harness h(test::quickConfig(scene, "view", kSize));
    // The passes each technique leaves out of such a frame (TechniqueInfo::passes names them).
    const std::vector<std::pair<std::string, std::vector<std::string>>> expected = {
        {"shadowmap", {"depth"}},   {"cascaded", {"depth"}},    {"pcss", {"depth"}},
        {"vsm", {"depth", "blur"}}, {"esm", {"depth", "blur"}}, {"evsm", {"depth", "blur"}},
        {"msm", {"depth", "blur"}}, {"cubemap", {"depth"}},     {"paraboloid", {"depth"}},
        {"volume", {"mark"}},       {"planar", {"shadows"}},    {"projective", {"texture", "blur"}}};
    for (const auto& [name, passes] : expected) {
        SCOPED_TRACE(name);
        std::unique_ptr<GlTechnique> t = TechniqueRegistry::create(TechniqueSpec::parse(specOf(name)));
        h.prepare(*t);
        const FrameLoads loads = h.measureLoads(*t);
        for (const std::string& pass : passes) {
            bool skipped = false;
            for (const auto& [p, reason] : loads.skipped) skipped = skipped || (p == pass && !reason.empty());
            EXPECT_TRUE(skipped) << pass << " not reported skipped";
            for (const auto& [p, work] : loads.passes) EXPECT_NE(p, pass) << pass << " was entered";
        }
        const Judged j = judge(test::renderOnce(h, *t));
        EXPECT_GT(j.minFloor0, 1.0 - 1e-3);
        EXPECT_GT(j.minBoxTop0, 1.0 - 1e-3);
    }
}

TEST(ShadowExceptions, PermutationsCarryTheExceptionsOnlyWhereTheSceneHasThem) {
    // A scene without exceptions compiles the programs it always did; one with them says so in the key.
    const std::string plain =
        writeScene("plain", true, R"([{"type": "directional", "direction": [0.5, -1, 0]}])");
    const std::string excepted = writeScene("excepted", false, kTwoLights);
    for (const std::string name : {"shadowmap", "occluder", "proxy", "projective"}) {
        SCOPED_TRACE(name);
        std::unique_ptr<GlTechnique> a = TechniqueRegistry::create(TechniqueSpec::parse(specOf(name)));
        Harness ha(test::quickConfig(plain, "view", 64));
        const std::string plainKey = test::renderOnce(ha, *a).permutation;
        EXPECT_EQ(plainKey.find("SB_NON_RECEIVERS"), std::string::npos) << plainKey;
        EXPECT_EQ(plainKey.find("SB_SHADOWLESS_LIGHTS"), std::string::npos) << plainKey;
        std::unique_ptr<GlTechnique> b = TechniqueRegistry::create(TechniqueSpec::parse(specOf(name)));
        Harness hb(test::quickConfig(excepted, "view", 64));
        const std::string key = test::renderOnce(hb, *b).permutation;
        EXPECT_NE(key.find("SB_NON_RECEIVERS"), std::string::npos) << key;
        EXPECT_NE(key.find("SB_SHADOWLESS_LIGHTS=2u"), std::string::npos) << key; // bit 1: light 1
    }
}
