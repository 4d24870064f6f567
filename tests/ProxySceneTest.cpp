// "proxies" in scene files (scenes/SceneLoader.h): frames against hand-computed points, defaults,
// errors that name the file and the JSON path, --model dropping the replaced mesh's proxies, and the
// painting-machine scene's declared proxies against its own meshes.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "TestSupport.h"
#include "core/Error.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {

const std::string kCube = std::string(SB_SOURCE_DIR) + "/tests/data/cube.obj";
const std::string kPaintingMachine = std::string(SB_SOURCE_DIR) + "/scenes/data/painting_machine.json";

/// A scene file in `dir` with one sphere mesh "ball" (then `proxiesKey`, e.g. `, "proxies": [...]`).
std::string sceneWith(const std::string& dir, const std::string& proxiesKey) {
    const std::string path = dir + "/scene.json";
    test::writeFile(path, R"({"name": "p", "meshes": [{"name": "ball", "generator": "sphere", "radius": 1)" +
                              proxiesKey + R"(}], "instances": [{"mesh": "ball"}]})");
    return path;
}

/// The message of the error loading `path` throws ("" when it loads).
std::string errorOf(const std::string& path) {
    try {
        SceneLoader::load(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// The error of a scene whose mesh 0 declares the one proxy `proxy` (a JSON object).
std::string proxyError(const std::string& dir, const std::string& proxy) {
    return errorOf(sceneWith(dir, R"(, "proxies": [)" + proxy + "]"));
}

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

glm::vec3 apply(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec3(m * glm::vec4(p, 1.0f));
}

const Mesh* findMesh(const Scene& s, const std::string& name) {
    for (const Mesh& m : s.meshes)
        if (m.name == name) return &m;
    return nullptr;
}

} // namespace

TEST(ProxySceneTest, BoxFrameIsTranslateRotateXyzScale) {
    const std::string dir = test::freshTestDir("proxyscene");
    const Scene s = SceneLoader::load(sceneWith(
        dir,
        R"(, "proxies": [{"shape": "box", "position": [1, 2, 3], "rotation": [90, 0, 90], "size": [2, 3, 4]}])"));
    const Mesh& m = s.meshes[0];
    ASSERT_TRUE(m.proxiesDeclared);
    ASSERT_EQ(m.proxies.size(), 1u);
    EXPECT_EQ(m.proxies[0].shape, ShadowProxy::Shape::Box);
    // By hand, R = Rx(90) * Ry(0) * Rz(90): (1, 1, 1) -> S (2, 3, 4) -> Rz(90): (x, y, z) -> (-y, x, z)
    // = (-3, 2, 4) -> Rx(90): (x, y, z) -> (x, -z, y) = (-3, -4, 2) -> + (1, 2, 3) = (-2, -2, 5).
    // (The other order, Rz * Rx, would give (5, 4, 6); scaling after the rotation another point.)
    EXPECT_NEAR(glm::length(apply(m.proxies[0].frame, {1, 1, 1}) - glm::vec3(-2, -2, 5)), 0.0f, 1e-5f);
    // (-1, -1, -1) -> (-2, -3, -4) -> (3, -2, -4) -> (3, 4, -2) -> (4, 6, 1).
    EXPECT_NEAR(glm::length(apply(m.proxies[0].frame, {-1, -1, -1}) - glm::vec3(4, 6, 1)), 0.0f, 1e-5f);
    // The centre is the position.
    EXPECT_NEAR(glm::length(apply(m.proxies[0].frame, {0, 0, 0}) - glm::vec3(1, 2, 3)), 0.0f, 1e-6f);
}

TEST(ProxySceneTest, ScalarSizeDefaultsAndColours) {
    const std::string dir = test::freshTestDir("proxyscene");
    const Scene s = SceneLoader::load(sceneWith(dir, R"(, "proxies": [
        {"shape": "sphere", "size": 0.5},
        {"shape": "cylinder", "size": [1, 2, 3], "diffuse": [0, 1, 0.25], "reflective": [0.2, 0.3, 0.4]}])"));
    const Mesh& m = s.meshes[0];
    ASSERT_EQ(m.proxies.size(), 2u);
    // A scalar size scales all three axes; no position or rotation: the frame is S(0.5).
    const ShadowProxy& sphere = m.proxies[0];
    EXPECT_EQ(sphere.shape, ShadowProxy::Shape::Sphere);
    EXPECT_EQ(sphere.frame, glm::scale(glm::mat4(1.0f), glm::vec3(0.5f)));
    EXPECT_EQ(apply(sphere.frame, {0, 0, 1}), glm::vec3(0, 0, 0.5f));
    // No "diffuse": the instance's colour; "reflective" defaults to black.
    EXPECT_TRUE(sphere.diffuseFromInstance);
    EXPECT_EQ(sphere.reflective, glm::vec3(0.0f));
    const ShadowProxy& cylinder = m.proxies[1];
    EXPECT_EQ(cylinder.shape, ShadowProxy::Shape::Cylinder);
    EXPECT_EQ(apply(cylinder.frame, {1, 1, 1}), glm::vec3(1, 2, 3));
    EXPECT_FALSE(cylinder.diffuseFromInstance);
    EXPECT_EQ(cylinder.diffuse, glm::vec3(0, 1, 0.25f));
    EXPECT_EQ(cylinder.reflective, glm::vec3(0.2f, 0.3f, 0.4f));
}

TEST(ProxySceneTest, EmptyListDeclaresNoneAndNoKeyDeclaresNothing) {
    const Scene none = SceneLoader::load(sceneWith(test::freshTestDir("proxyscene"), R"(, "proxies": [])"));
    EXPECT_TRUE(none.meshes[0].proxiesDeclared);
    EXPECT_TRUE(none.meshes[0].proxies.empty());
    const Scene fitted = SceneLoader::load(sceneWith(test::freshTestDir("proxyscene"), ""));
    EXPECT_FALSE(fitted.meshes[0].proxiesDeclared);
    EXPECT_TRUE(fitted.meshes[0].proxies.empty());
}

TEST(ProxySceneTest, ZeroSizesAreAllowed) {
    // Degenerate proxies are the technique's hard case, not a load error.
    const std::string dir = test::freshTestDir("proxyscene");
    const Scene s = SceneLoader::load(sceneWith(dir, R"(, "proxies": [{"shape": "sphere", "size": 0},
        {"shape": "box", "position": [1, 1, 1], "size": [2, 0, 2]}])"));
    ASSERT_EQ(s.meshes[0].proxies.size(), 2u);
    EXPECT_EQ(apply(s.meshes[0].proxies[0].frame, {1, 1, 1}), glm::vec3(0.0f));
    EXPECT_EQ(apply(s.meshes[0].proxies[1].frame, {1, 1, 1}), glm::vec3(3, 1, 3));
}

TEST(ProxySceneTest, EveryKindOfMeshTakesTheKey) {
    for (const char* g : {"sphere", "box", "cylinder", "plane", "aircraft", "teapot", "lantern"}) {
        const std::string json =
            std::string(R"({"meshes": [{"name": "m", "generator": ")") + g +
            R"(", "proxies": [{"shape": "box", "size": 1}]}], "instances": [{"mesh": "m"}]})";
        const Scene s = SceneLoader::parse(json, "test.json");
        EXPECT_TRUE(s.meshes[0].proxiesDeclared) << g;
        EXPECT_EQ(s.meshes[0].proxies.size(), 1u) << g;
    }
    const std::string model =
        R"({"meshes": [{"name": "m", "file": ")" + kCube +
        R"(", "proxies": [{"shape": "sphere", "size": 2}]}], "instances": [{"mesh": "m"}]})";
    const Scene s = SceneLoader::parse(model, "test.json");
    ASSERT_EQ(s.meshes[0].proxies.size(), 1u);
    EXPECT_EQ(apply(s.meshes[0].proxies[0].frame, {1, 0, 0}), glm::vec3(2, 0, 0));
}

