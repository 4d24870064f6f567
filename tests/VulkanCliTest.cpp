// `bench --api vulkan` end to end: a measured run with the validation layer on (rows with api=vulkan,
// no validation error), and every way the Vulkan path can be refused, each one clear line with the exit
// code of its cause: the machine lacks something (no Vulkan driver, a technique or submission mode
// without a Vulkan form, a GL-only command: 3) or the input is wrong (a device index out of range,
// a Vulkan option without --api vulkan: 2). Never a crash.
#include <cctype>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/ResultColumns.h"
#include "registry/TechniqueRegistry.h"

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

/// How often `needle` occurs in `text`.
size_t occurrences(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
}

TEST(VulkanCli, EveryTechniqueHasAVulkanForm) {
    // The registry's every row has a Vulkan form: --list says "gl, vulkan" for each technique with a GL
    // form, "vulkan (no GL form: <why>)" for the others (raytraced: GL has no ray queries), and never
    // "no Vulkan form".
    auto r = runCommand(kBench + " --list");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string techniques = r.output.substr(0, r.output.find("\nscenes:"));
    EXPECT_EQ(techniques.find("no Vulkan form"), std::string::npos) << techniques;
    EXPECT_EQ(occurrences(techniques, "apis:     gl, vulkan"), TechniqueRegistry::namesOn(Api::GL).size())
        << techniques;
    EXPECT_EQ(occurrences(techniques, "apis:     vulkan (no GL form: "),
              TechniqueRegistry::names().size() - TechniqueRegistry::namesOn(Api::GL).size())
        << techniques;
    EXPECT_EQ(TechniqueRegistry::namesOn(Api::Vulkan).size(), TechniqueRegistry::names().size());
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
    // Commands that render with GL only refuse --api vulkan instead of running GL under a Vulkan label.
    // bench sweep has no --api option (2): a sweep file names the API (ASweepRunsWhereItsFileSays).
    auto r = runCommand(kBench + " sweep --api vulkan -t shadowmap -n 1,2");
    EXPECT_EQ(r.exitCode, 2) << r.output;
}

TEST(VulkanCli, ASceneInMotionMovesOnVulkanAsOnGl) {
    // The harness moves the casters, the sun and the camera at the start of each frame on both APIs:
    // the rows say the scene moved, cost the motion inside the frame and count the same work.
    const std::string csv = test::freshDir("vulkan-cli-motion") + "/r.csv";
    for (const std::string api : {"gl", "vulkan"}) {
        auto r =
            runCommand(kBench + " --api " + api + kQuick + kNoTimer +
                       " --scene aircraft_day --camera path -t shadowmap:resolution=512 -t volume --csv " +
                       csv + (api == "vulkan" ? " --vk-validation" : ""));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(linesStartingWith(r.output, "bench: vulkan validation: error"), 0) << r.output;
    }
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 4u);
    for (size_t i = 0; i < 2; ++i) {
        const auto &gl = rows[i], &vk = rows[i + 2];
        SCOPED_TRACE(gl.at(col::kTechnique));
        EXPECT_EQ(vk.at(col::kApi), "vulkan");
        EXPECT_NE(vk.at(col::kMotion), "");
        EXPECT_EQ(vk.at(col::kMotion), gl.at(col::kMotion));
        EXPECT_NE(vk.at(col::kMotionMsMedian), "") << "the motion's share of the frame";
        for (const auto& [column, value] : gl)
            if (column.rfind("counter_", 0) == 0) EXPECT_EQ(vk.at(column), value) << column;
    }
}

/// Per pass of each technique, `bench explain`'s work line ("ran  4 draws, 8384 triangles, 15 GL calls,
/// 5840 vertices, 11536 fragments") as its numbers: draws, triangles, API calls, vertices, fragments.
std::map<std::string, std::vector<double>> explainedPasses(const std::string& output) {
    std::map<std::string, std::vector<double>> out;
    std::istringstream lines(output);
    std::string line, technique;
    while (std::getline(lines, line)) {
        if (!line.empty() && line[0] != ' ') technique = line.substr(0, line.find(' '));
        const size_t ran = line.find("  ran  ");
        if (line.rfind("    ", 0) != 0 || ran == std::string::npos) continue;
        std::istringstream pass(line);
        std::string name;
        pass >> name;
        std::vector<double> numbers;
        std::istringstream work(line.substr(ran + 7));
        std::string word;
        while (work >> word)
            if (std::isdigit(static_cast<unsigned char>(word[0]))) numbers.push_back(std::stod(word));
        out[technique + "/" + name] = numbers;
    }
    return out;
}

