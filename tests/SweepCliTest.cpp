// `bench sweep`, `bench merge`, `bench export` and --format end to end: the product of the
// axes, rows as they finish, ratios within a round, failures recorded while the sweep goes on (an
// unsupported light, a GL error, a crashed worker), Ctrl-C and --resume without repeated or lost rows,
// shards run with GNU parallel and merged back into the unsharded sweep. Answers are counted by hand
// from the axes or recomputed from the CSV's own timing columns.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <map>
#include <set>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

extern char** environ;

using namespace sb;
using test::runCommand;

namespace {

const std::string kBench = SB_BENCH_BINARY;
// Tiny and quick: these tests check the machinery, not performance.
const std::string kQuickRun = " --size 64x64 --frames 2 --warmup 1"; // a plain bench run
const std::string kQuick = kQuickRun + " --no-progress";             // a sweep

std::string bench(const std::string& args) {
    return kBench + " " + args;
}

/// A CSV read back with access by column name.
struct Table {
    CsvTable t;
    explicit Table(const std::string& path) : t(CsvWriter::read(path)) {}
    size_t size() const { return t.rows.size(); }
    bool has(const std::string& c) const {
        return std::find(t.header.begin(), t.header.end(), c) != t.header.end();
    }
    const std::string& at(size_t row, const std::string& c) const {
        const size_t i = size_t(std::find(t.header.begin(), t.header.end(), c) - t.header.begin());
        if (i >= t.header.size()) throw std::runtime_error("no column " + c);
        return t.rows[row][i];
    }
    std::vector<size_t> indices() const {
        std::vector<size_t> out;
        for (size_t r = 0; r < size(); ++r) out.push_back(std::stoul(at(r, col::kConfigIndex)));
        std::sort(out.begin(), out.end());
        return out;
    }
};

std::vector<size_t> iota(size_t n) {
    std::vector<size_t> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

} // namespace

TEST(SweepCli, ProductOfTheAxesWithRatiosWithinEachRound) {
    const std::string dir = test::freshDir("sweep-product");
    const std::string csv = dir + "/s.csv";
    // 2 instance counts x 2 submission modes = 4 groups; 2 techniques x 2 rounds each = 16 rows.
    auto r = runCommand(
        bench("sweep -t none -t shadowmap:resolution=256 --instances 2,5 --submit retained,immediate "
              "--repeat 2 --csv " +
              csv + kQuick));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Table t(csv);
    ASSERT_EQ(t.size(), 16u);
    EXPECT_EQ(t.indices(), iota(16)) << "every configuration exactly once";
    std::map<std::string, std::vector<size_t>> byGroup;
    for (size_t i = 0; i < t.size(); ++i) {
        EXPECT_EQ(t.at(i, col::kStatus), "ok");
        EXPECT_EQ(t.at(i, col::kSweepConfigs), "16");
        EXPECT_EQ(t.at(i, col::kShard), "1/1");
        EXPECT_EQ(t.at(i, col::kBaseline), "none");
        byGroup[t.at(i, col::kConfigGroup)].push_back(i);
    }
    ASSERT_EQ(byGroup.size(), 4u);
    std::set<std::string> combos;
    for (const auto& [group, rows] : byGroup) {
        ASSERT_EQ(rows.size(), 4u);
        combos.insert(t.at(rows[0], col::kInstances) + "/" + t.at(rows[0], col::kSubmit));
        // Ratio within the round, recomputed from the two rows' own medians (4-decimal CSV rounding).
        for (size_t a : rows)
            for (size_t b : rows)
                if (t.at(a, col::kRepeat) == t.at(b, col::kRepeat) && t.at(a, col::kTechnique) == "none" &&
                    t.at(b, col::kTechnique) == "shadowmap") {
                    const double ratio =
                        std::stod(t.at(b, col::kWallMsMedian)) / std::stod(t.at(a, col::kWallMsMedian));
                    EXPECT_NEAR(std::stod(t.at(b, col::kWallRatioVsBaseline)), ratio, 1e-3 * ratio + 1e-4);
                    EXPECT_EQ(t.at(a, col::kWallRatioVsBaseline), "1.0000");
                }
    }
    EXPECT_EQ(combos, (std::set<std::string>{"2/retained", "2/immediate", "5/retained", "5/immediate"}));
    // Every column a sweep writes is documented in the README.
    const auto documented = test::documentedColumns();
    for (const std::string& h : t.t.header)
        EXPECT_TRUE(std::any_of(documented.begin(), documented.end(),
                                [&](const std::string& c) { return test::headerHas({h}, c); }))
            << "undocumented column: " << h;
}

TEST(SweepCli, FailuresAreRecordedAndTheSweepGoesOn) {
    const std::string dir = test::freshDir("sweep-failures");
    const std::string csv = dir + "/s.csv";
    // shadowmap cannot do a point light (that takes cubemap or paraboloid): that configuration is recorded as
    // unsupported (exit code 3 of the worker: a skip, not a failure), the rest are measured; exit code 0.
    auto r = runCommand(
        bench("sweep -t none -t shadowmap --instances 3 --light directional,point --csv " + csv + kQuick));
    EXPECT_EQ(r.exitCode, 0) << r.output;
    Table t(csv);
    ASSERT_EQ(t.size(), 4u);
    int skipped = 0;
    for (size_t i = 0; i < t.size(); ++i) {
        const bool shouldSkip = t.at(i, col::kTechnique) == "shadowmap" && t.at(i, col::kLights) == "point";
        EXPECT_EQ(t.at(i, col::kStatus), shouldSkip ? "unsupported" : "ok") << i;
        if (shouldSkip) {
            ++skipped;
            EXPECT_NE(t.at(i, col::kError).find("omni shadow map"), std::string::npos)
                << t.at(i, col::kError);
        }
    }
    EXPECT_EQ(skipped, 1);
    EXPECT_NE(r.output.find("1 unsupported here"), std::string::npos) << r.output;
}

TEST(SweepCli, CrashedWorkerAndGlErrorCostOneRowEach) {
    const std::string dir = test::freshDir("sweep-crash");
    for (const char* fault : {"crash", "glerror"}) {
        const std::string csv = dir + "/" + fault + ".csv";
        // Configuration 1 (shadowmap, round 1) is sabotaged; round 2 runs in a fresh worker. Under
        // AddressSanitizer (scripts/sanitize.sh) the injected SIGSEGV must stay a signal, not become
        // ASan's report and exit 1, so its handler is off for this command (no effect without ASan).
        auto r =
            runCommand("ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:handle_segv=0\" SHADOWBENCH_FAULT_INJECT=" +
                       std::string(fault) + ":1 " +
                       bench("sweep -t none -t shadowmap --instances 3 --repeat 2 --csv " + csv + kQuick));
        EXPECT_EQ(r.exitCode, 1) << r.output;
        Table t(csv);
        ASSERT_EQ(t.size(), 4u) << fault;
        EXPECT_EQ(t.indices(), iota(4));
        for (size_t i = 0; i < t.size(); ++i) {
            const bool sabotaged = t.at(i, col::kConfigIndex) == "1";
            EXPECT_EQ(t.at(i, col::kStatus), sabotaged ? "failed" : "ok") << fault << " row " << i;
            if (sabotaged) {
                const std::string expected = std::string(fault) == "crash" ? "signal 11" : "GL_INVALID_ENUM";
                EXPECT_NE(t.at(i, col::kError).find(expected), std::string::npos) << t.at(i, col::kError);
            }
        }
    }
}

TEST(SweepCli, InterruptThenResumeLosesAndRepeatsNothing) {
    const std::string dir = test::freshDir("sweep-resume");
    const std::string csv = dir + "/s.csv", log = dir + "/log.txt";
    const std::string args = "sweep -t none --instances 2,3,4,5,6,7,8,9 --size 64x64 --frames 40 --warmup 1 "
                             "--no-progress --csv " +
                             csv;
    // Start it, wait for the first rows, then SIGINT the runner only: it must stop its worker too.
    const std::string command = "exec " + bench(args) + " > " + log + " 2>&1";
    const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
    pid_t pid = 0;
    ASSERT_EQ(posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ), 0);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    size_t rows = 0;
    while (std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        try {
            if (std::filesystem::exists(csv)) rows = CsvWriter::read(csv).rows.size();
        } catch (const std::exception&) {
        }
        if (rows >= 2) break;
    }
    ASSERT_GE(rows, 2u) << test::readFile(log);
    ::kill(pid, SIGINT);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130) << test::readFile(log);
    EXPECT_NE(test::readFile(log).find("--resume"), std::string::npos);
    const size_t before = Table(csv).size();
    EXPECT_GE(before, rows);
    EXPECT_LT(before, 8u) << "the interrupt came too late to test anything";

    // Without --resume the same command refuses to add to the file.
    auto again = runCommand(bench(args));
    EXPECT_EQ(again.exitCode, 2) << again.output;
    EXPECT_NE(again.output.find("pass --resume"), std::string::npos) << again.output;
    EXPECT_EQ(Table(csv).size(), before);

    auto resumed = runCommand(bench(args + " --resume"));
    ASSERT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_NE(resumed.output.find(std::to_string(before) + " done before"), std::string::npos)
        << resumed.output;
    EXPECT_EQ(Table(csv).indices(), iota(8)) << "nothing repeated, nothing lost";

    // A different sweep cannot append to it.
    auto other = runCommand(bench("sweep -t none --instances 2 --csv " + csv + kQuick));
    EXPECT_EQ(other.exitCode, 2);
    EXPECT_NE(other.output.find("not of this sweep"), std::string::npos) << other.output;
}

