// The bench binary end to end: --help, --list, a short run writing every documented CSV column, and
// each bad input of the foundation issue: one clear line naming what was wrong, a non-zero exit code,
// nothing already written lost.
#include <algorithm>
#include <filesystem>
#include <regex>
#include <set>

#include <iostream>

#include <gtest/gtest.h>

#include "PngDecoder.h"
#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;
// Small and fast: the CLI tests check behaviour, not performance.
const std::string kQuickNoLayout = " --size 96x96 --frames 2 --warmup 1 --no-timer-check";
const std::string kQuick = " --instances 4" + kQuickNoLayout; // scenes with a layout

std::string bench(const std::string& args) {
    return kBench + " " + args;
}

int countLines(const std::string& s, const std::string& prefix) {
    int n = 0;
    size_t pos = 0;
    while ((pos = s.find(prefix, pos)) != std::string::npos) {
        ++n;
        pos += prefix.size();
    }
    return n;
}

TEST(Cli, HelpShowsExamples) {
    auto r = runCommand(bench("--help"));
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.output.find("Examples:"), std::string::npos);
    EXPECT_NE(r.output.find("--technique"), std::string::npos);
}

// `bench accuracy --help` is the accuracy mode's own help: its title, its options in their group, its
// columns and examples; the plain run's help hides those options (it refuses them).
TEST(Cli, AccuracyHelpShowsTheAccuracyOptions) {
    auto r = runCommand(bench("accuracy --help"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* s :
         {"bench accuracy: render each technique", "Accuracy options", "--sweep", "--light-index",
          "--ref-samples", "--no-stability", "acc_wrong_pct", "bench accuracy -t shadowmap --sweep"})
        EXPECT_NE(r.output.find(s), std::string::npos) << "missing '" << s << "' in:\n" << r.output;
    auto plain = runCommand(bench("--help"));
    ASSERT_EQ(plain.exitCode, 0);
    EXPECT_EQ(plain.output.find("--ref-samples"), std::string::npos) << plain.output;
    EXPECT_NE(plain.output.find("bench accuracy [options]"), std::string::npos); // the mode is still listed
}

TEST(Cli, ListShowsTechniquesEffectsPassesAndProperties) {
    auto r = runCommand(bench("--list"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* s :
         {"none", "shadowmap", "passes:   depth, lighting", "resolution", "bias_constant", "bias_slope",
          "pcf", "hardware_compare", "default 2048", "[16, 8192]", "hard_shadows", "aircraft"})
        EXPECT_NE(r.output.find(s), std::string::npos) << "missing '" << s << "' in:\n" << r.output;
}

TEST(Cli, ShortRunWritesEveryDocumentedColumn) {
    std::string dir = test::freshDir("cli-run");
    std::string csv = dir + "/r.csv", samples = dir + "/s.csv", shot = dir + "/c.png", vis = dir + "/v.png";
    auto r = runCommand(bench("-t none -t shadowmap:pcf=3" + kQuick + " --csv " + csv + " --samples " +
                              samples + " --screenshot " + shot + " --visibility " + vis));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    CsvTable t = CsvWriter::read(csv);
    ASSERT_EQ(t.rows.size(), 2u);
    auto cols = test::documentedColumns();
    ASSERT_GT(cols.size(), 30u) << "docs/CSV.md column table not found or too short";
    // Every documented column except those only `bench accuracy` writes (acc_*, ref_*) and those only
    // sweeps, bottleneck studies and failed configurations have (SweepCliTest checks those).
    for (const std::string& c : cols) {
        if (c.rfind("acc_", 0) == 0 || c.rfind("ref_", 0) == 0 || test::sweepOnlyColumns().count(c)) continue;
        EXPECT_TRUE(test::headerHas(t.header, c)) << "documented column missing: " << c;
    }
    // Every column in the file is documented too.
    for (const std::string& h : t.header)
        EXPECT_TRUE(std::any_of(cols.begin(), cols.end(),
                                [&](const std::string& c) { return test::headerHas({h}, c); }))
            << "undocumented column: " << h;
    auto col = [&](const std::string& name) {
        return size_t(std::find(t.header.begin(), t.header.end(), name) - t.header.begin());
    };
    EXPECT_EQ(t.rows[0][col(col::kTechnique)], "none");
    EXPECT_EQ(t.rows[1][col(col::kTechnique)], "shadowmap");
    EXPECT_NE(t.rows[1][col(col::kProperties)].find("pcf=3"), std::string::npos);
    EXPECT_EQ(t.rows[1][col(col::kFrames)], "2");
    EXPECT_EQ(t.rows[1][col(col::kInstances)], "4");
    EXPECT_EQ(t.rows[1][col(col::kTimerVerdict)], "unchecked");
    CsvTable s = CsvWriter::read(samples);
    EXPECT_EQ(s.rows.size(), 4u); // 2 techniques x 2 frames
    EXPECT_TRUE(std::filesystem::exists(dir + "/c_none.png"));
    EXPECT_TRUE(std::filesystem::exists(dir + "/c_shadowmap.png"));
    EXPECT_TRUE(std::filesystem::exists(dir + "/v_shadowmap.png"));
}

// Two configurations of one technique each keep their --screenshot and --visibility files, and each row
// names its own. The independent answer is the same configuration run alone: its visibility must equal,
// value for value, the file its row names in the run of two (the same binary, driver and frame render
// the same pixels: no tolerance), and differ from the other configuration's (a 256 map against 2048
// moves the shadow's edge on aircraft at 96x96).
TEST(Cli, EveryConfigurationKeepsItsOwnImagesAndItsRowNamesThem) {
    const std::string dir = test::freshDir("cli-images");
    const std::string csv = dir + "/r.csv";
    const auto r = runCommand(bench("-t shadowmap -t shadowmap:resolution=256" + kQuick + " -q --csv " + csv +
                                    " --screenshot " + dir + "/c.png --visibility " + dir + "/v.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto alone =
        runCommand(bench("-t shadowmap:resolution=256" + kQuick + " -q --visibility " + dir + "/alone.png"));
    ASSERT_EQ(alone.exitCode, 0) << alone.output;
    const auto rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 2u);
    for (const auto& row : rows)
        ASSERT_TRUE(row.count(col::kVisibilityFile) && row.count(col::kScreenshotFile))
            << "the row does not record its files";
    // The default configuration keeps the name a run of distinct techniques gives it; the other adds the
    // property it changes.
    EXPECT_EQ(rows[0].at(col::kVisibilityFile), "v_shadowmap.png");
    EXPECT_EQ(rows[0].at(col::kScreenshotFile), "c_shadowmap.png");
    EXPECT_EQ(rows[1].at(col::kVisibilityFile), "v_shadowmap_resolution=256.png");
    EXPECT_EQ(rows[1].at(col::kScreenshotFile), "c_shadowmap_resolution=256.png");
    const test::DecodedPng first = test::decodePng(dir + "/" + rows[0].at(col::kVisibilityFile));
    const test::DecodedPng second = test::decodePng(dir + "/" + rows[1].at(col::kVisibilityFile));
    const test::DecodedPng reference = test::decodePng(dir + "/alone.png");
    ASSERT_TRUE(first.ok && second.ok && reference.ok) << first.why << second.why << reference.why;
    EXPECT_EQ(second.pixels, reference.pixels) << "the 256 row's file is not the 256 configuration's picture";
    size_t differing = 0;
    for (size_t i = 0; i < first.pixels.size() && i < second.pixels.size(); ++i)
        differing += first.pixels[i] != second.pixels[i];
    EXPECT_GT(differing, 0u) << "the two configurations' visibility files hold the same picture";
    for (const auto& row : rows) EXPECT_TRUE(test::decodePng(dir + "/" + row.at(col::kScreenshotFile)).ok);
}

TEST(Cli, TimerVerdictIsMeasuredAndUntrustedNumbersAreHidden) {
    std::string dir = test::freshDir("cli-timer");
    std::string csv = dir + "/r.csv";
    auto r = runCommand(bench("-t shadowmap --instances 4 --size 96x96 --frames 2 --warmup 1 --csv " + csv));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    CsvTable t = CsvWriter::read(csv);
    auto cell = [&](const std::string& name) {
        return t.rows[0][size_t(std::find(t.header.begin(), t.header.end(), name) - t.header.begin())];
    };
    std::string verdict = cell(col::kTimerVerdict);
    ASSERT_TRUE(verdict == "trusted" || verdict == "untrusted") << verdict;
    // The evidence is the frames' own query type, with the numbers the rule judged.
    EXPECT_NE(cell(col::kTimerReason).find("GL_TIMESTAMP pairs"), std::string::npos)
        << cell(col::kTimerReason);
    EXPECT_NE(cell(col::kTimerReason).find("timer growth"), std::string::npos) << cell(col::kTimerReason);
    if (cell(col::kRenderer).find("llvmpipe") != std::string::npos) {
        // docs/ARCHITECTURE.md, "The timing contract": on Mesa llvmpipe a GL_TIMESTAMP pair spans about one
        // tile's work, and jumps with the scheduler under load; TimerVerdictGLTest runs 20 calibrations
        // under load. One run here must come out untrusted every time, loaded or not.
        EXPECT_EQ(verdict, "untrusted") << cell(col::kTimerReason);
    }
    if (verdict == "untrusted") {
        EXPECT_EQ(cell(col::kGpuMsMedian), "");
        EXPECT_EQ(cell("gpu_depth_ms_median"), "");
        EXPECT_NE(r.output.find("GPU times are not reported"), std::string::npos) << r.output;
    } else {
        EXPECT_NE(cell(col::kGpuMsMedian), "");
    }
}

struct BadInput {
    const char* name;
    std::string args;
    int exitCode;
    const char* mustMention;
};
void PrintTo(const BadInput& b, std::ostream* os) {
    *os << b.name;
}

class BadInputs : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputs, OneClearLineAndNonZeroExit) {
    const BadInput& b = GetParam();
    std::string dir = test::freshDir(std::string("bad-") + b.name);
    // A CSV with earlier results that must survive every failure byte for byte.
    std::string csv = dir + "/keep.csv";
    CsvWriter::appendRows(csv, {{{"technique", "earlier"}, {"wall_ms_median", "1.0"}}});
    std::string before = test::readFile(csv);
    std::string args = std::regex_replace(b.args, std::regex("\\$DIR"), dir);
    if (args.find("--csv") == std::string::npos) args += " --csv " + csv;
    auto r = runCommand(bench(args));
    EXPECT_EQ(r.exitCode, b.exitCode) << r.output;
    EXPECT_EQ(countLines(r.output, "bench: error:"), 1) << r.output;
    std::string errorLine = r.output.substr(r.output.find("bench: error:"));
    errorLine = errorLine.substr(0, errorLine.find('\n'));
    EXPECT_NE(errorLine.find(b.mustMention), std::string::npos) << "error line: " << errorLine;
    EXPECT_EQ(test::readFile(csv), before) << "the existing CSV changed";
}

const BadInput kBadInputs[] = {
    {"unknown_technique", "-t shadowmapp" + kQuick, 2, "unknown technique 'shadowmapp'"},
    {"unknown_property", "-t shadowmap:resolutoin=2048" + kQuick, 2, "resolutoin"},
    {"out_of_range_property", "-t shadowmap:resolution=99999" + kQuick, 2, "[16, 8192]"},
    {"bad_property_type", "-t shadowmap:pcf=three" + kQuick, 2, "pcf"},
    {"property_without_value", "-t shadowmap:pcf" + kQuick, 2, "pcf"},
    {"malformed_scene_json", "--scene " + std::string(SB_SOURCE_DIR) + "/tests/data/malformed.json" + kQuick,
     2, "malformed.json"},
    {"scene_wrong_type", "--scene " + std::string(SB_SOURCE_DIR) + "/tests/data/wrong_type.json" + kQuick, 2,
     "/layout/count"},
    {"missing_scene", "--scene $DIR/nope.json" + kQuick, 2, "nope.json"},
    {"missing_model", "--model $DIR/missing.obj" + kQuick, 2, "missing.obj"},
    {"zero_instances", "--instances 0 --size 96x96 --frames 1", 2, "--instances"},
    {"absurd_instances", "--instances 900000 --size 96x96 --frames 1", 2, "memory"},
    {"bad_size", "--size 96by96", 2, "--size"},
    {"bad_submit", "--submit sometimes" + kQuick, 2, "--submit"},
    {"unknown_camera", "--camera sideways" + kQuick, 2, "sideways"},
    {"unknown_backend", "--backend vulkan" + kQuick, 2, "vulkan"},
    {"unknown_option", "--frobnicate" + kQuick, 2, "frobnicate"},
    {"unsupported_point_light", "-t shadowmap --light point" + kQuick, 3, "point light"},
    {"sweep_without_accuracy", "--sweep" + kQuick, 2, "--sweep"},
    {"accuracy_nothing_faces_light",
     "accuracy --scene " + std::string(SB_SOURCE_DIR) + "/tests/data/light_from_below.json" + kQuickNoLayout,
     2, "nothing to judge"},
    {"accuracy_scene_infinite_vertex",
     "accuracy --scene " + std::string(SB_SOURCE_DIR) + "/tests/data/infinite_vertex.json" + kQuickNoLayout,
     2, "infinite_vertex.obj': vertex 1 "},
    // A path the user gave that cannot be written is bad input, found before the first frame.
    {"unwritable_csv", "-t none" + kQuick + " --csv /proc/shadowbench/r.csv", 2, "/proc/shadowbench/r.csv"},
};

INSTANTIATE_TEST_SUITE_P(Cli, BadInputs, ::testing::ValuesIn(kBadInputs),
                         [](const auto& p) { return std::string(p.param.name); });

TEST(Cli, EveryHeadlessBackendRunsBothTechniques) {
    // A whole run per backend, destructors included (GL objects must be released while the context
    // still exists), and the backend recorded in the row.
    for (const char* backend : {"egl-surfaceless", "egl-device", "osmesa"}) {
        std::string csv = test::freshDir(std::string("cli-backend-") + backend) + "/r.csv";
        auto r = runCommand(
            bench(std::string("--backend ") + backend + " -t none -t shadowmap" + kQuick + " --csv " + csv));
        if (r.exitCode == 3 && std::string(backend) == "egl-device") {
            std::cout << "egl-device not available here: " << r.output << "\n";
            continue;
        }
        ASSERT_EQ(r.exitCode, 0) << backend << ": " << r.output;
        CsvTable t = CsvWriter::read(csv);
        ASSERT_EQ(t.rows.size(), 2u) << backend;
        EXPECT_EQ(
            t.rows[1][size_t(std::find(t.header.begin(), t.header.end(), "backend") - t.header.begin())],
            backend);
    }
}

TEST(Cli, WindowViewerRendersAndQuits) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY (scripts/test.sh runs the suite under xvfb-run)";
    std::string dir = test::freshDir("cli-window");
    auto r = runCommand(bench("--window --window-frames 3 -t none -t shadowmap --instances 4 --size 96x96 "
                              "--screenshot " +
                              dir + "/w.png"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir + "/w.png"));
}

TEST(Cli, AccuracyRowHasTimingAndEveryDocumentedAccuracyColumn) {
    std::string csv = test::freshDir("cli-accuracy") + "/a.csv";
    auto r = runCommand(bench("accuracy -t none -t shadowmap -t reference --scene sphere_plane --camera top "
                              "--size 128x128 --frames 2 --warmup 1 --no-timer-check --csv " +
                              csv));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    CsvTable t = CsvWriter::read(csv);
    ASSERT_EQ(t.rows.size(), 3u);
    auto cols = test::documentedColumns();
    for (const std::string& h : t.header)
        EXPECT_TRUE(std::any_of(cols.begin(), cols.end(),
                                [&](const std::string& c) { return test::headerHas({h}, c); }))
            << "undocumented column: " << h;
    for (const std::string& c : cols) {
        if (test::sweepOnlyColumns().count(c)) continue;
        EXPECT_TRUE(test::headerHas(t.header, c)) << "documented column missing: " << c;
    }
    auto cell = [&](size_t row, const std::string& name) {
        return t.rows[row][size_t(std::find(t.header.begin(), t.header.end(), name) - t.header.begin())];
    };
    // The reference judged against itself is exact; `none` misses the whole shadow (false light only).
    EXPECT_EQ(std::stod(cell(2, col::kAccWrongPct)), 0.0);
    EXPECT_GT(std::stod(cell(0, col::kAccFalseLightPct)), 1.0);
    EXPECT_EQ(std::stod(cell(0, col::kAccFalseShadowPct)), 0.0);
    for (size_t i = 0; i < 3; ++i) EXPECT_EQ(cell(i, col::kAccNan), "0.0000");
}

TEST(Cli, GpuIndexOutOfRangeIsBadInput) {
    // An index past the machine's EGL devices is the user's input (exit 2), named with the device
    // count, whether the backend is chosen by --gpu (auto) or named; it never falls back to another
    // backend and measures there (it did: exit 0 under auto, exit 3 with egl-device).
    for (const std::string backend : {"", " --backend egl-device"}) {
        auto r = runCommand(bench("--gpu 99" + backend + kQuick));
        EXPECT_EQ(r.exitCode, 2) << backend << ": " << r.output;
        EXPECT_NE(r.output.find("--gpu 99 is out of range"), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("wall median"), std::string::npos) << "measured anyway: " << r.output;
    }
}

TEST(Cli, RowsOfTechniquesThatFinishedSurviveALaterFailure) {
    // none runs and appends its row; shadowmap then refuses the point light: its refusal is a row of its
    // own (status unsupported, the reason in error), the none row stays, and the exit code says what
    // the machine lacked (3).
    std::string dir = test::freshDir("cli-partial");
    std::string csv = dir + "/r.csv";
    auto r = runCommand(bench("-t none -t shadowmap --light point" + kQuick + " --csv " + csv));
    EXPECT_EQ(r.exitCode, 3) << r.output;
    CsvTable t = CsvWriter::read(csv);
    ASSERT_EQ(t.rows.size(), 2u);
    auto cell = [&](size_t row, const std::string& name) {
        return t.rows[row][size_t(std::find(t.header.begin(), t.header.end(), name) - t.header.begin())];
    };
    EXPECT_EQ(cell(0, col::kTechnique), "none");
    EXPECT_EQ(cell(0, col::kStatus), "ok");
    EXPECT_EQ(cell(1, col::kTechnique), "shadowmap");
    EXPECT_EQ(cell(1, col::kStatus), "unsupported");
    EXPECT_NE(cell(1, col::kError).find("point light"), std::string::npos) << cell(1, col::kError);
}

} // namespace

TEST(Cli, RepeatInterleavesRoundsAndPairsRatios) {
    std::string dir = test::freshDir("cli-repeat");
    std::string csv = dir + "/r.csv";
    auto r = runCommand(bench("-t none -t shadowmap --repeat 3" + kQuick + " --csv " + csv));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    CsvTable t = CsvWriter::read(csv);
    ASSERT_EQ(t.rows.size(), 6u);
    auto col = [&](const std::string& name) {
        return size_t(std::find(t.header.begin(), t.header.end(), name) - t.header.begin());
    };
    // Written in measurement order: none, shadowmap per round, rounds 1..3.
    for (size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(t.rows[i][col(col::kTechnique)], i % 2 ? "shadowmap" : "none") << i;
        EXPECT_EQ(t.rows[i][col(col::kRepeat)], std::to_string(i / 2 + 1)) << i;
        EXPECT_EQ(t.rows[i][col(col::kBaseline)], "none");
    }
    EXPECT_NE(r.output.find("paired over 3 rounds"), std::string::npos) << r.output;
}
