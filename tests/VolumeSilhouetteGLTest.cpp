// `volume`'s GPU silhouette paths (extrusion=geometry: a geometry shader on triangles with adjacency;
// extrusion=compute: a compute shader writing vertices drawn indirectly) against the CPU path
// (extrusion=cpu, ShadowVolumeMesh::buildVolume, the independent answer). On every closed built-in
// mesh, with a point and a directional light and z-fail forced as well as the per-caster default, the
// device's volume triangle count (cleared every frame: the second frame's, read back after it) must
// equal the CPU's exactly, and the marked image must be the CPU's: the same triangles (in another
// order) count the same stencil values, and the shaders transform each vertex as extrude.vert does.
#include <string>

#include <gtest/gtest.h>

#include "SilhouetteScene.h"
#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

constexpr int kSize = 128;
/// Frames rendered before the counters are read: more than one, so a count not cleared would show.
constexpr int kFrames = 2;

struct Frame {
    double triangles = 0;
    std::vector<float> visibility;
};

Frame render(const std::string& scene, const std::string& spec) {
    Harness h(test::quickConfig(scene, "oblique", kSize));
    std::unique_ptr<GlTechnique> t = TechniqueRegistry::create(TechniqueSpec::parse(spec));
    h.prepare(*t);
    for (int i = 0; i < kFrames; ++i) h.renderFrame(*t);
    Frame f;
    f.visibility = h.targets().readVisibilityRGBA32F();
    f.triangles = test::counter(t->counters(), "volume_triangles");
    return f;
}

class VolumeSilhouette : public ::testing::TestWithParam<const char*> {};

} // namespace

TEST_P(VolumeSilhouette, DeviceCountAndImageEqualTheCpuPath) {
    const std::string generator = GetParam();
    const std::string scene = test::writeSilhouetteScene(test::freshTestDir("volumesil"), generator);
    for (const std::string base : {"volume", "volume:mode=zfail:bounded_volumes=false"}) {
        const Frame cpu = render(scene, base + ":extrusion=cpu");
        ASSERT_GT(cpu.triangles, 0.0) << generator << " " << base << ": the case must cast";
        for (const char* gpu : {"geometry", "compute"}) {
            const std::string spec = base + ":extrusion=" + gpu;
            const Frame f = render(scene, spec);
            EXPECT_EQ(f.triangles, cpu.triangles) << generator << " " << spec;
            EXPECT_EQ(test::differingSamples(f.visibility, cpu.visibility), 0) << generator << " " << spec;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(ClosedBuiltinMeshes, VolumeSilhouette,
                         ::testing::Values("sphere", "box", "cylinder", "aircraft", "lantern"),
                         [](const auto& p) { return std::string(p.param); });