TEST(SweepCli, ShardsWithGnuParallelMergeIntoTheWholeSweep) {
    const std::string dir = test::freshDir("sweep-shards");
    const std::string axes = "-t none -t shadowmap --instances 2,3,4 --scale 1,2";
    // The unsharded plan: its id and size, from --dry-run.
    auto plan = runCommand(bench("sweep " + axes + kQuick + " --dry-run"));
    ASSERT_EQ(plan.exitCode, 0) << plan.output;
    const size_t open = plan.output.find("("), comma = plan.output.find(",", open);
    const std::string id = plan.output.substr(open + 1, comma - open - 1);
    ASSERT_EQ(id.size(), 16u) << plan.output;
    EXPECT_NE(plan.output.find("6 combinations, 12 configurations"), std::string::npos) << plan.output;

    auto r = runCommand("parallel --will-cite " + bench("sweep " + axes + kQuick) + " --shard {}/2 --csv " +
                        dir + "/part{}.csv ::: 1 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Table a(dir + "/part1.csv"), b(dir + "/part2.csv");
    EXPECT_EQ(a.size() + b.size(), 12u);
    for (const Table* t : {&a, &b})
        for (size_t i = 0; i < t->size(); ++i) EXPECT_EQ(t->at(i, col::kSweepId), id);
    // Round-robin: groups 0, 2, 4 in shard 1, groups 1, 3, 5 in shard 2.
    for (size_t i = 0; i < a.size(); ++i) EXPECT_EQ(std::stoul(a.at(i, col::kConfigGroup)) % 2, 0u);
    for (size_t i = 0; i < b.size(); ++i) EXPECT_EQ(std::stoul(b.at(i, col::kConfigGroup)) % 2, 1u);

    auto m = runCommand(bench("merge -o " + dir + "/all.csv " + dir + "/part1.csv " + dir + "/part2.csv"));
    ASSERT_EQ(m.exitCode, 0) << m.output;
    Table all(dir + "/all.csv");
    EXPECT_EQ(all.size(), 12u);
    for (size_t i = 0; i < all.size(); ++i)
        EXPECT_EQ(all.at(i, col::kConfigIndex), std::to_string(i)) << "sorted";

    // One shard alone is incomplete (exit 1), and says which configurations are missing.
    auto half = runCommand(bench("merge -o " + dir + "/half.csv " + dir + "/part1.csv"));
    EXPECT_EQ(half.exitCode, 1) << half.output;
    EXPECT_NE(half.output.find("6 of 12 configurations missing"), std::string::npos) << half.output;
    EXPECT_FALSE(std::filesystem::exists(dir + "/half.csv"));
}

TEST(SweepCli, RowsInJsonAndMarkdown) {
    const std::string dir = test::freshDir("sweep-formats");
    const std::string csv = dir + "/r.csv";
    // --format json: the rows on stdout, the human output on stderr.
    auto j =
        runCommand("(" + bench("-t none -t shadowmap --instances 2 --format json --csv " + csv + kQuickRun) +
                   " 2>/dev/null)");
    ASSERT_EQ(j.exitCode, 0) << j.output;
    const nlohmann::json doc = nlohmann::json::parse(j.output);
    ASSERT_EQ(doc["rows"].size(), 2u);
    EXPECT_EQ(doc["rows"][0][col::kTechnique], "none");
    EXPECT_TRUE(doc["rows"][1][col::kWallMsMedian].is_number());
    EXPECT_TRUE(doc["rows"][0][col::kGitCommit].is_string());
    // The same rows as the CSV, value for value.
    Table t(csv);
    EXPECT_NEAR(doc["rows"][1][col::kWallMsMedian].get<double>(), std::stod(t.at(1, col::kWallMsMedian)),
                1e-9);

    auto md = runCommand(bench("export " + csv + " --format md"));
    ASSERT_EQ(md.exitCode, 0) << md.output;
    EXPECT_NE(md.output.find("| technique"), std::string::npos) << md.output;
    EXPECT_NE(md.output.find("| shadowmap"), std::string::npos) << md.output;
    EXPECT_NE(md.output.find("Common to all 2 rows:"), std::string::npos) << md.output;

    auto bad = runCommand(bench("export " + csv + " --format yaml"));
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("yaml"), std::string::npos) << bad.output;
}