TEST(ProxySceneTest, ErrorsNameFileAndPath) {
    const std::string dir = test::freshTestDir("proxyscene");
    const std::string file = dir + "/scene.json";
    struct Case {
        const char* proxy;
        const char* path;     ///< the JSON path the error names
        const char* expected; ///< part of what it says
    };
    const Case cases[] = {
        {R"({"shape": "cone", "size": 1})", "/meshes/0/proxies/0/shape", "one of sphere, box, cylinder"},
        {R"({"shape": 3, "size": 1})", "/meshes/0/proxies/0/shape", "one of sphere, box, cylinder"},
        {R"({"size": 1})", "/meshes/0/proxies/0", "missing required key \"shape\""},
        {R"({"shape": "box", "size": [1, -1, 1]})", "/meshes/0/proxies/0/size", ">= 0"},
        {R"({"shape": "box", "size": -0.5})", "/meshes/0/proxies/0/size", ">= 0"},
        {R"({"shape": "box", "size": 1e39})", "/meshes/0/proxies/0/size", "finite"},
        {R"({"shape": "box", "size": "big"})", "/meshes/0/proxies/0/size",
         "a number or an array of 3 numbers"},
        {R"({"shape": "box", "size": [1, 2]})", "/meshes/0/proxies/0/size",
         "a number or an array of 3 numbers"},
        {R"({"shape": "box"})", "/meshes/0/proxies/0", "missing required key \"size\""},
        {R"({"shape": "box", "size": 1, "colour": [1, 0, 0]})", "/meshes/0/proxies/0/colour",
         "unknown key (valid keys: shape, position, rotation, size, diffuse, reflective)"},
        {R"({"shape": "box", "size": 1, "position": [0, 1]})", "/meshes/0/proxies/0/position", "3 numbers"},
        {R"({"shape": "box", "size": 1, "rotation": [0, 1e40, 0]})", "/meshes/0/proxies/0/rotation",
         "finite"},
        {R"({"shape": "box", "size": 1, "diffuse": [1, 0, 2]})", "/meshes/0/proxies/0/diffuse", "[0, 1]"},
        {R"({"shape": "box", "size": 1, "reflective": "red"})", "/meshes/0/proxies/0/reflective",
         "3 numbers"},
        {R"("box")", "/meshes/0/proxies/0", "an object"},
    };
    for (const Case& c : cases) {
        const std::string e = proxyError(dir, c.proxy);
        EXPECT_TRUE(contains(e, file + ": " + std::string(c.path) + ": ")) << c.proxy << "\n" << e;
        EXPECT_TRUE(contains(e, c.expected)) << c.proxy << "\n" << e;
        EXPECT_FALSE(contains(e, "\n")) << c.proxy << "\n" << e;
    }
    // The second entry of the list is named by its index.
    const std::string e = errorOf(
        sceneWith(dir, R"(, "proxies": [{"shape": "box", "size": 1}, {"shape": "pyramid", "size": 1}])"));
    EXPECT_TRUE(contains(e, file + ": /meshes/0/proxies/1/shape: expected one of sphere, box, cylinder"))
        << e;
    // Not a list.
    EXPECT_TRUE(contains(errorOf(sceneWith(dir, R"(, "proxies": {"shape": "box"})")),
                         file + ": /meshes/0/proxies: expected an array"));
}

