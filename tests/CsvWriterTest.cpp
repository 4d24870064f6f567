// Atomic CSV appends (DESIGN.md section 7): nothing lost, header union, RFC 4180 quoting, failures that
// leave the existing file byte-identical and no temporary files behind.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "bench/CsvWriter.h"
#include "scenes/Error.h"
#include "TestSupport.h"

using namespace sb;
namespace fs = std::filesystem;

namespace {

TEST(CsvWriterTest, NewFileThenAppendKeepsEarlierRows) {
    std::string dir = test::freshDir("csv-append");
    std::string path = dir + "/r.csv";
    CsvWriter::appendRows(path, {{{"a", "1"}, {"b", "2"}}});
    CsvWriter::appendRows(path, {{{"a", "3"}, {"b", "4"}}, {{"a", "5"}, {"b", "6"}}});
    EXPECT_EQ(test::readFile(path), "a,b\n1,2\n3,4\n5,6\n");
}

TEST(CsvWriterTest, NewColumnsExtendTheHeaderWithEmptyCellsForOldRows) {
    std::string path = test::freshDir("csv-union") + "/r.csv";
    CsvWriter::appendRows(path, {{{"technique", "none"}, {"gpu_lighting_ms_median", "1"}}});
    CsvWriter::appendRows(path, {{{"technique", "shadowmap"}, {"gpu_depth_ms_median", "2"}, {"gpu_lighting_ms_median", "3"}}});
    EXPECT_EQ(test::readFile(path), "technique,gpu_lighting_ms_median,gpu_depth_ms_median\n"
                                    "none,1,\n"
                                    "shadowmap,3,2\n");
}

TEST(CsvWriterTest, QuotingRoundTrips) {
    std::string path = test::freshDir("csv-quote") + "/r.csv";
    const std::string tricky[] = {"a,b", "say \"hi\"", "two\nlines", "plain", "", "\r\n"};
    CsvRow row;
    for (size_t i = 0; i < std::size(tricky); ++i) row.emplace_back("c" + std::to_string(i), tricky[i]);
    CsvWriter::appendRows(path, {row});
    CsvTable t = CsvWriter::read(path);
    ASSERT_EQ(t.rows.size(), 1u);
    for (size_t i = 0; i < std::size(tricky); ++i) EXPECT_EQ(t.rows[0][i], tricky[i]) << i;
    EXPECT_EQ(CsvWriter::quote("say \"hi\""), "\"say \"\"hi\"\"\"");
}

TEST(CsvWriterTest, RaggedRowsAreErrorsNamingTheFile) {
    try {
        CsvWriter::parse("a,b\n1,2,3\n", "x.csv");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("x.csv"), std::string::npos) << e.what();
    }
}

TEST(CsvWriterTest, MissingDirectoryThrowsNamingThePath) {
    std::string path = test::freshDir("csv-missing") + "/no/such/dir/r.csv";
    try {
        CsvWriter::appendRows(path, {{{"a", "1"}}});
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        EXPECT_EQ(e.code(), ExitCode::Failure);
    }
}

TEST(CsvWriterTest, FailedRenameLeavesOriginalAndNoTempFile) {
    // The target is a directory: the temp file is written, the rename must fail. The directory and its
    // content stay as they were and the temp file is removed.
    std::string dir = test::freshDir("csv-rename");
    std::string path = dir + "/r.csv";
    fs::create_directories(path);
    std::ofstream(path + "/keep.txt") << "precious";
    EXPECT_THROW(CsvWriter::appendRows(path, {{{"a", "1"}}}), Error);
    EXPECT_EQ(test::readFile(path + "/keep.txt"), "precious");
    for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().filename(), "r.csv") << e.path();
}

TEST(CsvWriterTest, UnwritableDirectoryLeavesFileByteIdentical) {
    if (geteuid() == 0) {
        // root ignores directory permissions; use a path under /proc, which nobody can create files in.
        // Root ignores directory permissions; /proc refuses new files even to root.
        EXPECT_THROW(CsvWriter::appendRows("/proc/shadowbench-test/r.csv", {{{"a", "1"}}}), Error);
        return;
    }
    std::string dir = test::freshDir("csv-ro");
    std::string path = dir + "/r.csv";
    CsvWriter::appendRows(path, {{{"a", "1"}}});
    std::string before = test::readFile(path);
    fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_THROW(CsvWriter::appendRows(path, {{{"a", "2"}}}), Error);
    fs::permissions(dir, fs::perms::owner_all);
    EXPECT_EQ(test::readFile(path), before);
}
} // namespace
