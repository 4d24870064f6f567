// `volume`'s GPU silhouette paths (extrusion=geometry: a geometry shader on triangles with adjacency;
// extrusion=compute: a compute shader writing indices drawn indirectly) against the CPU path
// (extrusion=cpu, ShadowVolumeMesh::buildVolume, the independent answer). On every closed built-in
// mesh, with a point and a directional light and z-fail forced as well as the per-caster default, the
// device's volume triangle count (cleared every frame: the second frame's, read back after it) must
// equal the CPU's exactly, and the marked image must be the CPU's: the same triangles (in another
// order) count the same stencil values, and the shaders transform each vertex as extrude.vert does.
#include <string>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/harness/Harness.h"
#include "registry/TechniqueRegistry.h"

using namespace sb;

namespace {

constexpr int kSize = 128;
/// Frames rendered before the counters are read: more than one, so a count not cleared would show.
constexpr int kFrames = 2;

/// Two instances of `generator` (the second smaller and turned) over a ground that casts nothing, a
/// point light and an oblique directional light in general position (no face plane through them).
std::string writeScene(const std::string& dir, const std::string& generator) {
    const std::string path = dir + "/" + generator + ".json";
    test::writeFile(path, R"({"name": ")" + generator + R"(",
  "meshes": [{"name": "caster", "generator": ")" +
                              generator + R"("},
             {"name": "ground", "generator": "plane", "size": 12, "tessellation": 2}],
  "instances": [{"mesh": "ground", "position": [0, 0, 0], "casts_shadow": false},
                {"mesh": "caster", "position": [0, 1.3, 0]},
                {"mesh": "caster", "position": [2.1, 0.9, -1.4], "scale": 0.6, "rotation": [10, 35, 5]}],
  "lights": [{"type": "point", "position": [2.3, 4.1, 1.7]},
             {"type": "directional", "direction": [-0.35, -1, -0.21]}],
  "cameras": [{"name": "oblique", "eye": [-4.2, 3.3, 5.1], "target": [0.3, 0.6, -0.2], "up": [0, 1, 0],
               "fov": 50, "near": 0.1, "far": 100}]})");
    return path;
}

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

int differing(const std::vector<float>& a, const std::vector<float>& b) {
    int n = 0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) n += a[i] != b[i];
    return n + int(a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
}

class VolumeSilhouette : public ::testing::TestWithParam<const char*> {};

} // namespace

TEST_P(VolumeSilhouette, DeviceCountAndImageEqualTheCpuPath) {
    const std::string generator = GetParam();
    const std::string scene = writeScene(test::freshTestDir("volumesil"), generator);
    for (const std::string base : {"volume", "volume:mode=zfail:bounded_volumes=false"}) {
        const Frame cpu = render(scene, base + ":extrusion=cpu");
        ASSERT_GT(cpu.triangles, 0.0) << generator << " " << base << ": the case must cast";
        for (const char* gpu : {"geometry", "compute"}) {
            const std::string spec = base + ":extrusion=" + gpu;
            const Frame f = render(scene, spec);
            EXPECT_EQ(f.triangles, cpu.triangles) << generator << " " << spec;
            EXPECT_EQ(differing(f.visibility, cpu.visibility), 0) << generator << " " << spec;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(ClosedBuiltinMeshes, VolumeSilhouette,
                         ::testing::Values("sphere", "box", "cylinder", "aircraft", "lantern"),
                         [](const auto& p) { return std::string(p.param); });
