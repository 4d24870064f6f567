// `volume` and open meshes through the bench binary: the default handles open casters, a refusal is
// bad input (exit code 2) rather than an unsupported context (3), and in a plain multi-technique run
// a technique that refuses is reported as a row while the techniques after it are still measured.
// The open mesh is the built-in teapot (its patches leave 128 open edges after welding, counted by
// ShadowVolumeMeshTest), so the cases need nothing installed; the real model files are checked where
// the packages that ship them (glmark2-data, assimp-testmodels: scripts/install-deps.sh) are present.
#include <filesystem>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;
const std::string kQuick = " --size 96x96 --frames 2 --warmup 1 --no-timer-check";

} // namespace

TEST(VolumeCli, DefaultShadowsAnOpenMesh) {
    // The teapot is open: the default (multiplicity) must measure it, exit 0, status ok.
    const std::string csv = test::freshTestDir("volumecli") + "/r.csv";
    const auto r = runCommand(kBench + " -t volume --scene teapot --instances 2 --csv " + csv + kQuick);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].at(col::kStatus), "ok");
    EXPECT_NE(rows[0].at(col::kProperties).find("open_edges=multiplicity"), std::string::npos);
    EXPECT_GT(std::stod(rows[0].at("counter_volume_triangles")), 0.0) << "the open teapot must cast";
}

TEST(VolumeCli, RefusalIsReportedAndTheNextTechniqueStillRuns) {
    // open_edges=refuse on an open mesh: a row with status failed naming the mesh, exit code 2 (the
    // scene does not meet what was asked for; the context lacks nothing), and `none` after it measured.
    const std::string csv = test::freshTestDir("volumecli") + "/r.csv";
    const auto r = runCommand(
        kBench + " -t volume:open_edges=refuse -t none --scene teapot --instances 2 --csv " + csv + kQuick);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("'teapot' has 128 open edges"), std::string::npos) << r.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 2u) << r.output;
    EXPECT_EQ(rows[0].at(col::kTechnique), "volume");
    EXPECT_EQ(rows[0].at(col::kStatus), "failed");
    EXPECT_NE(rows[0].at(col::kError).find("open_edges=refuse"), std::string::npos);
    EXPECT_EQ(rows[0].at(col::kWallMsMedian), "");
    EXPECT_EQ(rows[1].at(col::kTechnique), "none");
    EXPECT_EQ(rows[1].at(col::kStatus), "ok");
    EXPECT_EQ(rows[1].at(col::kFrames), "2");
    // The console table still has the measured technique.
    EXPECT_NE(r.output.find("\nnone "), std::string::npos) << r.output;
}

TEST(VolumeCli, ExitCodeIsTheWorstRefusal) {
    // shadowmap with a point light: unsupported here (3, no cube map); volume refusing the open teapot:
    // bad input (2); none measured. The run says 2 (bad input outranks what the context lacks, as
    // --help states), and every refusal has its row: unsupported, failed, then ok.
    const std::string csv = test::freshTestDir("volumecli") + "/r.csv";
    const auto r = runCommand(kBench + " -t shadowmap -t volume:open_edges=refuse -t none --scene teapot " +
                              "--instances 2 --light point --csv " + csv + kQuick);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 3u) << r.output;
    EXPECT_EQ(rows[0].at(col::kStatus), "unsupported");
    EXPECT_EQ(rows[1].at(col::kStatus), "failed");
    EXPECT_EQ(rows[2].at(col::kStatus), "ok");
    // Only the unsupported one: exit 3, as a single technique run always said.
    const auto alone =
        runCommand(kBench + " -t shadowmap -t none --scene teapot --instances 2 --light point" + kQuick);
    EXPECT_EQ(alone.exitCode, 3) << alone.output;
    EXPECT_NE(alone.output.find("\nnone "), std::string::npos) << alone.output;
}

TEST(VolumeCli, RealOpenModelsMatchTheReference) {
    // Real models that are open (the old default refused them): the default must shadow them as the
    // Embree reference does, looking down on the model (camera near). Multiplicity volumes are exact up
    // to rasterisation, so the error is the edge band's: bound 0.3% of judged pixels (measured 0% for
    // both at 192x192 on llvmpipe), where a leaking or missing volume is whole percent; `none` beside it
    // must be wrong by more (measured 1.0% and 0.6%), or the view holds no shadow to get right.
    const std::vector<std::string> models = {"/usr/share/glmark2/models/horse.3ds",
                                             "/usr/share/glmark2/models/cat.3ds"};
    int tried = 0;
    for (const std::string& model : models) {
        if (!std::filesystem::exists(model)) continue;
        ++tried;
        const std::string csv = test::freshTestDir("volumecli") + "/acc.csv";
        const auto r = runCommand(kBench + " accuracy -t volume -t none --model " + model +
                                  " --instances 1 --camera near --size 192x192 --frames 1 --warmup 0 "
                                  "--no-timer-check --no-stability --csv " +
                                  csv);
        ASSERT_EQ(r.exitCode, 0) << model << "\n" << r.output;
        const auto rows = test::csvRowMaps(csv);
        ASSERT_EQ(rows.size(), 2u);
        EXPECT_GT(std::stod(rows[0].at(col::kAccEvaluated)), 1000.0) << model;
        EXPECT_LT(std::stod(rows[0].at(col::kAccWrongPct)), 0.3) << model;
        EXPECT_GT(std::stod(rows[1].at(col::kAccWrongPct)), 0.4) << model << ": no shadow in view";
    }
    if (tried == 0) GTEST_SKIP() << "glmark2-data is not installed (scripts/install-deps.sh installs it)";
}

TEST(VolumeCli, MeshShaderExtractionIsRefusedWhereTheDeviceLacksIt) {
    // extrusion=mesh needs VK_EXT_mesh_shader: the system lavapipe (22.3.6) does not offer it and GL
    // has no mesh shaders; each refusal is one line naming the extension and the driver entry (exit 3,
    // the context lacks it). An open caster under a GPU silhouette path is a scene the form cannot draw
    // (exit 3, as vsm under a point light), named in the refusal.
    const auto vk =
        runCommand(kBench + " --api vulkan -t volume:extrusion=mesh --scene sphere_plane" + kQuick);
    EXPECT_EQ(vk.exitCode, 3) << vk.output;
    EXPECT_NE(vk.output.find("needs the device extension VK_EXT_mesh_shader"), std::string::npos)
        << vk.output;
    EXPECT_NE(vk.output.find("--driver mesa-25.0.7"), std::string::npos) << vk.output;
    const auto gl = runCommand(kBench + " -t volume:extrusion=mesh --scene sphere_plane" + kQuick);
    EXPECT_EQ(gl.exitCode, 3) << gl.output;
    EXPECT_NE(gl.output.find("VK_EXT_mesh_shader"), std::string::npos) << gl.output;
    const auto open = runCommand(kBench + " -t volume:extrusion=geometry --scene teapot" + kQuick);
    EXPECT_EQ(open.exitCode, 3) << open.output;
    EXPECT_NE(open.output.find("'teapot' has 128 open edges"), std::string::npos) << open.output;
}
