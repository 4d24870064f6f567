// `bench merge` as a Slurm merge job's log shows it: hand-made shard CSVs of a small sweep, the exit
// code (0 complete, 1 configurations missing or failed, 2 inputs that do not fit together), the one line
// on stderr of a refusal, and the report's lines: the hosts, each mixture let through, and what each
// shard lacks with the command that completes it. The shards of the split are worked out by hand from
// SweepPlan::shard's rule (group g runs in shard (g mod N) + 1 of N).
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"

using namespace sb;
using test::runCommand;
using test::writeFile;

namespace {

const std::string kBench = SB_BENCH_BINARY;

constexpr const char* kHeader =
    "sweep_id,sweep_name,sweep_configs,config_index,config_group,shard,status,cpu_model,git_commit,host\n";

/// A row of a sweep of 12 configurations in groups of two, split 4 ways.
std::string row(size_t index, const std::string& status = "ok", const std::string& cpu = "AMD EPYC 7B13",
                const std::string& host = "node1") {
    const size_t group = index / 2;
    return "s1,study,12," + std::to_string(index) + "," + std::to_string(group) + "," +
           std::to_string(group % 4 + 1) + "/4," + status + "," + cpu + ",fd7aef0," + host + "\n";
}

class MergeCli : public ::testing::Test {
protected:
    void SetUp() override { mDir = test::freshTestDir("merge-cli"); }
    void TearDown() override {
        std::error_code ec;
        std::filesystem::remove_all(mDir, ec);
    }
    std::string path(const std::string& name) const { return mDir + "/" + name; }
    test::CommandResult merge(const std::string& args) {
        return runCommand("cd " + mDir + " && " + kBench + " merge " + args);
    }
    bool has(const test::CommandResult& r, const std::string& line) const {
        return r.output.find(line) != std::string::npos;
    }
    /// Shards 1, 3 and 4 of 4 (groups 0 and 4, 2, 3: indices 0-1 and 8-9, 4-5, 6-7), all ok, on the
    /// given hosts; shard 2 (indices 2-3 and 10-11) is written by each test as it needs.
    void writeShards134(const std::string& cpu4 = "AMD EPYC 7B13") {
        writeFile(path("part1.csv"),
                  kHeader + row(0) + row(1) + row(8, "ok", "AMD EPYC 7B13", "node2") + row(9));
        writeFile(path("part3.csv"), kHeader + row(4, "ok", "AMD EPYC 7B13", "node3") + row(5));
        writeFile(path("part4.csv"), kHeader + row(6, "ok", cpu4) + row(7, "ok", cpu4));
    }
    std::string mDir;
};

TEST_F(MergeCli, CompleteShardsMergeAndCountTheirHosts) {
    writeShards134();
    writeFile(path("part2.csv"), kHeader + row(2) + row(3) + row(10) + row(11));
    const auto r = merge("-o all.csv part1.csv part2.csv part3.csv part4.csv");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(has(r, "merged 4 files of sweep s1 ('study'): 12 rows of 12 configurations -> all.csv\n"))
        << r.output;
    EXPECT_TRUE(has(r, "\nrows from 3 hosts\n")) << r.output; // node1, node2, node3: never refused
    EXPECT_EQ(CsvWriter::read(path("all.csv")).rows.size(), 12u);
}

TEST_F(MergeCli, MixedCpuModelsAreRefusedNamingBothFiles) {
    // Exit 2 (the inputs do not fit together), one line naming the column, both values and the first
    // file and line of each; nothing written.
    writeShards134("Intel Xeon Gold 6338");
    writeFile(path("part2.csv"), kHeader + row(2) + row(3) + row(10) + row(11));
    const auto r = merge("-o all.csv part1.csv part2.csv part3.csv part4.csv");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_EQ(r.output,
              "bench: error: rows of different measurements mixed: cpu_model 'AMD EPYC 7B13' in "
              "'part1.csv:2' but 'Intel Xeon Gold 6338' in 'part4.csv:2'; merge the shards of one "
              "commit, CPU model, renderer and driver, or pass --allow-mixed to merge them anyway\n");
    EXPECT_FALSE(std::filesystem::exists(path("all.csv")));
}

TEST_F(MergeCli, AllowMixedMergesAndListsEachMixture) {
    writeShards134("Intel Xeon Gold 6338");
    writeFile(path("part2.csv"), kHeader + row(2) + row(3) + row(10) + row(11));
    const auto r = merge("-o all.csv --allow-mixed part1.csv part2.csv part3.csv part4.csv");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(has(r, "warning: rows of different measurements merged (--allow-mixed)")) << r.output;
    EXPECT_TRUE(has(r, "\n  cpu_model: 'AMD EPYC 7B13' 10 rows (first in 'part1.csv:2'), 'Intel Xeon Gold "
                       "6338' 2 rows (first in 'part4.csv:2')\n"))
        << r.output;
    EXPECT_EQ(CsvWriter::read(path("all.csv")).rows.size(), 12u);
}

TEST_F(MergeCli, MissingAndFailedRowsAreListedPerShardWithTheCommandsThatRerunThem) {
    // Shard 2 never ran (indices 2-3, 10-11), index 7 of shard 4 is lost, index 9 of shard 1 failed.
    writeFile(path("part1.csv"), kHeader + row(0) + row(1) + row(8) + row(9, "failed", ""));
    writeFile(path("part3.csv"), kHeader + row(4) + row(5));
    writeFile(path("part4.csv"), kHeader + row(6));
    const auto r = merge("-o all.csv part1.csv part3.csv part4.csv");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    const std::string expected =
        "read 3 files of sweep s1 ('study'): 7 rows of 12 configurations (1 failed), 5 missing; nothing "
        "written\n"
        "rows from 1 host\n"
        "incomplete: 5 of 12 configurations missing (indices 2-3, 7, 10-11), 1 failed (indices 9)\n"
        "  shard 1/4: failed 9\n"
        "  shard 2/4: missing 2-3, 10-11 (no input holds this shard's rows)\n"
        "  shard 4/4: missing 7\n"
        "to complete the sweep, rerun these shards, then merge again (DEF: the definition of sweep s1 "
        "'study' with the options its shards ran with; rows already there are kept):\n"
        "  bench sweep DEF --shard 1/4 --csv part1.csv --resume --retry-failed\n"
        "  bench sweep DEF --shard 2/4 --csv part2.csv --resume --retry-failed\n"
        "  bench sweep DEF --shard 4/4 --csv part4.csv --resume --retry-failed\n"
        "bench: error: incomplete: 5 of 12 configurations missing (indices 2-3, 7, 10-11), 1 failed "
        "(indices 9); nothing written: rerun the shards listed above, or pass --allow-incomplete\n";
    EXPECT_EQ(r.output, expected);
    EXPECT_FALSE(std::filesystem::exists(path("all.csv")));

    // Told to, it writes what is there, still lists the gaps, and exits 0.
    const auto allowed = merge("-o all.csv --allow-incomplete part1.csv part3.csv part4.csv");
    EXPECT_EQ(allowed.exitCode, 0) << allowed.output;
    EXPECT_TRUE(has(allowed, "  shard 2/4: missing 2-3, 10-11")) << allowed.output;
    EXPECT_EQ(CsvWriter::read(path("all.csv")).rows.size(), 7u);
}

TEST_F(MergeCli, AMixtureIsBadInputEvenWhenRowsAreMissing) {
    // Exit 2 comes first: rerunning the missing shard would not make the rows one measurement.
    writeShards134("Intel Xeon Gold 6338");
    const auto r = merge("-o all.csv part1.csv part3.csv part4.csv");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_TRUE(has(r, "cpu_model")) << r.output;
}

TEST_F(MergeCli, AllowMixedTimerStillLetsOnlyTheVerdictsThrough) {
    const std::string header = "sweep_id,sweep_configs,config_index,shard,status,timer_verdict\n";
    writeFile(path("a.csv"), header + "s1,2,0,1/2,ok,trusted\n");
    writeFile(path("b.csv"), header + "s1,2,1,2/2,ok,untrusted\n");
    const auto r = merge("-o all.csv --allow-mixed-timer a.csv b.csv");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(has(r, "warning: rows carry different GPU-timer verdicts: trusted 1 untrusted 1"))
        << r.output;
}

} // namespace
