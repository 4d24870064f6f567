// The census frame's loads, which the bottleneck study fits frame time against, checked
// against counts made by hand from the scene: GL calls per submission mode (from the meshes' index
// counts), primitives submitted (the scene's triangles, exact by the GL spec's definition), vertex
// shader invocations (between the unique vertices and three per triangle: the spec lets an
// implementation reuse shaded vertices), and fragment shader invocations of a full-screen pass.
#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {

constexpr int kSize = 64;

FrameLoads census(SubmitMode mode, const std::string& technique) {
    Harness h(test::quickConfig("sphere_plane", "top", kSize, mode));
    auto t = TechniqueRegistry::create(TechniqueSpec::parse(technique));
    h.prepare(*t);
    return h.measureLoads(*t);
}

/// GL_CULL_FACE switched on for the closed meshes' instances and off after the draw (Submitter's
/// back-face culling): the camera "top" sees sphere_plane's sphere (closed) from outside, its plane is
/// open, so the lit pass switches it twice.
uint64_t cullFaceCalls(const Scene& scene) {
    for (const Instance& i : scene.instances)
        if (scene.meshes[i.mesh].closed) return 2;
    return 0;
}

uint64_t sceneTriangles() {
    const Scene s = SceneLoader::load("sphere_plane");
    return s.totalTriangles();
}

} // namespace

TEST(StageLoadsGLTest, ImmediateModeCountsOneCallPerVertexAttribute) {
    const Scene scene = SceneLoader::load("sphere_plane");
    // Per draw(): glBindVertexArray(0) and the empty draw that flushes the driver's vertex buffer
    // (ImmediateSubmitter.h); per instance: two uniforms, glBegin, glEnd and, per index, a normal and
    // a position (Submitter::emitImmediate).
    uint64_t calls = 2 + cullFaceCalls(scene);
    for (const Instance& i : scene.instances) calls += 2 + 2 + 2 * scene.meshes[i.mesh].indices.size();
    const FrameLoads l = census(SubmitMode::Immediate, "none");
    EXPECT_EQ(l.submitted.glCalls, calls);
    EXPECT_EQ(l.submitted.triangles, scene.totalTriangles());
    if (!l.pipeline) GTEST_SKIP() << "no GL_ARB_pipeline_statistics_query on this context";
    EXPECT_EQ(l.pipeline->primitivesSubmitted, scene.totalTriangles());
    // glBegin/glEnd streams have no indices to reuse a shaded vertex by.
    EXPECT_EQ(l.pipeline->vertexShaderInvocations, 3 * scene.totalTriangles());
}

TEST(StageLoadsGLTest, RetainedModeCountsAFewCallsPerInstance) {
    const Scene scene = SceneLoader::load("sphere_plane");
    // Per instance: two uniforms and glDrawElements; one VAO bind per mesh (instances sorted by mesh),
    // and the final glBindVertexArray(0).
    const uint64_t calls = 3 * scene.instances.size() + scene.meshes.size() + 1 + cullFaceCalls(scene);
    const FrameLoads l = census(SubmitMode::Retained, "none");
    EXPECT_EQ(l.submitted.glCalls, calls);
    if (!l.pipeline) GTEST_SKIP() << "no GL_ARB_pipeline_statistics_query on this context";
    EXPECT_EQ(l.pipeline->primitivesSubmitted, sceneTriangles());
    uint64_t unique = 0;
    for (const Instance& i : scene.instances) unique += scene.meshes[i.mesh].positions.size();
    EXPECT_GE(l.pipeline->vertexShaderInvocations, unique);
    EXPECT_LE(l.pipeline->vertexShaderInvocations, 3 * sceneTriangles());
}

TEST(StageLoadsGLTest, FullScreenPassShadesEveryPixelOnce) {
    const FrameLoads l = census(SubmitMode::Retained, "synthetic:fragment_iterations=1:draw_scene=false");
    EXPECT_EQ(l.submitted.glCalls, 0u) << "no scene draws";
    if (!l.pipeline) GTEST_SKIP() << "no GL_ARB_pipeline_statistics_query on this context";
    EXPECT_EQ(l.pipeline->primitivesSubmitted, 1u);
    EXPECT_EQ(l.pipeline->vertexShaderInvocations, 3u);
    // One invocation per covered pixel plus what the implementation shades in partly covered 2x2 quads
    // and tiles: llvmpipe counts 4x4 blocks, 66560 for 256^2 (+1.6%); 5% plus one 64-pixel tile row
    // bounds that from above at any size.
    const double pixels = double(kSize) * kSize;
    EXPECT_GE(double(l.pipeline->fragmentShaderInvocations), pixels);
    EXPECT_LE(double(l.pipeline->fragmentShaderInvocations), 1.05 * pixels + 64.0);
}