TEST(VulkanCli, ExplainCountsEachPassOnVulkanAsOnGl) {
    // The census frame on Vulkan: the submitter's draws and a pipeline-statistics query per pass, the
    // same output as GL's. Draws, triangles and vertices count the application's work: equal; fragments
    // are the rasterisers' own (the two drivers' edge rules differ by a few per million).
    const std::string args = " --size 96x96 --scene sphere_plane -t shadowmap -t volume -t cubemap";
    auto gl = runCommand(kBench + " explain" + args);
    ASSERT_EQ(gl.exitCode, 0) << gl.output;
    auto vk = runCommand(kBench + " explain --api vulkan --vk-validation" + args);
    ASSERT_EQ(vk.exitCode, 0) << vk.output;
    EXPECT_EQ(linesStartingWith(vk.output, "bench: vulkan validation: error"), 0) << vk.output;
    const auto glPasses = explainedPasses(gl.output), vkPasses = explainedPasses(vk.output);
    // shadowmap: depth, lighting; volume: ambient, mark, lighting; cubemap: depth, lighting
    ASSERT_EQ(glPasses.size(), 7u) << gl.output;
    ASSERT_EQ(vkPasses.size(), glPasses.size()) << vk.output;
    for (const auto& [pass, g] : glPasses) {
        SCOPED_TRACE(pass);
        ASSERT_EQ(vkPasses.count(pass), 1u);
        const std::vector<double>& v = vkPasses.at(pass);
        ASSERT_EQ(g.size(), 5u);
        ASSERT_EQ(v.size(), 5u) << "pipeline statistics on Vulkan";
        EXPECT_EQ(v[0], g[0]) << "draws";
        EXPECT_EQ(v[1], g[1]) << "triangles";
        EXPECT_EQ(v[3], g[3]) << "vertices";
        EXPECT_NEAR(v[4], g[4], 1e-4 * g[4] + 64) << "fragments";
    }
}

TEST(VulkanCli, ASweepRunsOnTheApiItsFileNames) {
    // "api" is an axis (or, as one value, a fixed option) of the sweep format; "args" may say it too.
    const std::string dir = test::freshDir("vulkan-cli-sweep");
    test::writeFile(dir + "/axis.json", R"({"name": "axis", "techniques": ["none", "volume"],
        "scenes": ["sphere_plane"], "size": ["64x64"], "frames": 2, "warmup": 1, "api": ["gl", "vulkan"]})");
    test::writeFile(dir + "/args.json",
                    R"({"name": "args", "techniques": ["none"], "scenes": ["sphere_plane"],
        "size": ["64x64"], "frames": 2, "warmup": 1, "args": ["--api", "vulkan", "--no-timer-check"]})");
    auto r = runCommand(kBench + " sweep " + dir + "/axis.json --csv " + dir + "/axis.csv");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    r = runCommand(kBench + " sweep " + dir + "/args.json --csv " + dir + "/args.csv");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto axis = test::csvRowMaps(dir + "/axis.csv");
    ASSERT_EQ(axis.size(), 4u);
    std::map<std::string, std::string> drawCalls; // technique/api -> counter_draw_calls
    for (const auto& row : axis) {
        EXPECT_EQ(row.at(col::kStatus), "ok");
        drawCalls[row.at(col::kTechnique) + "/" + row.at(col::kApi)] = row.at("counter_draw_calls");
    }
    ASSERT_EQ(drawCalls.size(), 4u) << "each technique on gl and on vulkan";
    EXPECT_EQ(drawCalls["volume/vulkan"], drawCalls["volume/gl"]);
    const auto args = test::csvRowMaps(dir + "/args.csv");
    ASSERT_EQ(args.size(), 1u);
    EXPECT_EQ(args[0].at(col::kApi), "vulkan");
    EXPECT_EQ(args[0].at(col::kBackend), "vulkan");
}

TEST(VulkanCli, AFeatureTheDeviceLacksIsRefusedNamingTheDevice) {
    // depth_bounds needs the depthBounds feature: refused per device, not per API (lavapipe lacks it).
    auto r = runCommand(vulkan("-t volume:depth_bounds=true"));
    if (r.exitCode == 0) GTEST_SKIP() << "this device has depthBounds";
    EXPECT_EQ(r.exitCode, 3) << r.output;
    EXPECT_NE(r.output.find("depth_bounds needs the depthBounds feature, which 'llvmpipe"), std::string::npos)
        << r.output;
}

TEST(VulkanCli, ListSaysWhichTechniquesHaveAVulkanFormAndTheDevices) {
    auto r = runCommand(kBench + " --list");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("apis:     gl, vulkan"), std::string::npos) << r.output;
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
    // shadowmap's flat maps refuse a point light on either API (cubemap draws it): a row, exit 3.
    const std::string csv = test::freshDir("vulkan-cli-refusal") + "/r.csv";
    auto r = runCommand(vulkan("--light point -t none -t shadowmap -t cubemap --csv " + csv));
    EXPECT_EQ(r.exitCode, 3) << r.output; // the worst of the run
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 3u) << r.output;
    std::map<std::string, std::string> status;
    for (const auto& row : rows) status[row.at(col::kTechnique)] = row.at(col::kStatus);
    EXPECT_EQ(status["none"], "ok");
    EXPECT_EQ(status["cubemap"], "ok");
    EXPECT_EQ(status["shadowmap"], "unsupported");
    EXPECT_NE(r.output.find("point light"), std::string::npos) << r.output;
}

} // namespace