TEST(SweepCli, DefinitionFileAndBadAxes) {
    const std::string dir = test::freshDir("sweep-file");
    const std::string file = dir + "/s.json";
    std::ofstream(file)
        << R"({"name": "t", "techniques": ["none", {"name": "shadowmap", "properties": {"resolution": [256, 512]}}],
                              "instances": [2, 4], "frames": 2, "warmup": 1, "size": "64x64"})";
    auto plan = runCommand(bench("sweep " + file + " --dry-run"));
    ASSERT_EQ(plan.exitCode, 0) << plan.output;
    // 2 instance counts x (none + shadowmap at 2 resolutions) = 6 configurations.
    EXPECT_NE(plan.output.find("sweep 't'"), std::string::npos) << plan.output;
    EXPECT_NE(plan.output.find("2 combinations, 6 configurations"), std::string::npos) << plan.output;
    EXPECT_NE(plan.output.find("shadowmap:resolution=512"), std::string::npos) << plan.output;
    // The command line replaces the file's axis.
    auto cli = runCommand(bench("sweep " + file + " --instances 2 --dry-run"));
    EXPECT_NE(cli.output.find("1 combinations, 3 configurations"), std::string::npos) << cli.output;

    for (const auto& [args, needle] :
         std::vector<std::pair<std::string, std::string>>{{"--scene nosuch", "nosuch"},
                                                          {"--camera nowhere", "camera 'nowhere'"},
                                                          {"--submit retained,,immediate", "empty item"},
                                                          {"-t shadowmap:resolution=5", "resolution"},
                                                          {"--shard 3/2", "--shard 3/2"},
                                                          {"--size 10x10", "combination"}}) {
        auto r = runCommand(bench("sweep -t none --csv " + dir + "/x.csv " + args));
        EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find(needle), std::string::npos) << args << "\n" << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir + "/x.csv")) << args;
    }
}

