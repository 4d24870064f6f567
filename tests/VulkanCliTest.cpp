// `bench --api vulkan` end to end: a measured run with the validation layer on (rows with api=vulkan,
// no validation error), and every way the Vulkan path can be refused, each one clear line with the exit
// code of its cause: the machine lacks something (no Vulkan driver, a technique or submission mode
// without a Vulkan form, a GL-only command: 3) or the input is wrong (a device index out of range,
// a Vulkan option without --api vulkan: 2). Never a crash.
#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;
const std::string kQuick = " --size 96x96 --frames 2 --warmup 1 --instances 6";
// The refusals need no timer calibration: they must come before any frame.
const std::string kNoTimer = " --no-timer-check";

std::string vulkan(const std::string& args) {
    return kBench + " --api vulkan" + kQuick + kNoTimer + " " + args;
}

/// The lines of `output` that start with `prefix`.
int linesStartingWith(const std::string& output, const std::string& prefix) {
    int n = 0;
    size_t pos = 0;
    while (pos < output.size()) {
        const size_t end = output.find('\n', pos);
        if (output.compare(pos, prefix.size(), prefix) == 0) ++n;
        if (end == std::string::npos) break;
        pos = end + 1;
    }
    return n;
}

TEST(VulkanCli, MeasuresWithTheValidationLayerOnAndRecordsTheApi) {
    const std::string dir = test::freshDir("vulkan-cli");
    const std::string csv = dir + "/r.csv";
    auto r = runCommand(kBench + " --api vulkan" + kQuick +
                        " -t none -t shadowmap:pcf=3 --vk-validation --csv " + csv);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(linesStartingWith(r.output, "bench: vulkan validation: error"), 0) << r.output;
    EXPECT_NE(r.output.find("llvmpipe"), std::string::npos) << "lavapipe is the default device:\n"
                                                            << r.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 2u);
    for (const auto& row : rows) {
        EXPECT_EQ(row.at(col::kApi), "vulkan");
        EXPECT_EQ(row.at(col::kBackend), "vulkan");
        EXPECT_EQ(row.at(col::kStatus), "ok");
        EXPECT_NE(row.at(col::kApiVersion).find("1."), std::string::npos) << row.at(col::kApiVersion);
        // The timestamps are checked against the frame as on GL; GPU times appear only when trusted.
        ASSERT_TRUE(row.at(col::kTimerVerdict) == "trusted" || row.at(col::kTimerVerdict) == "untrusted")
            << row.at(col::kTimerVerdict);
        EXPECT_NE(row.at(col::kTimerReason).find("vkCmdWriteTimestamp"), std::string::npos)
            << row.at(col::kTimerReason);
        EXPECT_EQ(row.at(col::kGpuMsMedian).empty(), row.at(col::kTimerVerdict) != "trusted")
            << row.at(col::kGpuMsMedian);
        EXPECT_NE(row.at("counter_draw_calls"), "");
    }
    EXPECT_EQ(rows[1].at(col::kTechnique), "shadowmap");
    // The census frame's work per pass: the depth pass drew the casters, the lighting pass everything.
    EXPECT_GT(std::stoi(rows[1].at("work_depth_draws")), 0) << "per-pass submitted work";
    EXPECT_GT(std::stoi(rows[1].at("work_lighting_draws")), std::stoi(rows[1].at("work_depth_draws")))
        << "the lighting pass draws the ground too";
}

TEST(VulkanCli, GlRowsSayGl) {
    const std::string dir = test::freshDir("vulkan-cli-gl");
    const std::string csv = dir + "/r.csv";
    auto r = runCommand(kBench + kQuick + " -t none --no-timer-check --csv " + csv);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].at(col::kApi), "gl");
}

