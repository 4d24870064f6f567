// The perf gate end to end (bench ci, bench compare; README "Gate a change"): a baseline written by
// --update passes against the same build, and each deliberate regression (core/Injection.h) fails
// layer A with the pass that grew named. The expected outcome of each case is known by construction:
// the injection adds a full-screen pass, so its fragments appear where there were none.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestPaths.h"
#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;

namespace {

class PerfGateCliTest : public ::testing::Test {
protected:
    void SetUp() override { mDir = test::freshTestDir("gate"); }
    void TearDown() override { std::filesystem::remove_all(mDir); }
    /// bench ci with layer A on two configurations, baseline and output in the scratch folder.
    test::CommandResult ci(const std::string& env, const std::string& args) const {
        return test::runCommand(env + " " + test::benchBinary() + " ci --layers A --configs " + kConfigs +
                                " --baseline " + mDir + "/baseline --out " + mDir + "/out " + args);
    }
    static constexpr const char* kConfigs = "none_aircraft,shadowmap_aircraft";
    std::string mDir;
};

TEST_F(PerfGateCliTest, SameBuildPassesAndAnInjectedPassFailsNamingIt) {
    const auto update = ci("", "--update");
    ASSERT_EQ(update.exitCode, 0) << update.output;
    const auto same = ci("", "");
    EXPECT_EQ(same.exitCode, 0) << same.output;
    EXPECT_NE(same.output.find("perf gate: PASS"), std::string::npos) << same.output;
    EXPECT_NE(same.output.find("| none_aircraft | balanced | exact (PASS)"), std::string::npos)
        << same.output;

    const auto injected = ci("SHADOWBENCH_INJECT=extra_fullscreen_pass", "");
    EXPECT_EQ(injected.exitCode, 1) << injected.output;
    EXPECT_NE(injected.output.find("perf gate: FAIL"), std::string::npos) << injected.output;
    EXPECT_NE(injected.output.find("none_aircraft: injected_fullscreen_fragments absent -> "),
              std::string::npos)
        << injected.output;
    EXPECT_NE(injected.output.find("shadowmap_aircraft: injected_fullscreen_fragments absent -> "),
              std::string::npos)
        << injected.output;
    // The report files say the same.
    const std::string json = test::readFile(mDir + "/out/report.json");
    EXPECT_NE(json.find("\"verdict\": \"FAIL\""), std::string::npos) << json;
    EXPECT_NE(test::readFile(mDir + "/out/work.csv").find("extra_fullscreen_pass"), std::string::npos);
    // And the dashboard files chart the same rows, named by configuration, with the frame's exact work
    // as work.csv has it (the injected pass's fragments included).
    const auto rows = test::csvRowMaps(mDir + "/out/work.csv");
    const auto gh = nlohmann::json::parse(test::readFile(mDir + "/out/gh-benchmark.json"));
    const auto gbench = nlohmann::json::parse(test::readFile(mDir + "/out/gbench.json"));
    ASSERT_EQ(gbench["benchmarks"].size(), rows.size());
    for (size_t i = 0; i < rows.size(); ++i) {
        EXPECT_EQ(gbench["benchmarks"][i]["name"], rows[i].at(col::kCiConfig));
        EXPECT_DOUBLE_EQ(gbench["benchmarks"][i][col::kLoadFragments].get<double>(),
                         std::stod(rows[i].at(col::kLoadFragments)));
        bool found = false;
        for (const auto& item : gh)
            if (item["name"] == rows[i].at(col::kCiConfig) + " load_fragments") {
                found = true;
                EXPECT_DOUBLE_EQ(item["value"].get<double>(), std::stod(rows[i].at(col::kLoadFragments)));
            }
        EXPECT_TRUE(found) << gh.dump(1);
    }
    // Every column bench ci writes is documented in the README's CSV section.
    const auto documented = test::documentedColumns();
    for (const std::string& h : CsvWriter::read(mDir + "/out/work.csv").header)
        EXPECT_TRUE(std::any_of(documented.begin(), documented.end(),
                                [&](const std::string& c) { return test::headerHas({h}, c); }))
            << "undocumented column: " << h;
}

TEST_F(PerfGateCliTest, ShadowMapRegressionsFailOnTheDepthPass) {
    // Drawing receivers into the map adds the ground's triangles to the depth pass; doubling the map
    // quadruples its texels. Both are work an unmodified build does not do, so layer A must name them.
    ASSERT_EQ(ci("", "--update").exitCode, 0);
    const auto culling = ci("SHADOWBENCH_INJECT=no_caster_culling", "");
    EXPECT_EQ(culling.exitCode, 1) << culling.output;
    EXPECT_NE(culling.output.find("increase: shadowmap_aircraft: depth_triangles "), std::string::npos)
        << culling.output;
    EXPECT_EQ(culling.output.find("increase: none_aircraft"), std::string::npos) << culling.output;
    const auto resolution = ci("SHADOWBENCH_INJECT=double_shadow_resolution", "");
    EXPECT_EQ(resolution.exitCode, 1) << resolution.output;
    EXPECT_NE(
        resolution.output.find("shadowmap_aircraft: counter_shadow_map_texels 262144 -> 1048576 (+300.0%)"),
        std::string::npos)
        << resolution.output;
    EXPECT_NE(resolution.output.find("shadowmap_aircraft: depth_fragments "), std::string::npos)
        << resolution.output;
}

TEST_F(PerfGateCliTest, CompareJudgesTwoResultFiles) {
    const std::string header =
        "status,renderer,gl_version,technique,instances,work_depth_fragments,wall_ms_median\n";
    test::writeFile(mDir + "/a.csv",
                    header + "ok,llvmpipe,4.5,shadowmap,10,1000,5\nok,llvmpipe,4.5,shadowmap,10,1000,6\n");
    test::writeFile(mDir + "/b.csv",
                    header + "ok,llvmpipe,4.5,shadowmap,10,1120,5\nok,llvmpipe,4.5,shadowmap,10,1120,6\n");
    const std::string bench = test::benchBinary();
    const auto same =
        test::runCommand(bench + " compare " + mDir + "/a.csv " + mDir + "/a.csv --json " + mDir + "/c.json");
    EXPECT_EQ(same.exitCode, 0) << same.output;
    EXPECT_NE(same.output.find("C: wall time (unpaired rounds): INCONCLUSIVE"), std::string::npos)
        << same.output;
    EXPECT_NE(same.output.find("needs bench ci (valgrind)"), std::string::npos) << same.output;
    const auto grew = test::runCommand(bench + " compare " + mDir + "/a.csv " + mDir + "/b.csv");
    EXPECT_EQ(grew.exitCode, 1) << grew.output;
    EXPECT_NE(grew.output.find("depth_fragments 1000 -> 1120 (+12.0%)"), std::string::npos) << grew.output;
    const auto shrank = test::runCommand(bench + " compare " + mDir + "/b.csv " + mDir + "/a.csv");
    EXPECT_EQ(shrank.exitCode, 0) << shrank.output;
    EXPECT_NE(shrank.output.find("decrease:"), std::string::npos) << shrank.output;
}

// The hostile-input battery: bench compare on files that hold nothing comparable, or counts that are not
// counts. Each must fail (exit 1) with its reason and no configuration may read PASS; non-finite
// thresholds are bad input (exit 2). Before, every one of these exited 0 with PASS (an absent or
// unparseable count read as 0, a "decrease"; a nan floor made layer C unable to fail).
TEST_F(PerfGateCliTest, CompareFailsOnWhatItCouldNotCompare) {
    const std::string header = "ci_config,status,renderer,gl_version,work_depth_draws,work_depth_fragments\n";
    const std::string good = header + "a,ok,llvmpipe,Mesa 22.3.6,40,1000\n";
    auto withCount = [&](const std::string& fragments) {
        return header + "a,ok,llvmpipe,Mesa 22.3.6,40," + fragments + "\n";
    };
    struct Case {
        std::string name, base, head, options;
        int exitCode;
        std::string reason;
    };
    const std::vector<Case> cases = {
        {"empty head", good, "", "", 1, "head: the file is empty (no header)"},
        {"empty base", "", good, "", 1, "base: the file is empty (no header)"},
        {"header only", good, header, "", 1, "head: no rows (a header only)"},
        {"cut inside its header", good, "ci_config,status,rend", "", 1,
         "head: no work columns (work_*, load_*, counter_*)"},
        {"wrong header", good, "name,value\na,1\n", "", 1, "head: no status column (not a result table)"},
        {"every row failed", good, header + "a,failed,,,,\n", "", 1,
         "head: none of its 1 rows has status ok"},
        {"nan", good, withCount("nan"), "", 1, "head: work_depth_fragments 'nan' is not a count"},
        {"negative", good, withCount("-5"), "", 1, "head: work_depth_fragments '-5' is not a count"},
        {"fractional", good, withCount("999.5"), "", 1, "work_depth_fragments '999.5' is not a count"},
        {"not a number", good, withCount("lots"), "", 1, "work_depth_fragments 'lots' is not a count"},
        {"empty where the base has it", good, withCount(""), "", 1,
         "count on one side only: a: depth_fragments 1000 -> absent"},
        {"absent column", good,
         "ci_config,status,renderer,gl_version,work_depth_draws\na,ok,llvmpipe,Mesa 22.3.6,40\n", "", 1,
         "count on one side only: a: depth_fragments 1000 -> absent"},
        {"missing from the head", good, header + "b,ok,llvmpipe,Mesa 22.3.6,40,1000\n", "", 1,
         "a: in the base only"},
        {"missing from the base", header + "b,ok,llvmpipe,Mesa 22.3.6,40,1000\n", good, "", 1,
         "a: not in the base"},
        {"floor nan", good, good, "--floor nan", 2, "--floor nan: expected a number in [0, 10]"},
        {"alpha nan", good, good, "--alpha nan", 2, "--alpha nan: expected a number in [1e-09, 0.5]"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        test::writeFile(mDir + "/base.csv", c.base);
        test::writeFile(mDir + "/head.csv", c.head);
        const auto r = test::runCommand(std::string(test::benchBinary()) + " compare " + mDir + "/base.csv " +
                                        mDir + "/head.csv " + c.options);
        EXPECT_EQ(r.exitCode, c.exitCode) << r.output;
        EXPECT_NE(r.output.find(c.reason), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("(PASS)"), std::string::npos) << r.output;
        EXPECT_EQ(r.output.find("compare: PASS"), std::string::npos) << r.output;
    }
    // The control: the good file against itself passes, its configuration compared.
    test::writeFile(mDir + "/base.csv", good);
    const auto same = test::runCommand(std::string(test::benchBinary()) + " compare " + mDir + "/base.csv " +
                                       mDir + "/base.csv");
    EXPECT_EQ(same.exitCode, 0) << same.output;
    EXPECT_NE(same.output.find("| a |  | exact (PASS) |"), std::string::npos) << same.output;
}

// bench ci against a baseline cut inside its header, and against one that lacks a configuration of the
// suite: each fails naming why, and the configuration's cell says it was not compared. Before, both said
// PASS with "exact (PASS)" on rows that were never compared.
TEST_F(PerfGateCliTest, CiFailsOnATruncatedBaselineAndAMissingConfiguration) {
    // The committed baseline's rows (none_aircraft's is its first), cut, in the scratch baseline folder.
    const std::string full = test::readFile(std::string(SB_SOURCE_DIR) + "/results/ci/baseline/work.csv");
    const std::string path = mDir + "/baseline/work.csv";
    std::filesystem::create_directories(mDir + "/baseline");
    test::writeFile(path, full.substr(0, full.find(',', full.find(',') + 1) + 4)); // "ci_config,status,api"
    const auto cut = ci("", "");
    EXPECT_EQ(cut.exitCode, 1) << cut.output;
    EXPECT_NE(cut.output.find("perf gate: FAIL"), std::string::npos) << cut.output;
    EXPECT_NE(cut.output.find("unusable input: base: no work columns"), std::string::npos) << cut.output;
    EXPECT_NE(cut.output.find("| none_aircraft | balanced | not compared: not in the base (FAIL) |"),
              std::string::npos)
        << cut.output;
    // The baseline without shadowmap_aircraft's row (the header and none_aircraft's row only).
    const size_t second = full.find('\n', full.find('\n') + 1) + 1;
    ASSERT_EQ(full.find("\nnone_aircraft,"), full.find('\n'));
    test::writeFile(path, full.substr(0, second));
    const auto missing = ci("", "");
    EXPECT_EQ(missing.exitCode, 1) << missing.output;
    EXPECT_NE(missing.output.find("shadowmap_aircraft: not in the baseline (add it with --update)"),
              std::string::npos)
        << missing.output;
    EXPECT_NE(missing.output.find("| none_aircraft | balanced | exact (PASS) |"), std::string::npos)
        << missing.output;
    EXPECT_EQ(missing.output.find("| shadowmap_aircraft | balanced | exact"), std::string::npos)
        << missing.output;
    EXPECT_EQ(ci("", "--floor nan").exitCode, 2);
}

// The driver A/B end to end: the base on Mesa 25.0.7 (unpacked beside the system's 22.3.6), the head on
// the system driver, one configuration each. On Vulkan (whose rows leave gl_version empty) the
// application's work is exact and the driver's fragments are reported with both values, neither PASS nor
// FAIL; on GL the head doubles its shadow map (an application-work change), which fails naming the
// counter. Before, the Vulkan row passed as "exact (PASS)" with the depth pass's lost fragments judged as
// a decrease on one driver, and the GL row said only "not comparable".
TEST_F(PerfGateCliTest, DriverABJudgesApplicationWorkAndReportsDriverWork) {
    const std::string prefix = "/opt/shadowbench/drivers/mesa-25.0.7";
    if (!std::filesystem::exists(prefix))
        GTEST_SKIP() << "Mesa 25.0.7 is not unpacked at " << prefix << ": no second driver to A/B against";
    const std::string baseEnv = " --base-driver mesa-25.0.7";
    auto ab = [&](const std::string& config, const std::string& extra) {
        return test::runCommand(std::string(test::benchBinary()) + " ci --layers A --configs " + config +
                                baseEnv + extra + " --out " + mDir + "/out");
    };
    const auto vulkan = ab("shadowmap_vulkan", "");
    EXPECT_EQ(vulkan.exitCode, 0) << vulkan.output;
    EXPECT_NE(vulkan.output.find("perf gate: PASS"), std::string::npos) << vulkan.output;
    EXPECT_NE(
        vulkan.output.find("| shadowmap_vulkan | balanced | application work exact; driver work differs "
                           "(explained): "),
        std::string::npos)
        << vulkan.output;
    EXPECT_EQ(vulkan.output.find("(PASS)"), std::string::npos) << vulkan.output;
    // Both values, 25.0.7's (no fragment shader in a depth-only pass) and 22.3.6's (its stamps with the
    // casters' back faces culled; 59072 when they are drawn).
    EXPECT_NE(
        vulkan.output.find("driver work (explained, not judged): shadowmap_vulkan: depth_fragments 0 -> "
                           "29552 (head/base: from 0)"),
        std::string::npos)
        << vulkan.output;
    EXPECT_NE(vulkan.output.find("Mesa 25.0.7-2~bpo12+1"), std::string::npos) << vulkan.output;

    const auto gl = ab("shadowmap_aircraft", " --head-env SHADOWBENCH_INJECT=double_shadow_resolution");
    EXPECT_EQ(gl.exitCode, 1) << gl.output;
    EXPECT_NE(gl.output.find("application work differs across drivers: shadowmap_aircraft: "
                             "counter_shadow_map_texels 262144 -> 1048576"),
              std::string::npos)
        << gl.output;
    EXPECT_NE(
        gl.output.find("driver work (explained, not judged): shadowmap_aircraft: depth_fragments 0 -> "),
        std::string::npos)
        << gl.output;
}

// Layer B on a machine where valgrind cannot run the bench: exit 3 (the machine lacks what the layer
// needs, not a failed gate) with the one-line reason and the log's path, and --update rewrites nothing,
// layer A's file included. The valgrind on PATH here replays a real failure: it prints the committed log of
// callgrind dying on RDTSCP in libhwy (tests/data/callgrind/sigill-libhwy.stderr.txt) and kills itself
// with SIGILL, as valgrind does; InstructionCountValgrindTest makes the real valgrind fail the same way.
TEST_F(PerfGateCliTest, LayerBWhereValgrindCannotRunIsExitThreeAndUpdateWritesNothing) {
    ASSERT_EQ(ci("", "--update").exitCode, 0);
    const std::string committed = test::readFile(mDir + "/baseline/work.csv");
    ASSERT_FALSE(committed.empty());
    const std::string fake = mDir + "/fake-valgrind";
    std::filesystem::create_directories(fake);
    test::writeFile(fake + "/valgrind", "#!/bin/sh\n"
                                        "if [ \"$1\" = --version ]; then echo valgrind-3.19.0; exit 0; fi\n"
                                        "cat '" +
                                            std::string(SB_SOURCE_DIR) +
                                            "/tests/data/callgrind/sigill-libhwy.stderr.txt' >&2\n"
                                            "kill -ILL $$\n");
    std::filesystem::permissions(fake + "/valgrind", std::filesystem::perms::owner_all);
    const std::string path = "PATH=" + fake + ":$PATH";
    for (const std::string args : {"--layers A,B --update", "--layers B"}) {
        SCOPED_TRACE(args);
        const auto r =
            test::runCommand(path + " " + test::benchBinary() + " ci --configs none_aircraft --baseline " +
                             mDir + "/baseline --out " + mDir + "/out " + args);
        EXPECT_EQ(r.exitCode, 3) << r.output;
        EXPECT_NE(
            r.output.find("killed by SIGILL: valgrind cannot execute the instruction at 0x2251d522 "
                          "(bytes 0F 01 F9, RDTSCP) in hwy::platform::TimerResolution() (libhwy.so.1.0.3)"),
            std::string::npos)
            << r.output;
        EXPECT_NE(r.output.find("(log: " + mDir + "/out/callgrind/none_aircraft/stderr.txt)"),
                  std::string::npos)
            << r.output;
        EXPECT_EQ(r.output.find("I   refs"), std::string::npos) << r.output;
        EXPECT_EQ(test::readFile(mDir + "/baseline/work.csv"), committed);
        EXPECT_FALSE(std::filesystem::exists(mDir + "/baseline/instructions.json"));
    }
}

TEST_F(PerfGateCliTest, BadInputIsExitTwo) {
    const std::string bench = test::benchBinary();
    EXPECT_EQ(test::runCommand("SHADOWBENCH_INJECT=extra_pass " + bench + " -t none --frames 1").exitCode, 2);
    EXPECT_EQ(test::runCommand(bench + " ci --layers D").exitCode, 2);
    EXPECT_EQ(test::runCommand(bench + " ci --configs no_such_config --quick --out " + mDir).exitCode, 2);
    EXPECT_EQ(test::runCommand(bench + " ci --quick --baseline " + mDir + "/none --out " + mDir).exitCode, 2);
    // A missing baseline is found before the suite runs: no configuration was measured.
    EXPECT_FALSE(std::filesystem::exists(mDir + "/work.csv"));
    EXPECT_EQ(test::runCommand(bench + " compare " + mDir + "/missing.csv " + mDir + "/missing.csv").exitCode,
              2);
}

} // namespace

// A gate run that calibrates -t auto (the suite's auto_aircraft on a renderer its committed seed was not
// measured on: here the seed's rows are relabelled to another renderer, as on another driver) leaves the
// committed calibration byte for byte as it was and writes what it measured to the user's cache folder
// ($XDG_CACHE_HOME/shadowbench). The committed suite and seed are copied into a scratch source tree, the
// run's working directory, with one change: the suite's frame size is 32x32 (the calibration's cost is
// preparing its candidates, not pixels). Nothing but the two copied files may be in that tree afterwards.
TEST_F(PerfGateCliTest, CalibratingLeavesTheCommittedSeedAsItWas) {
    namespace fs = std::filesystem;
    const fs::path tree = fs::path(mDir) / "tree", ci = tree / "results" / "ci",
                   cache = fs::path(mDir) / "cache";
    fs::create_directories(ci);
    std::string suite = test::readFile(std::string(SB_SOURCE_DIR) + "/results/ci/suite.json");
    const std::string size = "\"--size\", \"160x160\"";
    ASSERT_NE(suite.find(size), std::string::npos) << suite;
    suite.replace(suite.find(size), size.size(), "\"--size\", \"32x32\"");
    test::writeFile((ci / "suite.json").string(), suite);
    CsvTable seed = CsvWriter::read(std::string(SB_SOURCE_DIR) + "/results/ci/auto-calibration.csv");
    ASSERT_FALSE(seed.rows.empty());
    ASSERT_EQ(seed.header[0], "renderer");
    for (auto& row : seed.rows) row[0] = "another renderer";
    const std::string seedPath = (ci / "auto-calibration.csv").string();
    CsvWriter::writeTable(seedPath, seed);
    const std::string before = test::readFile(seedPath);

    // Mesa's shader cache stays where it was (it follows XDG_CACHE_HOME too): a cold one costs seconds.
    const auto run = test::runCommand(
        "cd " + tree.string() +
        " && MESA_SHADER_CACHE_DIR=\"${XDG_CACHE_HOME:-$HOME/.cache}/mesa_shader_cache\" " +
        "XDG_CACHE_HOME=" + cache.string() + " " + test::benchBinary() +
        " ci --quick --configs auto_aircraft --suite results/ci/suite.json --update --baseline " + mDir +
        "/baseline --out " + mDir + "/out");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const std::string after = test::readFile(seedPath);
    EXPECT_TRUE(after == before) << "a benchmark run modified the committed calibration: " << before.size()
                                 << " bytes before, " << after.size() << " after";
    const fs::path cached = cache / "shadowbench" / "auto-calibration.csv";
    ASSERT_TRUE(fs::exists(cached)) << "the calibration did not go to $XDG_CACHE_HOME/shadowbench";
    EXPECT_FALSE(CsvWriter::read(cached.string()).rows.empty());
    std::vector<std::string> files;
    for (const auto& e : fs::recursive_directory_iterator(tree))
        if (!e.is_directory()) files.push_back(fs::relative(e.path(), tree).string());
    std::sort(files.begin(), files.end());
    EXPECT_EQ(files, (std::vector<std::string>{"results/ci/auto-calibration.csv", "results/ci/suite.json"}));
}
