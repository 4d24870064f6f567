// Unit tests of techniques/common/InstanceCulling: boxes against an orthographic clip volume written out
// by hand (x, y in [-2, 2], depth along -z from 1 to 9), so each verdict follows from the planes alone.
#include <gtest/gtest.h>

#include "techniques/common/InstanceCulling.h"

using namespace sb;

namespace {

// glm::ortho(-2, 2, -2, 2, 1, 9) by its definition: x' = x / 2, y' = y / 2, z' = -(z + 5) / 4, w = 1.
glm::mat4 handOrtho() {
    glm::mat4 m(0.0f); // column-major: m[column][row]
    m[0][0] = 0.5f;
    m[1][1] = 0.5f;
    m[2][2] = -0.25f;
    m[3][2] = -1.25f;
    m[3][3] = 1.0f;
    return m;
}

Aabb box(glm::vec3 lo, glm::vec3 hi) {
    Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

} // namespace

TEST(InstanceCulling, BoxesInsideOutsideAndStraddling) {
    const glm::mat4 vp = handOrtho();
    EXPECT_TRUE(InstanceCulling::mayReach(box({-1, -1, -5}, {1, 1, -4}), vp, CullPlanes::All));
    // Wholly left of x = -2, wholly above y = 2, wholly beyond the far plane z = -9.
    EXPECT_FALSE(InstanceCulling::mayReach(box({-4, -1, -5}, {-2.1f, 1, -4}), vp, CullPlanes::All));
    EXPECT_FALSE(InstanceCulling::mayReach(box({-1, 2.5f, -5}, {1, 3, -4}), vp, CullPlanes::All));
    EXPECT_FALSE(InstanceCulling::mayReach(box({-1, -1, -12}, {1, 1, -9.5f}), vp, CullPlanes::All));
    // Straddling the left plane: kept.
    EXPECT_TRUE(InstanceCulling::mayReach(box({-3, -1, -5}, {-1.9f, 1, -4}), vp, CullPlanes::All));
    // Between the light and the near plane (z > -1): culled by All, kept by SidesAndFar (a caster
    // towards the light still shadows what the map covers).
    const Aabb nearer = box({-1, -1, 0}, {1, 1, 3});
    EXPECT_FALSE(InstanceCulling::mayReach(nearer, vp, CullPlanes::All));
    EXPECT_TRUE(InstanceCulling::mayReach(nearer, vp, CullPlanes::SidesAndFar));
    // Outside a side plane is culled in both modes.
    EXPECT_FALSE(InstanceCulling::mayReach(box({5, -1, 0}, {6, 1, 3}), vp, CullPlanes::SidesAndFar));
    // An empty box reaches nothing.
    EXPECT_FALSE(InstanceCulling::mayReach(Aabb{}, vp, CullPlanes::All));
}

TEST(InstanceCulling, MaskFollowsTheDrawSetAndTheFrustum) {
    Scene scene;
    Mesh m;
    m.positions = {{-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, {0.5f, -0.5f, 0.5f}};
    m.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
    m.indices = {0, 1, 2};
    scene.meshes.push_back(m);
    for (glm::vec3 p : {glm::vec3(0, 0, -5), glm::vec3(10, 0, -5), glm::vec3(0, 0, -5)}) {
        Instance inst;
        inst.position = p;
        scene.instances.push_back(inst);
    }
    scene.instances[2].castsShadow = false; // a receiver inside the frustum
    scene.updateTransforms();

    InstanceCulling culling;
    culling.setScene(scene);
    std::vector<uint8_t> keep;
    // Casters: the first (inside) kept, the second (x = 10) culled, the receiver not in the set.
    EXPECT_EQ(culling.cull(handOrtho(), DrawSet::Casters, CullPlanes::All, keep), 1u);
    EXPECT_EQ(keep, (std::vector<uint8_t>{1, 0, 0}));
    EXPECT_EQ(culling.count(DrawSet::Casters), 2u);
    EXPECT_EQ(culling.cull(handOrtho(), DrawSet::All, CullPlanes::All, keep), 2u);
    EXPECT_EQ(keep, (std::vector<uint8_t>{1, 0, 1}));
}
