// Every submission mode must produce the same image (docs/ARCHITECTURE.md, "Submission"): the modes differ
// only in how the same vertices and per-instance values reach the same program. Reference: retained.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

struct Images {
    std::vector<unsigned char> color;
    std::vector<float> visibility;
    uint64_t triangles = 0;
};

Images render(const std::string& technique, SubmitMode mode, const std::string& scene) {
    RunConfig cfg = test::quickConfig(scene, "mid", 256, mode);
    if (scene == "aircraft") cfg.sceneOptions.instances = 12;
    Harness h(cfg);
    auto t = TechniqueRegistry::create(technique);
    h.prepare(*t);
    h.renderFrame(*t);
    Images img{h.targets().readColorRGBA8(), h.targets().readVisibilityRGBA32F(), 0};
    for (const auto& [name, v] : t->counters())
        if (name == "triangles") img.triangles = uint64_t(v);
    return img;
}

struct ModeCase {
    const char* technique;
    SubmitMode mode;
    const char* scene = "aircraft";
};
void PrintTo(const ModeCase& c, std::ostream* os) {
    *os << c.technique << "/" << submitModeName(c.mode) << "/" << c.scene;
}

class SubmissionModes : public ::testing::TestWithParam<ModeCase> {};

TEST_P(SubmissionModes, SameImageAsRetained) {
    const ModeCase& c = GetParam();
    Images ref = render(c.technique, SubmitMode::Retained, c.scene);
    Images got = render(c.technique, c.mode, c.scene);
    ASSERT_EQ(ref.color.size(), got.color.size());
    EXPECT_EQ(ref.triangles, got.triangles) << "every mode must submit the same triangles";
    // Tolerance: at most 1/255 per channel on at most 0.1% of pixels. The vertex data and program are
    // identical; the instanced mode reads the model matrix from attributes instead of uniforms, and
    // display lists may be re-encoded by the driver, which can move a vertex by one ulp and flip the
    // coverage of a pixel exactly on an edge. Anything beyond that is a real difference.
    size_t differentPixels = 0;
    int maxDiff = 0;
    for (size_t p = 0; p < ref.color.size() / 4; ++p) {
        int d = 0;
        for (int ch = 0; ch < 3; ++ch)
            d = std::max(d, std::abs(int(ref.color[p * 4 + ch]) - int(got.color[p * 4 + ch])));
        maxDiff = std::max(maxDiff, d);
        differentPixels += d > 1;
    }
    EXPECT_LE(differentPixels, ref.color.size() / 4 / 1000) << "max channel difference " << maxDiff;
    size_t visDiff = 0;
    for (size_t i = 0; i < ref.visibility.size(); ++i)
        visDiff += std::abs(ref.visibility[i] - got.visibility[i]) > 0.01f;
    EXPECT_LE(visDiff, ref.visibility.size() / 1000);
}

// The techniques under every mode but retained (the image they must match). A technique that unbinds a
// texture right after its last draw exposes the driver keeping immediate-mode vertices unflushed across that
// unbind (ImmediateSubmitter.h): projective's receivers are its last draw (all black before the fix), and on
// `primitives`, whose instance list ends with a cylinder in view, shadowmap's and reference's last instance
// was shaded with the default texture (600 pixels, 0.9%, shadowed). Planar and blob unbind nothing; they are
// here so that every ad-hoc technique is held to the same image in every mode.
const ModeCase kModeCases[] = {
    {"none", SubmitMode::Immediate},
    {"none", SubmitMode::DisplayList},
    {"none", SubmitMode::Instanced},
    {"shadowmap", SubmitMode::Immediate},
    {"shadowmap", SubmitMode::DisplayList},
    {"shadowmap", SubmitMode::Instanced},
    {"shadowmap", SubmitMode::Immediate, "primitives"},
    {"reference", SubmitMode::Immediate, "primitives"},
    {"planar", SubmitMode::Immediate},
    {"planar", SubmitMode::DisplayList},
    {"planar", SubmitMode::Instanced},
    {"projective", SubmitMode::Immediate},
    {"projective", SubmitMode::DisplayList},
    {"projective", SubmitMode::Instanced},
    {"projective", SubmitMode::Immediate, "primitives"},
    {"blob", SubmitMode::Immediate},
    {"blob", SubmitMode::DisplayList},
    {"blob", SubmitMode::Instanced},
};

INSTANTIATE_TEST_SUITE_P(Submit, SubmissionModes, ::testing::ValuesIn(kModeCases), [](const auto& p) {
    const std::string scene = p.param.scene;
    return std::string(p.param.technique) + "_" + submitModeName(p.param.mode) +
           (scene == "aircraft" ? "" : "_" + scene);
});

struct Counts {
    uint64_t triangles = 0, drawCalls = 0, expectedTriangles = 0, instances = 0, meshesUsed = 0;
};

Counts countFrame(SubmitMode mode) {
    RunConfig cfg = test::quickConfig("aircraft", "far", 64, mode);
    cfg.sceneOptions.instances = 12;
    Harness h(cfg);
    auto t = TechniqueRegistry::create("none");
    h.prepare(*t);
    h.renderFrame(*t);
    Counts c;
    for (const auto& [name, v] : t->counters()) {
        if (name == "triangles") c.triangles = uint64_t(v);
        if (name == "draw_calls") c.drawCalls = uint64_t(v);
    }
    std::vector<bool> used(h.scene().meshes.size(), false);
    for (const Instance& i : h.scene().instances) {
        c.expectedTriangles += h.scene().meshes[i.mesh].triangleCount();
        used[i.mesh] = true;
    }
    c.instances = h.scene().instances.size();
    c.meshesUsed = uint64_t(std::count(used.begin(), used.end(), true));
    return c;
}

TEST(Submitter, CountsWhatItDraws) {
    // Hand count: 12 aircraft + the ground, each its mesh's triangles; immediate, display list and
    // retained make one draw per instance, instanced one per mesh.
    for (SubmitMode mode : kAllSubmitModes) {
        Counts c = countFrame(mode);
        EXPECT_EQ(c.triangles, c.expectedTriangles) << submitModeName(mode);
        EXPECT_EQ(c.drawCalls, mode == SubmitMode::Instanced ? c.meshesUsed : c.instances)
            << submitModeName(mode);
    }
}

} // namespace