TEST(ProxySceneTest, ModelOptionDropsTheReplacedMeshsProxies) {
    const std::string json = R"({"meshes": [
        {"name": "ball", "generator": "sphere", "proxies": [{"shape": "sphere", "size": 1}]},
        {"name": "crate", "generator": "box", "proxies": [{"shape": "box", "size": 1}]}],
        "instances": [{"mesh": "crate"}],
        "layout": {"mesh": "ball", "count": 2, "region": [[0, 0, 0], [1, 1, 1]]}})";
    const Scene plain = SceneLoader::parse(json, "test.json");
    EXPECT_TRUE(plain.meshes[0].proxiesDeclared);
    EXPECT_EQ(plain.meshes[0].proxies.size(), 1u);
    SceneOptions options;
    options.modelPath = kCube;
    const Scene replaced = SceneLoader::parse(json, "test.json", options);
    EXPECT_FALSE(replaced.meshes[0].proxiesDeclared);
    EXPECT_TRUE(replaced.meshes[0].proxies.empty());
    // The other mesh keeps its own.
    EXPECT_TRUE(replaced.meshes[1].proxiesDeclared);
    EXPECT_EQ(replaced.meshes[1].proxies.size(), 1u);
}

TEST(ProxySceneTest, PaintingMachineIsBuiltIn) {
    const auto names = SceneLoader::listBuiltinScenes();
    EXPECT_NE(std::find(names.begin(), names.end(), "painting_machine"), names.end());
    const Scene s = SceneLoader::load("painting_machine");
    EXPECT_EQ(s.name, "painting_machine");
    EXPECT_EQ(s.computeContentHash(), SceneLoader::load(kPaintingMachine).computeContentHash());
}

