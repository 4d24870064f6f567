// --back-faces cull on Vulkan (lavapipe, validation layer on): as tests/BackFacesGLTest.cpp on GL, every
// technique's image with closed meshes' back faces culled equals its image with every face drawn, bit
// for bit, in both submission modes, and the depth and lit passes run fewer fragment shaders
// (pipeline statistics) where a closed caster is drawn. The front face comes from each pass's matrix
// and clip space (VulkanSubmitter::setCullView): a wrong one would cull the front faces and change
// the image everywhere a closed mesh is seen.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "BackFacesFrame.h"
#include "TestSupport.h"
#include "bench/lib/harness/VulkanHarness.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

constexpr int kSize = 96;

using Frame = test::BackFacesFrame;

Frame render(const std::string& technique, const std::string& scene, BackFaces backFaces, SubmitMode submit) {
    RunConfig cfg = test::quickConfig(scene, "mid", kSize, submit);
    cfg.api = RunConfig::Api::Vulkan;
    cfg.vulkan.validation = true;
    cfg.backFaces = backFaces;
    if (scene == "aircraft") cfg.sceneOptions.instances = 6;
    VulkanHarness h(cfg);
    auto t = TechniqueRegistry::createVulkan(TechniqueSpec::parse(technique));
    h.prepare(*t);
    return test::captureBackFacesFrame(h, *t);
}

struct Case {
    const char* technique;
    const char* scene;
    SubmitMode submit = SubmitMode::Retained;
};
void PrintTo(const Case& c, std::ostream* os) {
    *os << c.technique << "/" << c.scene << "/" << submitModeName(c.submit);
}

class BackFacesVkImages : public ::testing::TestWithParam<Case> {};

// Tolerance 0: the same triangles under the same rules; the back faces only ever lost the depth test.
TEST_P(BackFacesVkImages, CullEqualsDraw) {
    const Case& c = GetParam();
    const Frame drawn = render(c.technique, c.scene, BackFaces::Draw, c.submit);
    const Frame culled = render(c.technique, c.scene, BackFaces::Cull, c.submit);
    EXPECT_EQ(drawn.color, culled.color);
    EXPECT_EQ(drawn.visibility, culled.visibility);
}

const Case kCases[] = {
    {"none", "sphere_plane"},
    {"shadowmap", "sphere_plane"},
    {"shadowmap", "aircraft", SubmitMode::Instanced},
    {"pcss:bias_slope=0", "sphere_plane"},
    {"vsm", "sphere_plane"},
    {"esm", "sphere_plane", SubmitMode::Instanced},
    {"cascaded", "aircraft"},
    {"cubemap", "point_light"},
    {"paraboloid", "point_light"},
    {"volume", "sphere_plane"},
    {"volume", "aircraft", SubmitMode::Instanced},
    {"projective", "sphere_plane"},
    {"planar", "sphere_plane"},
    {"blob", "sphere_plane"},
    {"occluder", "aircraft"},
    {"proxy", "sphere_plane"},
    {"hybrid", "aircraft"},
    {"synthetic", "aircraft", SubmitMode::Instanced},
};
INSTANTIATE_TEST_SUITE_P(Techniques, BackFacesVkImages, ::testing::ValuesIn(kCases));

TEST(BackFacesVkWork, FewerFragmentsWithAClosedCaster) {
    const Frame drawn = render("shadowmap", "sphere_plane", BackFaces::Draw, SubmitMode::Retained);
    const Frame culled = render("shadowmap", "sphere_plane", BackFaces::Cull, SubmitMode::Retained);
    ASSERT_EQ(drawn.passFragments.size(), culled.passFragments.size());
    ASSERT_FALSE(drawn.passFragments.empty()) << "lavapipe has pipelineStatisticsQuery";
    for (size_t i = 0; i < drawn.passFragments.size(); ++i) {
        SCOPED_TRACE(drawn.passFragments[i].first);
        if (drawn.passFragments[i].first == "depth" || drawn.passFragments[i].first == "lighting") {
            EXPECT_LT(culled.passFragments[i].second, drawn.passFragments[i].second);
        }
    }
}

// projective's silhouette texture, as on GL: the closed sphere's back faces are culled there too.
TEST(BackFacesVkWork, ProjectiveTextureShadesFewerFragments) {
    const Frame drawn = render("projective", "sphere_plane", BackFaces::Draw, SubmitMode::Retained);
    const Frame culled = render("projective", "sphere_plane", BackFaces::Cull, SubmitMode::Retained);
    ASSERT_EQ(drawn.passFragments.size(), culled.passFragments.size());
    bool found = false;
    for (size_t i = 0; i < drawn.passFragments.size(); ++i)
        if (drawn.passFragments[i].first == "texture") {
            found = true;
            EXPECT_LT(culled.passFragments[i].second, drawn.passFragments[i].second);
        }
    EXPECT_TRUE(found) << "projective declares a texture pass";
}

} // namespace
