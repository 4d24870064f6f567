// What `shadowmap`'s depth pass draws, on exact numbers rather than time (results/ci/lean-shadow-pass.md):
// the census frame's pipeline statistics of a shadowmap frame against a `none` frame of the same scene.
// Both draw the same lit pass (every instance once, same targets), so the difference is the depth pass
// alone: its primitives must be the casters' triangles, once per light, and nothing else (no receiver,
// no ground plane, no full-screen quad for a clear or a copy). The hand-written program of
// bench/handwritten/handshadow/ draws exactly this. Fragment counts are not pinned: llvmpipe counts fragment
// shader invocations per shaded 4x4 block, not per covered pixel, so they depend on triangle size.
#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"
#include "scenes/SceneLoader.h"

using namespace sb;

namespace {

constexpr int kSize = 64;

FrameLoads census(const std::string& technique) {
    Harness h(test::quickConfig("sphere_plane", "top", kSize));
    auto t = TechniqueRegistry::create(TechniqueSpec::parse(technique));
    h.prepare(*t);
    return h.measureLoads(*t);
}

uint64_t casterTriangles(const Scene& s) {
    uint64_t n = 0;
    for (const Instance& i : s.instances)
        if (i.castsShadow) n += s.meshes[i.mesh].indices.size() / 3;
    return n;
}

} // namespace

TEST(ShadowMapDepthPass, DrawsTheCastersOnceAndNothingElse) {
    const Scene scene = SceneLoader::load("sphere_plane");
    ASSERT_EQ(scene.lights.size(), 1u);
    const uint64_t casters = casterTriangles(scene);
    ASSERT_GT(casters, 0u);
    ASSERT_LT(casters, scene.totalTriangles()) << "the ground must be a receiver only for this test";

    const FrameLoads none = census("none");
    const FrameLoads sm = census("shadowmap:resolution=256");
    // The submitter's own count: the depth pass adds the casters' triangles and one draw per caster.
    EXPECT_EQ(sm.submitted.triangles, none.submitted.triangles + casters);
    if (!none.pipeline || !sm.pipeline) GTEST_SKIP() << "no GL_ARB_pipeline_statistics_query";
    // The GL's count, exact by the spec's definition of primitives submitted.
    EXPECT_EQ(sm.pipeline->primitivesSubmitted, none.pipeline->primitivesSubmitted + casters);
}
