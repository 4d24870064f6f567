// Result files far larger than a run's rows (docs/ARCHITECTURE.md, "Results"): export, compare and an
// append hold one row at a time, so their peak memory stays near the command's own and does not grow
// with the file. The file is made here: one real row of `bench -t none`, repeated, so every column is
// the bench's own. Peaks are measured (test::runCommandPeak), each bound stated with its reason.
#include <algorithm>
#include <filesystem>
#include <string>
#include <sys/stat.h>

#include <gtest/gtest.h>

#include "HostileSupport.h"
#include "TestPaths.h"
#include "TestSupport.h"

namespace {

constexpr size_t kTargetBytes = size_t(48)
                                << 20; // large enough that holding it shows, small enough to be quick
constexpr long kKiBPerMiB = 1024;

class LargeCsvCliTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        sDir = sb::test::freshDir("largecsv"); // once per suite: no current test to name it by
        const auto seed = sb::test::runCommand(
            "cd " + sDir + " && " + SB_BENCH_BINARY +
            " -t none --size 64x64 --frames 1 --warmup 0 --no-timer-check --csv seed.csv >/dev/null 2>&1");
        ASSERT_EQ(seed.exitCode, 0) << seed.output;
        const std::string text = sb::test::readFile(sDir + "/seed.csv");
        const size_t headerEnd = text.find('\n') + 1;
        const std::string header = text.substr(0, headerEnd), row = text.substr(headerEnd);
        ASSERT_EQ(std::count(row.begin(), row.end(), '\n'), 1) << "one row of one line expected";
        std::string big = header;
        big.reserve(kTargetBytes + row.size());
        sRows = 0;
        while (big.size() < kTargetBytes) {
            big += row;
            ++sRows;
        }
        sb::test::writeFile(sDir + "/big.csv", big);
        sBytes = big.size();
    }

    /// The peak of a small export (the seed's one row): what the command needs whatever the file.
    static long baselineKiB(const std::string& args) {
        return sb::test::runCommandPeak("cd " + sDir + " && exec " + SB_BENCH_BINARY + " " + args).peakRssKiB;
    }

    static long fileMiB() { return long(sBytes >> 20); }

    static inline std::string sDir;
    static inline size_t sRows = 0;
    static inline size_t sBytes = 0;
};