/// The "every run: ..." line of a dry run (the options every worker gets), or "" when there is none.
std::string everyRunLine(const std::string& output) {
    const size_t at = output.find("\nevery run: ");
    return at == std::string::npos ? "" : output.substr(at + 1, output.find('\n', at + 1) - at - 1);
}

size_t occurrences(const std::string& text, const std::string& word) {
    size_t n = 0;
    for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + word.size())) ++n;
    return n;
}

// The command line replaces what the definition file says (README, "Sweep configurations"), for the
// run options as for the axes: the rows are measured with the command line's --frames, --warmup and
// --seed (the CSV's own columns say what each run used), and the file's values are gone.
TEST(SweepCli, CommandLineRunOptionsReplaceTheFiles) {
    const std::string dir = test::freshDir("sweep-override");
    const std::string file = dir + "/s.json", csv = dir + "/r.csv";
    std::ofstream(file) << R"({"name": "o", "techniques": ["none"], "instances": [2], "size": "64x64",
                              "frames": 20, "warmup": 5, "seed": 3, "args": ["--max-memory-gib", "4"]})";
    auto r = runCommand(bench(
        "sweep " + file + " --frames 2 --warmup 1 --seed 7 --max-memory-gib 2 --no-progress --csv " + csv));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    Table t(csv);
    ASSERT_EQ(t.size(), 1u);
    EXPECT_EQ(t.at(0, col::kStatus), "ok") << t.at(0, col::kError);
    EXPECT_EQ(t.at(0, col::kFrames), "2");
    EXPECT_EQ(t.at(0, col::kWarmup), "1");
    EXPECT_EQ(t.at(0, col::kSeed), "7");

    // The README's own example definition with a shorter run.
    const std::string example = std::string(SB_SOURCE_DIR) + "/sweeps/submission.json";
    auto plan = runCommand(bench("sweep " + example + " --frames 5 --dry-run"));
    ASSERT_EQ(plan.exitCode, 0) << plan.output;
    EXPECT_EQ(everyRunLine(plan.output), "every run: --warmup 5 --frames 5") << plan.output.substr(0, 300);
}

