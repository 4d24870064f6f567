// Unit tests of scenes/BackFaceCulling: the rule that says when a pass may cull a closed instance's back
// faces, on views written out by hand: a 90-degree perspective camera on the +z axis looking at the
// origin (near 1, far 10), and an orthographic volume (x, y in [-2, 2], depth along -z from 1 to 9).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "HandOrtho.h"
#include "scenes/BackFaceCulling.h"
#include "scenes/MeshGenerators.h"

using namespace sb;
using sb::test::handOrtho;

namespace {

Aabb box(glm::vec3 lo, glm::vec3 hi) {
    Aabb b;
    b.extend(lo);
    b.extend(hi);
    return b;
}

/// Perspective camera at (0, 0, eyeZ) looking down -z, near `near`, far 20.
glm::mat4 camera(float eyeZ, float near) {
    return glm::perspective(glm::radians(90.0f), 1.0f, near, 20.0f) *
           glm::lookAt(glm::vec3(0, 0, eyeZ), glm::vec3(0, 0, eyeZ - 1.0f), glm::vec3(0, 1, 0));
}

const Aabb kUnitBox = box({-1, -1, -1}, {1, 1, 1});

} // namespace

TEST(BackFaceCulling, ProjectionCentreOfPerspectiveAndOrtho) {
    glm::vec3 c;
    ASSERT_TRUE(projectionCentre(camera(5.0f, 1.0f), c));
    EXPECT_NEAR(c.x, 0.0f, 1e-5f);
    EXPECT_NEAR(c.y, 0.0f, 1e-5f);
    EXPECT_NEAR(c.z, 5.0f, 1e-4f);
    EXPECT_FALSE(projectionCentre(handOrtho(), c)); // parallel: the centre lies at infinity
}

TEST(BackFaceCulling, EyeOutsideTheBoundsCulls) {
    // The nearest corner (z = 1) lies 4 in front of the eye, the near plane 1: nothing is cut.
    EXPECT_TRUE(mayCullBackFaces(kUnitBox, {camera(5.0f, 1.0f), false}));
}

TEST(BackFaceCulling, EyeInsideTheBoundsDrawsBoth) {
    EXPECT_FALSE(mayCullBackFaces(kUnitBox, {camera(0.5f, 0.1f), false}));
    // Inside even where the depth is clamped: the walls around the eye are back faces from in there.
    EXPECT_FALSE(mayCullBackFaces(kUnitBox, {camera(0.5f, 0.1f), true}));
}

TEST(BackFaceCulling, NearPlaneCuttingTheBoundsDrawsBoth) {
    // Eye at z = 2.5, outside the box, near 2: the box's front (z = 1) lies 1.5 in front of the eye,
    // behind the near plane, which opens the mesh.
    EXPECT_FALSE(mayCullBackFaces(kUnitBox, {camera(2.5f, 2.0f), false}));
    // Clamped depth (pancaking): the near plane does not cut.
    EXPECT_TRUE(mayCullBackFaces(kUnitBox, {camera(2.5f, 2.0f), true}));
    // Near 1.4: the front lies just in front of it.
    EXPECT_TRUE(mayCullBackFaces(kUnitBox, {camera(2.5f, 1.4f), false}));
}

TEST(BackFaceCulling, OrthoCullsUnlessTheNearPlaneCuts) {
    EXPECT_TRUE(mayCullBackFaces(box({-1, -1, -5}, {1, 1, -4}), {handOrtho(), false}));
    // Straddling the near plane z = -1.
    EXPECT_FALSE(mayCullBackFaces(box({-1, -1, -1.5f}, {1, 1, -0.5f}), {handOrtho(), false}));
    EXPECT_TRUE(mayCullBackFaces(box({-1, -1, -1.5f}, {1, 1, -0.5f}), {handOrtho(), true}));
}

TEST(BackFaceCulling, EmptyBoundsNeverCull) {
    EXPECT_FALSE(mayCullBackFaces(Aabb{}, {handOrtho(), true}));
}

TEST(BackFaceCulling, MirroredMatrixTurnsTheFrontFace) {
    EXPECT_TRUE(frontFaceCounterClockwise(camera(5.0f, 1.0f), false));
    EXPECT_TRUE(frontFaceCounterClockwise(handOrtho(), false));
    const glm::mat4 mirrored = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1)) * camera(5.0f, 1.0f);
    EXPECT_FALSE(frontFaceCounterClockwise(mirrored, false));
    // An infinite far plane (volume's projection): the test stays finite.
    const glm::mat4 infinite = glm::infinitePerspective(glm::radians(60.0f), 1.0f, 0.5f) *
                               glm::lookAt(glm::vec3(0, 0, 5), glm::vec3(0), glm::vec3(0, 1, 0));
    EXPECT_TRUE(frontFaceCounterClockwise(infinite, false));
    // A y-down framebuffer (Vulkan) counts the same triangle the other way round.
    EXPECT_FALSE(frontFaceCounterClockwise(camera(5.0f, 1.0f), true));
    EXPECT_TRUE(frontFaceCounterClockwise(mirrored, true));
}

TEST(BackFaceCulling, CullerDecidesClosedUnmirroredInstancesOnly) {
    Scene s;
    s.meshes = {MeshGenerators::box(glm::vec3(1.0f), 1), MeshGenerators::plane(2.0f, 1)};
    s.meshes[0].closed = true;
    s.meshes[1].closed = false;
    Instance closed, open, mirrored, inside;
    closed.mesh = 0;
    open.mesh = 1;
    mirrored.mesh = 0;
    mirrored.model = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1));
    inside.mesh = 0;
    inside.model = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 5)); // around the eye
    s.instances = {closed, open, mirrored, inside};
    BackFaceCuller culler;
    culler.setScene(s, BackFaces::Cull);
    const CullView view{camera(5.0f, 0.5f), false};
    EXPECT_EQ(culler.setView(&view, false), 1u);
    EXPECT_EQ(culler.decisions(), (std::vector<uint8_t>{1, 0, 0, 0}));
    EXPECT_TRUE(culler.frontCounterClockwise());
    EXPECT_EQ(culler.setView(nullptr, false), 0u);
    EXPECT_FALSE(culler.culls(0));
    culler.setScene(s, BackFaces::Draw);
    EXPECT_EQ(culler.setView(&view, false), 0u);
}

// A scene in motion: the culler follows the instances' new places and mirroring without setScene.
TEST(BackFaceCulling, CullerFollowsMovedInstances) {
    Scene s;
    s.meshes = {MeshGenerators::box(glm::vec3(1.0f), 1)};
    s.meshes[0].closed = true;
    Instance a, b;
    b.model = glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0));
    s.instances = {a, b};
    BackFaceCuller culler;
    culler.setScene(s, BackFaces::Cull);
    const CullView view{camera(5.0f, 0.5f), false};
    EXPECT_EQ(culler.decisions().size(), 2u);
    EXPECT_EQ(culler.setView(&view, false), 2u);
    // a moves around the eye (both faces drawn from inside), b is mirrored (its fronts turn clockwise).
    s.instances[0].model = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 5));
    s.instances[1].model = glm::scale(glm::mat4(1.0f), glm::vec3(-1, 1, 1));
    culler.instancesMoved(s);
    EXPECT_EQ(culler.setView(&view, false), 0u);
    EXPECT_EQ(culler.decisions(), (std::vector<uint8_t>{0, 0}));
    // And back: both culled again.
    s.instances[0].model = glm::mat4(1.0f);
    s.instances[1].model = glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0));
    culler.instancesMoved(s);
    EXPECT_EQ(culler.setView(&view, false), 2u);
}
