// Unit tests of scenes/InstanceCulling: boxes against an orthographic clip volume written out
// by hand (x, y in [-2, 2], depth along -z from 1 to 9), so each verdict follows from the planes alone.
#include <gtest/gtest.h>

#include "HandOrtho.h"
#include "scenes/InstanceCulling.h"

using namespace sb;
using sb::test::handOrtho;

namespace {

Aabb box(glm::vec3 lo, glm::vec3 hi) {
    Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

/// A mesh whose bounds are [-0.5, 0.5]^3 (three corners of the cube, one triangle): all the culls read.
Mesh unitBoxMesh() {
    Mesh m;
    m.positions = {{-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f}, {0.5f, -0.5f, 0.5f}};
    m.normals.assign(3, glm::vec3(0, 1, 0));
    m.indices = {0, 1, 2};
    return m;
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
    scene.meshes.push_back(unitBoxMesh());
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

// A scene in motion: instancesMoved moves each instance's bounds with its model matrix (the mesh's
// model-space bounds [-0.5, 0.5]^3 translated, computed by hand), and the culls follow.
TEST(InstanceCulling, MovedInstancesTakeTheirNewBounds) {
    Scene scene;
    scene.meshes.push_back(unitBoxMesh());
    Instance inst;
    inst.position = glm::vec3(0, 0, -5);
    scene.instances.push_back(inst);
    scene.updateTransforms();
    InstanceCulling culling;
    culling.setScene(scene);
    std::vector<uint8_t> keep;
    EXPECT_EQ(culling.cull(handOrtho(), DrawSet::All, CullPlanes::All, keep), 1u);

    scene.instances[0].position = glm::vec3(3, 0, -5); // wholly right of x = 2
    scene.updateTransforms();
    culling.instancesMoved(scene);
    const Aabb& b = culling.bounds()[0];
    EXPECT_FLOAT_EQ(b.min.x, 2.5f);
    EXPECT_FLOAT_EQ(b.max.x, 3.5f);
    EXPECT_FLOAT_EQ(b.min.z, -5.5f);
    EXPECT_FLOAT_EQ(b.max.z, -4.5f);
    EXPECT_EQ(culling.cull(handOrtho(), DrawSet::All, CullPlanes::All, keep), 0u);

    // An instance added since setScene: set up again, not read past the end.
    scene.instances.push_back(inst);
    scene.updateTransforms();
    culling.instancesMoved(scene);
    EXPECT_EQ(culling.bounds().size(), 2u);
    EXPECT_EQ(culling.cull(handOrtho(), DrawSet::All, CullPlanes::All, keep), 1u);
}

namespace {

/// A scene of one ground (casts nothing) and unit boxes at `centres` (cast), for the shadow culls.
Scene boxes(const std::vector<glm::vec3>& centres) {
    Scene s;
    s.meshes.push_back(unitBoxMesh());
    Instance ground;
    ground.castsShadow = false;
    s.instances.push_back(ground);
    for (const glm::vec3& c : centres) {
        Instance i;
        i.position = c;
        s.instances.push_back(i);
    }
    s.updateTransforms();
    return s;
}

} // namespace

TEST(InstanceCulling, AShadowOutsideTheViewIsCulledOneThatFallsIntoItIsNot) {
    // The view is the hand ortho: x, y in [-2, 2], z from -1 to -9 (looking down -z). A directional
    // light along -z: each box's shadow runs from it towards -z, through the receivers' bounds z in
    // [-20, -1]. Box A at (0, 0, 5) sits behind the eye, but its shadow comes down the middle of the
    // view: kept. Box B at (0, 6, -5) is above the view (y > 2), and so is its shadow under any light
    // without a y component: culled. Box C at (6, 0, 5) is beside the view and its shadow under the
    // straight light too (x > 2): culled; a light along (-0.8, 0, -1) slants its shadow into the view
    // (at x = 0 it is down at z = 5 - 6 / 0.8 = -2.5): kept.
    const Scene scene = boxes({{0, 0, 5}, {0, 6, -5}, {6, 0, 5}});
    InstanceCulling culling;
    culling.setScene(scene);
    const Aabb receivers = box({-20, -20, -20}, {20, 20, -1});
    Light straight;
    straight.direction = {0, 0, -1};
    std::vector<uint8_t> keep;
    EXPECT_EQ(culling.cullShadows(straight, receivers, handOrtho(), keep), 1u);
    EXPECT_EQ(keep, (std::vector<uint8_t>{0, 1, 0, 0})) << "the ground casts nothing; only A's shadow shows";
    Light slanted;
    slanted.direction = glm::normalize(glm::vec3(-0.8f, 0, -1));
    EXPECT_EQ(culling.cullShadows(slanted, receivers, handOrtho(), keep), 2u);
    EXPECT_EQ(keep, (std::vector<uint8_t>{0, 1, 0, 1}));
    // A point light at (0, 0, 8) fans the shadows out from the view's axis: A's straight down the
    // middle (kept), B's further up (culled), C's further out (culled).
    Light point;
    point.type = LightType::Point;
    point.position = {0, 0, 8};
    EXPECT_EQ(culling.cullShadows(point, receivers, handOrtho(), keep), 1u);
    EXPECT_EQ(keep, (std::vector<uint8_t>{0, 1, 0, 0}));
    // Nothing known of the receivers: every caster is kept.
    EXPECT_EQ(culling.cullShadows(straight, Aabb{}, handOrtho(), keep), 3u);
}

TEST(InstanceCulling, AFlattenedCasterIsCulledWhereItsShadowLands) {
    // Flattening onto the plane z = -5 along -z (a directional light straight down the view axis):
    // M maps (x, y, z, 1) to (x, y, -5, 1). Box A at (0, 0, 5) lands in the middle of the view, box
    // B at (6, 0, 5) beside it.
    glm::mat4 flatten(1.0f);
    flatten[2][2] = 0.0f;  // z' = 0 z ...
    flatten[3][2] = -5.0f; // ... - 5
    const Scene scene = boxes({{0, 0, 5}, {6, 0, 5}});
    InstanceCulling culling;
    culling.setScene(scene);
    std::vector<uint8_t> keep;
    EXPECT_EQ(culling.cullFlattened(flatten, handOrtho(), false, keep), 1u);
    EXPECT_EQ(keep, (std::vector<uint8_t>{0, 1, 0}));
    // Divided per vertex with a corner beyond the light (w <= 0): kept, whatever the other corners say.
    glm::mat4 beyond = flatten;
    beyond[0][3] = -1.0f; // w = 1 - x: the box at x = 6 has w < 0
    EXPECT_EQ(culling.cullFlattened(beyond, handOrtho(), true, keep), 2u);
}