struct OverrideCase {
    const char* name;
    const char* file; ///< the definition's keys besides techniques
    const char* cli;  ///< what the command line gives
    const char* gone; ///< what of the file's must not reach the runs ("" for a flag: it appears once)
};

const OverrideCase kOverrides[] = {
    {"Frames", R"("frames": 20)", "--frames 5", "--frames 20"},
    {"SecondsReplaceFrames", R"("frames": 20)", "--seconds 0.5", "--frames"},
    {"FramesReplaceSeconds", R"("seconds": 2)", "--frames 5", "--seconds"},
    {"Warmup", R"("warmup": 5)", "--warmup 1", "--warmup 5"},
    {"Seed", R"("seed": 3)", "--seed 7", "--seed 3"},
    {"Backend", R"("backend": "osmesa")", "--backend egl-surfaceless", "osmesa"},
    {"RefSamples", R"("mode": "accuracy", "ref_samples": 16)", "--ref-samples 4", "--ref-samples 16"},
    {"Gpu", R"("args": ["--gpu", "1"])", "--gpu 0", "--gpu 1"},
    {"LightIndexWithEquals", R"("mode": "accuracy", "args": ["--light-index=1"])", "--light-index 0",
     "--light-index=1"},
    {"MaxMemory", R"("args": ["--max-memory-gib", "4"])", "--max-memory-gib 2", "--max-memory-gib 4"},
    {"Model", R"("args": ["--model", "a.obj"])", "--model b.obj", "a.obj"},
    {"NoTimerCheck", R"("args": ["--no-timer-check"])", "--no-timer-check", ""},
    {"NoStability", R"("mode": "accuracy", "stability": false)", "--no-stability", ""},
    {"StrictEffects", R"("args": ["--strict-effects"])", "--strict-effects", ""},
};

