// The proxies of a scene (no GL): which proxies it yields for `proxy` and `planar`, and the frames of
// degenerate ones. Closed forms: a sanitised zero-radius sphere is a point (distances to it are
// distances to its centre up to the minimum size), a box with zero extent on one axis a flat rectangle.
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "scenes/ProxyCollection.h"

using namespace sb;

namespace {
bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}
} // namespace

TEST(ProxyCollectionTest, ZeroRadiusSphereBecomesAPoint) {
    ShadowProxy p;
    p.shape = ShadowProxy::Shape::Sphere;
    p.frame = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)), glm::vec3(0.0f));
    p.frame = ProxyCollection::sanitizeFrame(p.frame, 1e-6f);
    ASSERT_TRUE(finite(glm::inverse(p.frame)));
    const glm::vec3 q(1.0f, 2.0f, 5.0f); // 2 above the centre
    EXPECT_NEAR(glm::length(p.closestPoint(q) - q), 2.0f, 1e-5f);
    EXPECT_NEAR(glm::length(p.closestPoint(glm::vec3(1, 2, 3)) - glm::vec3(1, 2, 3)), 0.0f, 1e-5f);
}

TEST(ProxyCollectionTest, FlatBoxKeepsItsOtherAxesAndOrientation) {
    ShadowProxy p;
    p.shape = ShadowProxy::Shape::Box;
    const glm::mat4 rot = glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(0, 0, 1));
    p.frame = ProxyCollection::sanitizeFrame(glm::scale(rot, glm::vec3(2.0f, 0.0f, 1.0f)), 1e-6f);
    ASSERT_TRUE(finite(glm::inverse(p.frame)));
    EXPECT_EQ(glm::vec3(p.frame[0]), glm::vec3(rot[0]) * 2.0f); // untouched
    EXPECT_EQ(glm::vec3(p.frame[2]), glm::vec3(rot[2]));
    EXPECT_NEAR(glm::dot(glm::normalize(glm::vec3(p.frame[1])), glm::vec3(rot[1])), 1.0f, 1e-6f)
        << "the missing axis points where the unscaled one did (right-handed frame)";
    EXPECT_NEAR(glm::length(glm::vec3(p.frame[1])), 1e-6f, 1e-9f);
    // A point 3 above the flat rectangle's centre along its normal is 3 from it.
    const glm::vec3 q = 3.0f * glm::vec3(rot[1]);
    EXPECT_NEAR(glm::length(p.closestPoint(q) - q), 3.0f, 1e-5f);
}

TEST(ProxyCollectionTest, CollectFitsCastersDeclaredOrNot) {
    Scene scene;
    Mesh cube;
    cube.name = "cube";
    for (int i = 0; i < 8; ++i)
        cube.positions.emplace_back((i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f);
    cube.normals.assign(8, glm::vec3(0, 1, 0));
    Mesh declared = cube;
    declared.name = "declared";
    declared.proxiesDeclared = true;
    ShadowProxy two;
    two.shape = ShadowProxy::Shape::Sphere;
    two.diffuseFromInstance = false;
    two.diffuse = glm::vec3(0, 1, 0);
    declared.proxies = {two, two};
    scene.meshes = {cube, declared};
    Instance a;
    a.mesh = 0;
    a.position = glm::vec3(5, 0, 0);
    a.color = glm::vec3(1, 0, 0);
    Instance ground = a;
    ground.castsShadow = false; // receivers that cast nothing get no proxy
    Instance b = a;
    b.mesh = 1;
    scene.instances = {a, ground, b};
    scene.updateTransforms();
    std::vector<uint32_t> owners;
    const auto proxies = ProxyCollection::collect(scene, false, &owners);
    ASSERT_EQ(proxies.size(), 3u);
    EXPECT_EQ(owners, (std::vector<uint32_t>{scene.instances[0].objectId, scene.instances[2].objectId,
                                             scene.instances[2].objectId}));
    // The cube's tightest fit is its box (volume 8 against the sphere's 21.8 and the cylinder's 17.8
    // around it), moved by the instance, in the instance's colour.
    EXPECT_EQ(proxies[0].shape, ShadowProxy::Shape::Box);
    EXPECT_NEAR(glm::length(glm::vec3(proxies[0].frame * glm::vec4(1, 1, 1, 1)) - glm::vec3(6, 1, 1)), 0.0f,
                1e-5f);
    EXPECT_EQ(proxies[0].diffuse, glm::vec3(1, 0, 0));
    EXPECT_EQ(proxies[1].diffuse, glm::vec3(0, 1, 0)); // declared colour kept
    // proxies=fit ignores the declaration: one fitted box per caster.
    EXPECT_EQ(ProxyCollection::collect(scene, true, nullptr).size(), 2u);
}
