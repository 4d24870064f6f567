// Several bench processes appending to one --csv at once, as users do: plain runs started side by side
// and two shards of one sweep sharing a file. Every row each process reports must be in the file once
// (counted by hand from the commands: processes x runs x techniques), and every process exits 0.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

const std::string kQuick = " --scene synthetic_draws --size 32x32 --frames 1 --warmup 0";

size_t column(const CsvTable& t, const std::string& name) {
    return size_t(std::find(t.header.begin(), t.header.end(), name) - t.header.begin());
}

/// Runs the shell `jobs` at the same time (each in the background of one bash) and waits for all;
/// the exit code is 0 only when every job exited 0.
test::CommandResult runSideBySide(const std::vector<std::string>& jobs) {
    std::string script;
    for (const std::string& job : jobs) script += "( " + job + " ) & ";
    script += "fail=0; for j in $(jobs -p); do wait $j || fail=1; done; exit $fail";
    return test::runCommand("bash -c '" + script + "'");
}

TEST(ConcurrentCsvCli, PlainRunsSideBySideKeepEveryRow) {
    // 4 shells x 3 runs x 2 techniques = 24 rows; each run is tagged by its seed (shell * 10 + run).
    const std::string dir = test::freshDir("concurrent-runs"), csv = dir + "/all.csv";
    std::vector<std::string> shells;
    for (int shell = 1; shell <= 4; ++shell)
        shells.push_back("set -e; for r in 1 2 3; do " + std::string(SB_BENCH_BINARY) + " -t none -t blob" +
                         kQuick + " --no-timer-check -q --seed " + std::to_string(shell) + "$r --csv " + csv +
                         " >/dev/null; done");
    const auto r = runSideBySide(shells);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const CsvTable t = CsvWriter::read(csv);
    ASSERT_EQ(t.rows.size(), 24u);
    std::map<std::string, int> perSeed;
    for (const auto& row : t.rows)
        ++perSeed[row[column(t, col::kSeed)] + "/" + row[column(t, col::kTechnique)]];
    EXPECT_EQ(perSeed.size(), 24u); // every (seed, technique) once
    for (const auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().filename(), "all.csv") << "left behind: " << e.path();
}

TEST(ConcurrentCsvCli, TwoShardsOfOneSweepShareAFile) {
    // 6 instance counts x 2 techniques = 12 rows, split over two shards writing one CSV at once.
    const std::string dir = test::freshDir("concurrent-shards"), csv = dir + "/sweep.csv";
    std::vector<std::string> shards;
    for (int shard = 1; shard <= 2; ++shard)
        shards.push_back(std::string(SB_BENCH_BINARY) + " sweep -t none -t blob -n 1,2,3,4,5,6" + kQuick +
                         " --no-progress --shard " + std::to_string(shard) + "/2 --csv " + csv +
                         " >/dev/null");
    const auto r = runSideBySide(shards);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const CsvTable t = CsvWriter::read(csv);
    ASSERT_EQ(t.rows.size(), 12u);
    std::map<std::string, int> perConfig;
    for (const auto& row : t.rows) ++perConfig[row[column(t, col::kConfigIndex)]];
    EXPECT_EQ(perConfig.size(), 12u); // config_index 0..11, each once
}

} // namespace