TEST(VulkanCli, ATechniqueWithoutAVulkanFormIsUnsupported) {
    auto r = runCommand(vulkan("-t occluder"));
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("occluder has no Vulkan form"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--api gl"), std::string::npos) << r.output;
}

TEST(VulkanCli, GlOnlySubmissionModesAreUnsupported) {
    for (const char* mode : {"immediate", "displaylist"}) {
        auto r = runCommand(vulkan(std::string("-t none --submit ") + mode));
        EXPECT_EQ(r.exitCode, 3) << mode << "\n" << r.output;
        EXPECT_NE(r.output.find("is GL-only"), std::string::npos) << r.output;
    }
}

TEST(VulkanCli, ADeviceIndexOutOfRangeIsBadInput) {
    auto r = runCommand(vulkan("-t none --vk-device 99"));
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("99"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("llvmpipe"), std::string::npos) << "names the devices there are:\n" << r.output;
}

TEST(VulkanCli, NoVulkanDriverIsOneLineAndUnsupported) {
    // The loader finds no driver (VK_DRIVER_FILES takes precedence over VK_ICD_FILENAMES in newer loaders).
    auto r = runCommand("VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json " +
                        vulkan("-t none"));
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_EQ(linesStartingWith(r.output, "bench: error: vulkan:"), 1) << r.output;
}

TEST(VulkanCli, GlContextOptionsWithApiVulkanAreBadInput) {
    for (const std::string option : {"--backend osmesa", "--gpu 0"}) {
        auto r = runCommand(vulkan("-t none " + option));
        EXPECT_EQ(r.exitCode, 2) << option << "\n" << r.output;
        EXPECT_NE(r.output.find("--vk-device"), std::string::npos) << r.output;
    }
}

TEST(VulkanCli, VulkanOptionsWithoutApiVulkanAreBadInput) {
    auto r = runCommand(kBench + kQuick + " -t none --vk-device 0");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--api vulkan only"), std::string::npos) << r.output;
    r = runCommand(kBench + kQuick + " -t none --api metal");
    EXPECT_EQ(r.exitCode, 2) << r.output;
}

TEST(VulkanCli, AccuracyJudgesTheVulkanFrameAgainstTheSameReference) {
    // The Vulkan visibility against the Embree reference of a GL harness of the same configuration:
    // the images agree to the last bit of the half-float target (tests/GlVulkanImageVkTest.cpp), so the
    // wrong-pixel shares must agree to within a pixel's worth of 96^2 (0.011 points; 0.02 allowed).
    const std::string dir = test::freshDir("vulkan-cli-accuracy");
    const std::string csv = dir + "/a.csv";
    for (const char* api : {"gl", "vulkan"}) {
        auto r = runCommand(kBench + " accuracy --api " + api + kQuick + kNoTimer +
                            " -t shadowmap:resolution=512 --no-stability --csv " + csv);
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1].at(col::kApi), "vulkan");
    const double gl = std::stod(rows[0].at(col::kAccWrongPct)), vk = std::stod(rows[1].at(col::kAccWrongPct));
    EXPECT_NEAR(gl, vk, 0.02) << "GL " << gl << "% wrong, Vulkan " << vk << "%";
    EXPECT_GT(std::stod(rows[1].at(col::kAccEvaluated)), 0.0);
}

TEST(VulkanCli, GlOnlyCommandsSaySo) {
    // Commands that render with GL only refuse --api vulkan instead of running GL under a Vulkan label:
    // explain takes bench's options and refuses it (3); sweep and bottleneck have no such option (2).
    auto r = runCommand(kBench + " explain --api vulkan -t shadowmap");
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("renders with GL only"), std::string::npos) << r.output;
    r = runCommand(kBench + " sweep --api vulkan -t shadowmap -n 1,2");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    // ... while a sweep definition whose args ask for it measures on Vulkan (its workers draw with the
    // Vulkan forms: the bottleneck study's runs with --api vulkan).
    const std::string def = test::freshDir("vulkan-cli-sweep") + "/vk.json";
    test::writeFile(def, R"({"name": "vk", "techniques": ["none"], "scenes": ["sphere_plane"],
                             "size": ["64x64"], "frames": 1, "warmup": 0, "args": ["--api", "vulkan"]})");
    r = runCommand(kBench + " sweep " + def + " --csv " + def + ".csv");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    const CsvTable swept = CsvWriter::read(def + ".csv");
    ASSERT_EQ(swept.rows.size(), 1u) << r.output;
    const auto apiColumn = std::find(swept.header.begin(), swept.header.end(), col::kApi);
    ASSERT_NE(apiColumn, swept.header.end());
    EXPECT_EQ(swept.rows[0][size_t(apiColumn - swept.header.begin())], "vulkan");
    r = runCommand(vulkan("--scene aircraft_day -t shadowmap"));
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("motion"), std::string::npos) << r.output;
}

