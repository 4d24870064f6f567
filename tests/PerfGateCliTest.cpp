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
    EXPECT_NE(injected.output.find("none_aircraft: injected_fullscreen_fragments 0 -> "), std::string::npos)
        << injected.output;
    EXPECT_NE(injected.output.find("shadowmap_aircraft: injected_fullscreen_fragments 0 -> "),
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
