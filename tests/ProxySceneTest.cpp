// "proxies" in scene files (scenes/SceneLoader.h): frames against hand-computed points, defaults,
// errors that name the file and the JSON path, and the painting-machine scene's declared proxies
// against its own meshes.
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "TestSupport.h"
#include "scenes/Error.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {
std::string sceneWith(const std::string& dir, const std::string& proxiesKey) {
    const std::string path = dir + "/scene.json";
    test::writeFile(path, R"({"name": "p", "meshes": [{"name": "ball", "generator": "sphere", "radius": 1)" +
                              proxiesKey + R"(}], "instances": [{"mesh": "ball"}]})");
    return path;
}
std::string errorOf(const std::string& path) {
    try {
        SceneLoader::load(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}
} // namespace

TEST(ProxySceneTest, DeclaredFramesDefaultsAndNone) {
    const std::string dir = test::freshTestDir("proxyscene");
    const Scene s = SceneLoader::load(sceneWith(
        dir,
        R"(, "proxies": [{"shape": "box", "position": [1, 2, 3], "rotation": [0, 90, 0], "size": [2, 3, 4]},
                              {"shape": "sphere", "size": 0.5, "diffuse": [0, 1, 0], "reflective": [0.2, 0.2, 0.2]}])"));
    const Mesh& m = s.meshes[0];
    ASSERT_TRUE(m.proxiesDeclared);
    ASSERT_EQ(m.proxies.size(), 2u);
    // Box: (1, 1, 1) -> scaled (2, 3, 4) -> Ry(90): (x, y, z) -> (z, y, -x) = (4, 3, -2) -> + (1, 2, 3).
    const glm::vec3 corner(m.proxies[0].frame * glm::vec4(1, 1, 1, 1));
    EXPECT_NEAR(glm::length(corner - glm::vec3(5, 5, 1)), 0.0f, 1e-5f);
    EXPECT_EQ(m.proxies[0].shape, ShadowProxy::Shape::Box);
    EXPECT_TRUE(m.proxies[0].diffuseFromInstance);
    EXPECT_EQ(m.proxies[1].shape, ShadowProxy::Shape::Sphere);
    EXPECT_EQ(glm::vec3(m.proxies[1].frame * glm::vec4(1, 0, 0, 1)), glm::vec3(0.5f, 0, 0));
    EXPECT_FALSE(m.proxies[1].diffuseFromInstance);
    EXPECT_EQ(m.proxies[1].diffuse, glm::vec3(0, 1, 0));
    EXPECT_EQ(m.proxies[1].reflective, glm::vec3(0.2f));

    const Scene none = SceneLoader::load(sceneWith(test::freshTestDir("proxyscene"), R"(, "proxies": [])"));
    EXPECT_TRUE(none.meshes[0].proxiesDeclared);
    EXPECT_TRUE(none.meshes[0].proxies.empty());
    const Scene fitted = SceneLoader::load(sceneWith(test::freshTestDir("proxyscene"), ""));
    EXPECT_FALSE(fitted.meshes[0].proxiesDeclared);
}

TEST(ProxySceneTest, ErrorsNameFileAndPath) {
    const std::string dir = test::freshTestDir("proxyscene");
    std::string e = errorOf(sceneWith(dir, R"(, "proxies": [{"shape": "cone", "size": 1}])"));
    EXPECT_NE(e.find("scene.json"), std::string::npos) << e;
    EXPECT_NE(e.find("proxies"), std::string::npos) << e;
    EXPECT_NE(e.find("sphere, box, cylinder"), std::string::npos) << e;
    e = errorOf(sceneWith(dir, R"(, "proxies": [{"shape": "box", "size": [1, -1, 1]}])"));
    EXPECT_NE(e.find("size"), std::string::npos) << e;
    EXPECT_NE(e.find(">= 0"), std::string::npos) << e;
    e = errorOf(sceneWith(dir, R"(, "proxies": [{"shape": "box", "size": 1, "colour": [1, 0, 0]}])"));
    EXPECT_NE(e.find("colour"), std::string::npos) << e;
    e = errorOf(sceneWith(dir, R"(, "proxies": [{"shape": "box"}])"));
    EXPECT_NE(e.find("size"), std::string::npos) << e;
    // Zero sizes are allowed (degenerate proxies are the technique's hard case, not a load error).
    EXPECT_EQ(errorOf(sceneWith(dir, R"(, "proxies": [{"shape": "sphere", "size": 0}])")), "");
}

TEST(ProxySceneTest, PaintingMachineProxiesFitTheirMeshes) {
    const Scene s = SceneLoader::load(std::string(SB_SOURCE_DIR) + "/scenes/data/painting_machine.json");
    for (const Mesh& m : s.meshes) {
        if (m.name == "box") {
            ASSERT_EQ(m.proxies.size(), 1u);
            const glm::vec3 corner(m.proxies[0].frame * glm::vec4(1, 1, 1, 1));
            EXPECT_NEAR(glm::length(corner - m.computeBounds().max), 0.0f, 1e-5f);
        }
        if (m.name == "cylinder") {
            ASSERT_EQ(m.proxies.size(), 1u);
            const glm::mat4 inv = glm::inverse(m.proxies[0].frame);
            float radial = 0.0f, axial = 0.0f;
            for (const glm::vec3& p : m.positions) {
                const glm::vec3 l(inv * glm::vec4(p, 1.0f));
                radial = std::max(radial, glm::length(glm::vec2(l)));
                axial = std::max(axial, std::abs(l.z));
            }
            // Every vertex inside, and the proxy tight (the mesh reaches its side and caps).
            EXPECT_NEAR(radial, 1.0f, 1e-4f);
            EXPECT_NEAR(axial, 1.0f, 1e-4f);
        }
    }
    EXPECT_TRUE(hasEffect(s.effects, Effect::ColourBleeding));
    EXPECT_EQ(s.lights.size(), 2u);
}