TEST(VulkanCli, ListSaysWhichTechniquesHaveAVulkanFormAndTheDevices) {
    auto r = runCommand(kBench + " --list");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("apis:     gl, vulkan"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("apis:     gl (no Vulkan form"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("vulkan devices"), std::string::npos) << r.output;
}

// One run loop serves both APIs (bench/lib/harness/MeasuredHarness.h): each option below was accepted and
// ignored, or the loop answered differently, under --api vulkan while the two APIs had loops of their own.

TEST(VulkanCli, SamplesAreWrittenOnVulkanAsOnGl) {
    const std::string dir = test::freshDir("vulkan-cli-samples");
    std::vector<std::string> headers;
    for (const std::string api : {"gl", "vulkan"}) {
        SCOPED_TRACE(api);
        const std::string samples = dir + "/" + api + ".csv";
        auto r = runCommand(kBench + " --api " + api + " --size 96x96 --warmup 1 --instances 6 --frames 3" +
                            kNoTimer + " -t none --samples " + samples);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const auto table = CsvWriter::read(samples);
        EXPECT_EQ(table.rows.size(), 3u) << "one row per measured frame";
        headers.push_back(test::readFile(samples).substr(0, test::readFile(samples).find('\n')));
    }
    EXPECT_EQ(headers[0], headers[1]) << "the same columns on both APIs";
}

TEST(VulkanCli, ShadersAreDumpedOnVulkanAsCompiled) {
    const std::string dir = test::freshDir("vulkan-cli-dump");
    auto r = runCommand(vulkan("-t shadowmap --dump-shaders " + dir + "/vk"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runCommand(kBench + kQuick + kNoTimer + " -t shadowmap --dump-shaders " + dir + "/gl");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    // The lighting program in the GL cache's layout: the same program and permutation folders on both
    // APIs (the permutation key is the same defines' key), the Vulkan source as glslang compiled it.
    namespace fs = std::filesystem;
    std::string vertex;
    for (const auto& e : fs::recursive_directory_iterator(dir + "/vk/shadowmap"))
        if (e.path().string().find("common-scene.vert+shadowmap-lighting.frag") != std::string::npos &&
            e.path().filename() == "vertex.vert")
            vertex = e.path().string();
    ASSERT_FALSE(vertex.empty()) << "no lighting program dumped under " << dir << "/vk/shadowmap";
    const std::string relative = vertex.substr((dir + "/vk/").size());
    EXPECT_TRUE(fs::exists(dir + "/gl/" + relative)) << relative << " has no GL counterpart";
    const std::string source = test::readFile(vertex);
    EXPECT_EQ(source.rfind("#version 450\n", 0), 0u) << source.substr(0, 80);
    EXPECT_NE(source.find("#define LIGHT_COUNT"), std::string::npos);
    EXPECT_NE(source.find("#define SB_VERTEX_SHADER 1"), std::string::npos);
    EXPECT_EQ(test::readFile(dir + "/gl/" + relative).rfind("#version 450 compatibility\n", 0), 0u);
}

TEST(VulkanCli, TheEffectsWarningIsPrintedOnceOnVulkan) {
    // painting_machine asks for soft shadows and colour bleeding; shadowmap produces neither.
    auto r = runCommand(vulkan("--scene painting_machine -t shadowmap --repeat 2"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(linesStartingWith(r.output, "bench: warning: shadowmap cannot produce soft_shadows"), 1)
        << r.output;
    r = runCommand(vulkan("--scene painting_machine -t shadowmap --strict-effects"));
    EXPECT_EQ(r.exitCode, 3) << r.output;
}

TEST(VulkanCli, ARefusingTechniqueIsARowWhileTheOthersAreMeasured) {
    const std::string csv = test::freshDir("vulkan-cli-refusal") + "/r.csv";
    auto r = runCommand(vulkan("-t none -t pcss -t shadowmap --csv " + csv));
    EXPECT_EQ(r.exitCode, 3) << r.output; // the worst of the run: pcss has no Vulkan form
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 3u) << r.output;
    std::map<std::string, std::string> status;
    for (const auto& row : rows) status[row.at(col::kTechnique)] = row.at(col::kStatus);
    EXPECT_EQ(status["none"], "ok");
    EXPECT_EQ(status["shadowmap"], "ok");
    EXPECT_EQ(status["pcss"], "unsupported");
    EXPECT_NE(r.output.find("pcss has no Vulkan form"), std::string::npos) << r.output;
}

} // namespace
