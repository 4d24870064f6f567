// `volume`'s GPU silhouette paths on Vulkan (extrusion=geometry: silhouette.geom on triangles with
// adjacency; extrusion=compute: silhouette.comp writing vertices drawn with vkCmdDrawIndirect)
// against Vulkan's CPU path (extrusion=cpu, ShadowVolumeMesh::buildVolume, the independent answer), with
// the validation layer on. On one scene holding every closed built-in mesh (one Vulkan frame per form
// covers them all: GL's test takes them one by one), with a point and a directional light, by default
// and with z-fail forced, the device's volume triangle count (zeroed every frame: the second
// frame's, read after its fence) must equal the CPU's exactly, and the visibility image must be the
// CPU's: the same triangles in another order count the same stencil values (GL's test,
// tests/VolumeSilhouetteGLTest.cpp, holds the GL forms to the same answer).
//
// extrusion=mesh (volume/silhouette.mesh, VK_EXT_mesh_shader) is held to the same answer on the driver
// whose lavapipe offers mesh shaders (Mesa 25.0.7), in a child process of this test on that driver
// (tests/SecondDriver.h), the CPU path drawn there too; where that driver is not installed the case is
// skipped naming the install command (VolumeCli.MeshShaderExtractionIsRefusedWhereTheDeviceLacksIt
// checks the system driver's refusal).
#include <string>

#include <gtest/gtest.h>

#include "SecondDriver.h"
#include "SilhouetteScene.h"
#include "TestSupport.h"
#include "VulkanFrame.h"

using namespace sb;

namespace {

constexpr int kSize = 128;

struct Frame {
    double triangles = 0;
    std::vector<float> visibility;
};

Frame render(const std::string& scene, const std::string& spec) {
    test::VulkanFrame frame(test::quickConfig(scene, "oblique", kSize), spec);
    // A second frame: a count the frame does not zero would show twice the CPU's.
    frame.harness().renderFrame(frame.technique());
    Frame f;
    f.visibility = frame.harness().targets().readVisibilityRGBA32F();
    f.triangles = test::counter(frame.technique().counters(), "volume_triangles");
    return f;
}

/// Every closed built-in mesh in one scene, by default and with z-fail forced: each of `forms` against
/// the CPU path on this driver, count and image exactly.
void expectFormsEqualTheCpuPath(const std::vector<const char*>& forms, const std::string& dir) {
    const std::string generator = "sphere, box, cylinder, aircraft, lantern";
    const std::string scene = test::writeSilhouetteSceneOfAll(
        test::freshTestDir(dir), {"sphere", "box", "cylinder", "aircraft", "lantern"});
    for (const std::string base : {"volume", "volume:mode=zfail:bounded_volumes=false"}) {
        const Frame cpu = render(scene, base + ":extrusion=cpu");
        ASSERT_GT(cpu.triangles, 0.0) << generator << " " << base << ": the case must cast";
        for (const char* gpu : forms) {
            const std::string spec = base + ":extrusion=" + gpu;
            const Frame f = render(scene, spec);
            EXPECT_EQ(f.triangles, cpu.triangles) << generator << " " << spec;
            EXPECT_EQ(test::differingSamples(f.visibility, cpu.visibility), 0) << generator << " " << spec;
        }
    }
}

} // namespace

TEST(VolumeSilhouetteVk, DeviceCountAndImageEqualTheCpuPathOnEveryClosedBuiltinMesh) {
    expectFormsEqualTheCpuPath({"geometry", "compute"}, "volumesilvk");
}

TEST(VolumeSilhouetteVk, MeshShaderPathEqualsTheCpuPathOnTheSecondDriver) {
    if (!test::runsOnDriver(test::kSecondDriver))
        return test::runThisTestOnDriver(test::kSecondDriver, "volume extrusion=mesh");
    expectFormsEqualTheCpuPath({"mesh"}, "volumesilvkmesh");
}