// Streaming keeps one row and one output block (1 MiB): the peak is the small file's peak plus 16 MiB
// of slack for allocator and page-cache noise, far below the file's size (48 MiB; the old export held
// the table and the whole JSON document, 16 times the file).
TEST_F(LargeCsvCliTest, JsonExportStreams) {
    const long base = baselineKiB("export seed.csv --format json -o seed.json");
    const auto r = sb::test::runCommandPeak("cd " + sDir + " && exec " + SB_BENCH_BINARY +
                                            " export big.csv --format json -o big.json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_LT(r.peakRssKiB, base + 16 * kKiBPerMiB)
        << "small file: " << base << " KiB; file " << fileMiB() << " MiB";
    const std::string json = sb::test::readFile(sDir + "/big.json");
    // Every row is there: one "status" key per row, and the document closes.
    size_t rows = 0;
    for (size_t at = json.find("\"status\": "); at != std::string::npos;
         at = json.find("\"status\": ", at + 1))
        ++rows;
    EXPECT_EQ(rows, sRows);
    EXPECT_EQ(json.substr(json.size() - 7), "\n  ]\n}\n");
}

TEST_F(LargeCsvCliTest, GoogleBenchmarkExportStreams) {
    const long base = baselineKiB("export seed.csv --format gbench -o seed.gbench.json");
    const auto r = sb::test::runCommandPeak("cd " + sDir + " && exec " + SB_BENCH_BINARY +
                                            " export big.csv --format gbench -o big.gbench.json");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_LT(r.peakRssKiB, base + 16 * kKiBPerMiB)
        << "small file: " << base << " KiB; file " << fileMiB() << " MiB";
    const std::string json = sb::test::readFile(sDir + "/big.gbench.json");
    size_t benchmarks = 0;
    for (size_t at = json.find("\"run_type\""); at != std::string::npos;
         at = json.find("\"run_type\"", at + 1))
        ++benchmarks;
    EXPECT_EQ(benchmarks, sRows);
}

// compare keeps only the columns the gate reads, but still every row of them (bench/lib/gate/WorkGate.h
// compares tables): measured 190 MiB over the small file's peak for this 48 MiB file, where the old
// code, holding every column, took 480 MiB over it. Bound: five times the file over the small file's
// peak, which the old code exceeds twice over.
TEST_F(LargeCsvCliTest, CompareKeepsOnlyTheColumnsItNeeds) {
    const long base = baselineKiB("compare seed.csv seed.csv");
    const auto r =
        sb::test::runCommandPeak("cd " + sDir + " && exec " + SB_BENCH_BINARY + " compare big.csv big.csv");
    EXPECT_NE(r.output.find("(" + std::to_string(sRows) + " rows)"), std::string::npos) << r.output;
    EXPECT_LT(r.peakRssKiB, base + long(5 * sBytes / 1024))
        << "small file: " << base << " KiB; file " << fileMiB() << " MiB";
}

// Appending a row whose columns are the file's header writes only that row: the same inode (no
// rename), the earlier bytes unchanged, and the peak that of the same run on a small file plus 128 MiB
// (llvmpipe's peak varies between runs, by up to 80 MiB measured under the load of a test run; the old
// append read, parsed and rewrote the whole file: 290 MiB over the small file's peak for this 48 MiB
// file). The inode and the unchanged bytes are the exact proof; the peak shows nothing else grows.
TEST_F(LargeCsvCliTest, AppendingOneRowDoesNotRewriteTheFile) {
    const std::string quick = " -t none --size 64x64 --frames 1 --warmup 0 --no-timer-check --csv ";
    const long base = baselineKiB(quick + "seed.csv");
    const std::string path = sDir + "/append.csv";
    const std::string before = sb::test::readFile(sDir + "/big.csv");
    sb::test::writeFile(path, before);
    struct stat st {};
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    const ino_t inode = st.st_ino;
    const auto r =
        sb::test::runCommandPeak("cd " + sDir + " && exec " + SB_BENCH_BINARY + quick + "append.csv");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_LT(r.peakRssKiB, base + 128 * kKiBPerMiB)
        << "small file: " << base << " KiB; file " << fileMiB() << " MiB";
    ASSERT_EQ(::stat(path.c_str(), &st), 0);
    EXPECT_EQ(st.st_ino, inode) << "the file was replaced, not appended to";
    const std::string after = sb::test::readFile(path);
    ASSERT_GT(after.size(), before.size());
    EXPECT_TRUE(after.compare(0, before.size(), before) == 0) << "earlier bytes changed";
    EXPECT_EQ(std::count(after.begin() + long(before.size()), after.end(), '\n'), 1);
}

} // namespace

namespace {

// The in-place path on a full disk does what the rewrite does there: exit 1, one line naming the path
// and the OS reason, the earlier rows byte-identical (a short write is cut back), no file left beside.
TEST_F(LargeCsvCliTest, InPlaceAppendOnAFullDiskKeepsTheFile) {
    // The file is padded (in its empty `device` cell) to whole 4 KiB pages: a full tmpfs still takes
    // bytes into a file's last, partly used page, so only a file ending on a page boundary is refused.
    std::string seed = sb::test::readFile(sDir + "/seed.csv");
    const size_t cell = seed.find(",egl-surfaceless,,");
    ASSERT_NE(cell, std::string::npos) << seed;
    seed.insert(cell + 17, (4096 - seed.size() % 4096) % 4096, 'x');
    ASSERT_EQ(seed.size() % 4096, 0u);
    sb::test::FullDisk disk(sDir + "/full");
    disk.plant("pre.csv", seed);
    const auto r =
        sb::test::runCommand(disk.wrap("(" + std::string(SB_BENCH_BINARY) +
                                       " -t none --size 64x64 --frames 1 --warmup 0 --no-timer-check --csv " +
                                       disk.dir() + "/pre.csv >/dev/null)"));
    EXPECT_EQ(r.exitCode, 1) << disk.how() << ": " << r.output;
    EXPECT_NE(
        r.output.find("bench: error: cannot write CSV '" + disk.dir() + "/pre.csv': cannot append to it"),
        std::string::npos)
        << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_EQ(sb::test::readFile(disk.dir() + "/pre.csv"), seed);
    EXPECT_FALSE(std::filesystem::exists(disk.dir() + "/pre.csv.tmp"));
}

} // namespace