void PrintTo(const OverrideCase& c, std::ostream* os) {
    *os << c.name;
}

class SweepOverride : public ::testing::TestWithParam<OverrideCase> {};

// Every option `bench sweep` passes to its runs, given in the file and on the command line: the plan
// is valid (bench's parser takes an option once, so keeping both failed) and every run gets the
// command line's value only.
TEST_P(SweepOverride, CommandLineValueIsTheOneEveryRunGets) {
    const OverrideCase& c = GetParam();
    const std::string dir = test::freshTestDir("sweep-override");
    const std::string file = dir + "/s.json";
    std::ofstream(file) << R"({"techniques": ["none"], "size": "64x64", )" << c.file << "}";
    // The plan loads every combination's scene as its worker would, so the model files named must exist.
    for (const char* model : {"a.obj", "b.obj"})
        std::filesystem::copy_file(std::string(SB_SOURCE_DIR) + "/tests/data/cube.obj", dir + "/" + model);
    auto r = runCommand("cd " + dir + " && " + bench("sweep " + file + " " + c.cli + " --dry-run"));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string line = everyRunLine(r.output);
    EXPECT_EQ(occurrences(line, c.cli), 1u) << line;
    if (*c.gone) {
        EXPECT_EQ(line.find(c.gone), std::string::npos) << line;
    }
}

INSTANTIATE_TEST_SUITE_P(PassThrough, SweepOverride, ::testing::ValuesIn(kOverrides),
                         [](const auto& p) { return std::string(p.param.name); });

// The example definitions in sweeps/ stay valid: each dry-runs, with the number of combinations and
// configurations counted here from the JSON (product of the axes; per technique the product of its
// property value lists; times the rounds).
TEST(SweepCli, ExampleDefinitionsInSweepsFolderExpandAsCounted) {
    const std::filesystem::path folder = std::filesystem::path(SB_SOURCE_DIR) / "sweeps";
    size_t checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() != ".json") continue;
        const nlohmann::json j = nlohmann::json::parse(test::readFile(entry.path().string()));
        size_t combinations = 1;
        for (const char* axis :
             {"scenes", "instances", "scale", "tess", "tess_factor", "submit", "camera", "size", "light"})
            if (j.contains(axis) && j[axis].is_array()) combinations *= j[axis].size();
        size_t perCombination = 0;
        for (const auto& t : j["techniques"]) {
            size_t variants = 1;
            if (t.is_object() && t.contains("properties"))
                for (const auto& [key, values] : t[col::kProperties].items())
                    variants *= values.is_array() ? values.size() : 1;
            if (t.is_string()) {
                const std::string spec = t.get<std::string>();
                for (size_t eq = spec.find('='); eq != std::string::npos; eq = spec.find('=', eq + 1)) {
                    const std::string value = spec.substr(eq + 1, spec.find(':', eq) - eq - 1);
                    variants *= size_t(std::count(value.begin(), value.end(), ',')) + 1;
                }
            }
            perCombination += variants;
        }
        const size_t rounds = j.value("repeat", 1);
        const auto r = runCommand(bench("sweep " + entry.path().string() + " --dry-run"));
        ASSERT_EQ(r.exitCode, 0) << entry.path() << "\n" << r.output;
        const std::string expected = std::to_string(combinations) + " combinations, " +
                                     std::to_string(combinations * perCombination * rounds) +
                                     " configurations";
        EXPECT_NE(r.output.find(expected), std::string::npos)
            << entry.path() << ": expected " << expected << "\n"
            << r.output.substr(0, 300);
        ++checked;
    }
    EXPECT_GE(checked, 2u) << "the examples of the README are in sweeps/";
}