TEST(ProxySceneTest, PaintingMachineBoxProxyIsTheBox) {
    const Scene s = SceneLoader::load(kPaintingMachine);
    const Mesh* box = findMesh(s, "box");
    ASSERT_NE(box, nullptr);
    ASSERT_TRUE(box->proxiesDeclared);
    ASSERT_EQ(box->proxies.size(), 1u);
    const ShadowProxy& p = box->proxies[0];
    EXPECT_EQ(p.shape, ShadowProxy::Shape::Box);
    EXPECT_TRUE(p.diffuseFromInstance);
    const Aabb bounds = box->computeBounds();
    EXPECT_NEAR(glm::length(apply(p.frame, {1, 1, 1}) - bounds.max), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(apply(p.frame, {-1, -1, -1}) - bounds.min), 0.0f, 1e-5f);
}

TEST(ProxySceneTest, PaintingMachineCylinderProxyHoldsTheCylinder) {
    const Scene s = SceneLoader::load(kPaintingMachine);
    const Mesh* cylinder = findMesh(s, "cylinder");
    ASSERT_NE(cylinder, nullptr);
    ASSERT_TRUE(cylinder->proxiesDeclared);
    ASSERT_EQ(cylinder->proxies.size(), 1u);
    const ShadowProxy& p = cylinder->proxies[0];
    EXPECT_EQ(p.shape, ShadowProxy::Shape::Cylinder);
    ASSERT_FALSE(cylinder->positions.empty());
    const glm::mat4 inv = glm::inverse(p.frame);
    float radial = 0.0f, axial = 0.0f;
    for (const glm::vec3& v : cylinder->positions) {
        const glm::vec3 l = apply(inv, v);
        EXPECT_LE(glm::length(glm::vec2(l)), 1.0f + 1e-4f) << v.x << " " << v.y << " " << v.z;
        EXPECT_LE(std::abs(l.z), 1.0f + 1e-4f) << v.x << " " << v.y << " " << v.z;
        radial = std::max(radial, glm::length(glm::vec2(l)));
        axial = std::max(axial, std::abs(l.z));
    }
    // And tight: the mesh reaches the proxy's side and both caps.
    EXPECT_NEAR(radial, 1.0f, 1e-4f);
    EXPECT_NEAR(axial, 1.0f, 1e-4f);
}

TEST(ProxySceneTest, PaintingMachineSceneSetUp) {
    const Scene s = SceneLoader::load(kPaintingMachine);
    // Spheres and the ground get no declaration (the technique fits the spheres).
    for (const char* name : {"sphere", "ground"}) {
        const Mesh* m = findMesh(s, name);
        ASSERT_NE(m, nullptr) << name;
        EXPECT_FALSE(m->proxiesDeclared) << name;
    }
    EXPECT_TRUE(hasEffect(s.effects, Effect::SoftShadows));
    EXPECT_TRUE(hasEffect(s.effects, Effect::ColourBleeding));
    // Two coloured directional lights, both well above the horizon (over 30 degrees).
    ASSERT_EQ(s.lights.size(), 2u);
    for (const Light& l : s.lights) {
        EXPECT_EQ(l.type, LightType::Directional);
        EXPECT_LT(l.direction.y, -std::sin(glm::radians(30.0f)));
    }
    EXPECT_NE(s.lights[0].color, s.lights[1].color);
    // The ground receives but casts no shadow; the layout is 24 spheres.
    int ground = 0, spheres = 0;
    for (const Instance& inst : s.instances) {
        if (s.meshes[inst.mesh].name == "ground") {
            ++ground;
            EXPECT_FALSE(inst.castsShadow);
        }
        if (inst.fromLayout) {
            ++spheres;
            EXPECT_EQ(s.meshes[inst.mesh].name, "sphere");
        }
    }
    EXPECT_EQ(ground, 1);
    EXPECT_EQ(spheres, 24);
    // far, mid, near at decreasing distances from their targets, and top.
    for (const char* cam : {"far", "mid", "near", "top"}) ASSERT_NE(s.findCamera(cam), nullptr) << cam;
    auto distance = [&](const char* cam) {
        const CameraPreset& c = *s.findCamera(cam);
        return glm::length(c.target - c.eye);
    };
    EXPECT_GT(distance("far"), distance("mid"));
    EXPECT_GT(distance("mid"), distance("near"));
}
