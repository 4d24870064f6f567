// Atomic CSV appends (docs/ARCHITECTURE.md, "Results"): nothing lost, header union, RFC 4180 quoting,
// failures that leave the existing file byte-identical and no temporary files behind. Every expected file
// content is written out by hand; comparisons are exact (text, no tolerance).
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "core/Error.h"

using namespace sb;
using test::readFile;
using test::writeFile;
namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------------
// rename() seam. This executable's definition takes precedence over the C library's for every call,
// including the one inside CsvWriter, so a test can make the commit step fail or "crash" right after
// the temp file was written, fsync'ed and closed. Off by default: it then forwards to renameat(),
// which is what glibc's rename() does.
namespace {
enum class RenameMode { Real, Fail, Crash };
RenameMode gRenameMode = RenameMode::Real;
constexpr int kCrashExitCode = 42;
} // namespace

extern "C" int rename(const char* from, const char* to) noexcept {
    switch (gRenameMode) {
    case RenameMode::Fail:
        errno = EIO;
        return -1;
    case RenameMode::Crash:
        _exit(kCrashExitCode); // dies like a killed process: no unwinding, no cleanup
    case RenameMode::Real:
        break;
    }
    return renameat(AT_FDCWD, from, AT_FDCWD, to);
}

namespace {

class CsvWriterTest : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = test::freshTestDir("csv");
        mPath = mDir + "/results.csv";
    }
    void TearDown() override {
        gRenameMode = RenameMode::Real;
        fs::permissions(mDir, fs::perms::owner_all); // in case a test made it read-only
        fs::remove_all(mDir);
    }
    /// Names in the test directory other than `keep`: temp files a failed write left behind.
    std::vector<std::string> strayFiles(const std::string& keep = "results.csv") const {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(mDir))
            if (e.path().filename() != keep) out.push_back(e.path().filename().string());
        return out;
    }
    std::string errorOf(const std::vector<CsvRow>& rows, const std::string& path,
                        ExitCode expected = ExitCode::Failure) {
        try {
            CsvWriter::appendRows(path, rows);
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), expected) << e.what();
            return e.what();
        }
        ADD_FAILURE() << "appendRows(" << path << ") did not throw";
        return "";
    }
    std::string mDir, mPath;
};

TEST_F(CsvWriterTest, NewFileGetsHeaderAndRowsInGivenColumnOrder) {
    CsvWriter::appendRows(mPath, {{{"b", "1"}, {"a", "2"}}});
    EXPECT_EQ(readFile(mPath), "b,a\n1,2\n");
    EXPECT_TRUE(strayFiles().empty());
}

TEST_F(CsvWriterTest, AppendKeepsEarlierRows) {
    CsvWriter::appendRows(mPath, {{{"a", "1"}, {"b", "2"}}});
    CsvWriter::appendRows(mPath, {{{"a", "3"}, {"b", "4"}}, {{"a", "5"}, {"b", "6"}}});
    EXPECT_EQ(readFile(mPath), "a,b\n1,2\n3,4\n5,6\n");
}

TEST_F(CsvWriterTest, NewColumnsExtendTheHeaderWithEmptyCellsForOldRows) {
    CsvWriter::appendRows(mPath, {{{"technique", "none"}, {"gpu_lighting_ms_median", "1"}}});
    CsvWriter::appendRows(
        mPath, {{{"technique", "shadowmap"}, {"gpu_depth_ms_median", "2"}, {"gpu_lighting_ms_median", "3"}},
                {{"technique", "x"}}}); // a row lacking columns leaves them empty
    EXPECT_EQ(readFile(mPath), "technique,gpu_lighting_ms_median,gpu_depth_ms_median\n"
                               "none,1,\n"
                               "shadowmap,3,2\n"
                               "x,,\n");
}

TEST_F(CsvWriterTest, QuotingRoundTripsCommasQuotesAndNewlines) {
    const std::vector<std::string> tricky = {"a,b", "say \"hi\"", "two\nlines", "plain",
                                             "",    "\r\n",       "\"",         ",\"\n"};
    CsvRow row;
    for (size_t i = 0; i < tricky.size(); ++i) row.emplace_back("c" + std::to_string(i), tricky[i]);
    CsvWriter::appendRows(mPath, {row});
    CsvWriter::appendRows(mPath, {row}); // re-reading and re-writing must not change quoted cells
    CsvTable t = CsvWriter::read(mPath);
    ASSERT_EQ(t.rows.size(), 2u);
    for (const auto& r : t.rows)
        for (size_t i = 0; i < tricky.size(); ++i) EXPECT_EQ(r[i], tricky[i]) << "cell " << i;
    EXPECT_EQ(CsvWriter::quote("plain"), "plain");
    EXPECT_EQ(CsvWriter::quote("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(CsvWriter::quote("a,b"), "\"a,b\"");
    EXPECT_EQ(CsvWriter::quote("x\ny"), "\"x\ny\"");
}

TEST_F(CsvWriterTest, SingleEmptyCellSurvivesAsQuotedEmptyField) {
    // One column and an empty value would be a blank line, which the reader skips; the writer quotes it.
    CsvWriter::appendRows(mPath, {{{"note", ""}}, {{"note", "x"}}});
    EXPECT_EQ(readFile(mPath), "note\n\"\"\nx\n");
    EXPECT_EQ(CsvWriter::read(mPath).rows, (std::vector<std::vector<std::string>>{{""}, {"x"}}));
}

TEST_F(CsvWriterTest, ParseAcceptsCrLfAndBom) {
    CsvTable t = CsvWriter::parse("\xEF\xBB\xBF"
                                  "a,b\r\n1,\"x\r\ny\"\r\n",
                                  "t.csv");
    EXPECT_EQ(t.header, (std::vector<std::string>{"a", "b"}));
    EXPECT_EQ(t.rows, (std::vector<std::vector<std::string>>{{"1", "x\r\ny"}}));
    EXPECT_TRUE(CsvWriter::parse("", "empty.csv").header.empty());
}

TEST_F(CsvWriterTest, CellStartingWithAByteOrderMarkRoundTrips) {
    // Found by the CSV fuzzer: a header cell "\xEF\xBB\xBFa" (two BOMs in the text, the first stripped)
    // was written unquoted first in the file, and read back as the BOM and "a".
    const CsvTable t = CsvWriter::parse("\xEF\xBB\xBF\xEF\xBB\xBF"
                                        "a\n1\n",
                                        "bom.csv");
    ASSERT_EQ(t.header, (std::vector<std::string>{"\xEF\xBB\xBF"
                                                  "a"}));
    EXPECT_EQ(CsvWriter::parse(CsvWriter::serialize(t), "again.csv").header, t.header);
}

struct BadCsv {
    const char* name;
    const char* text;
    const char* where; ///< "file:line" the message must contain
};
const BadCsv kBadCsv[] = {
    {"too many fields", "a,b\n1,2\n1,2,3\n", "x.csv:3"},
    {"too few fields", "a,b\n1\n", "x.csv:2"},
    // The quoted newline makes row 2 span lines 2-3, so the ragged row starts on line 4.
    {"ragged after multi-line field", "a,b\n\"1\n2\",3\n4\n", "x.csv:4"},
    {"unclosed quote", "a,b\n\"1,2\n", "x.csv:2"},
    {"text after closing quote", "a,b\n\"1\"x,2\n", "x.csv:2"},
    {"quote in unquoted field", "a,b\n1\"2,3\n", "x.csv:2"},
    {"duplicate column", "a,a\n1,2\n", "x.csv:1"},
};

TEST_F(CsvWriterTest, MalformedFilesAreErrorsNamingFileAndLine) {
    for (const BadCsv& c : kBadCsv) {
        try {
            CsvWriter::parse(c.text, "x.csv");
            ADD_FAILURE() << c.name << ": accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(c.where), std::string::npos) << c.name << ": " << e.what();
        }
    }
}

TEST_F(CsvWriterTest, AppendToCorruptFileThrowsAndLeavesIt) {
    // A rewrite (a new column) reads every old row and refuses a ragged one; an in-place append reads
    // only the header and refuses a corrupt one.
    writeFile(mPath, "a,b\n1,2,3\n");
    EXPECT_THROW(CsvWriter::appendRows(mPath, {{{"c", "1"}}}), Error);
    EXPECT_EQ(readFile(mPath), "a,b\n1,2,3\n");
    writeFile(mPath, "a,a\n1,2,3\n");
    EXPECT_THROW(CsvWriter::appendRows(mPath, {{{"a", "1"}}}), Error);
    EXPECT_EQ(readFile(mPath), "a,a\n1,2,3\n");
    EXPECT_TRUE(strayFiles().empty());
}

TEST_F(CsvWriterTest, ReadOfMissingFileThrowsNamingThePath) {
    try {
        CsvWriter::read(mDir + "/nope.csv");
        FAIL() << "no throw";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(mDir + "/nope.csv"), std::string::npos) << e.what();
    }
}

TEST_F(CsvWriterTest, MissingDirectoryThrowsNamingThePath) {
    std::string path = mDir + "/no/such/dir/r.csv";
    std::string e = errorOf({{{"a", "1"}}}, path);
    EXPECT_NE(e.find(path), std::string::npos) << e;
    EXPECT_NE(e.find("No such file or directory"), std::string::npos) << e; // the OS reason
    EXPECT_THROW(CsvWriter::checkWritable(path), Error);
    EXPECT_TRUE(strayFiles().empty());
}

TEST_F(CsvWriterTest, UnwritableDirectoryLeavesFileByteIdentical) {
    if (geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions; see TempFileCannotBeCreated";
    CsvWriter::appendRows(mPath, {{{"a", "1"}}});
    std::string before = readFile(mPath);
    fs::permissions(mDir, fs::perms::owner_read | fs::perms::owner_exec);
    // A new column needs the rewrite through a temp file in the directory.
    std::string e = errorOf({{{"b", "2"}}}, mPath);
    EXPECT_NE(e.find(mPath), std::string::npos) << e;
    EXPECT_THROW(CsvWriter::checkWritable(mPath), Error);
    fs::permissions(mDir, fs::perms::owner_all);
    EXPECT_EQ(readFile(mPath), before);
    EXPECT_TRUE(strayFiles().empty());
}

TEST_F(CsvWriterTest, TempFileCannotBeCreatedLeavesFileByteIdentical) {
    // Works as root too: a 253-character name is valid, but "<name>.tmp" exceeds NAME_MAX (255), so the
    // temp file cannot be created in an otherwise writable directory.
    std::string name = std::string(249, 'r') + ".csv";
    std::string path = mDir + "/" + name;
    writeFile(path, "a\n1\n");
    std::string e = errorOf({{{"b", "2"}}}, path); // a new column: the rewrite needs the temp file
    EXPECT_NE(e.find(path), std::string::npos) << e;
    EXPECT_NE(e.find("File name too long"), std::string::npos) << e;
    EXPECT_EQ(readFile(path), "a\n1\n");
    EXPECT_TRUE(strayFiles(name).empty());
    EXPECT_THROW(CsvWriter::checkWritable(path), Error); // the up-front check sees it too
    // A new file of that name: the failed first write leaves no empty file behind.
    std::string fresh = mDir + "/" + std::string(249, 's') + ".csv";
    errorOf({{{"a", "2"}}}, fresh);
    EXPECT_FALSE(fs::exists(fresh));
    EXPECT_TRUE(strayFiles(name).empty());
}

TEST_F(CsvWriterTest, TempNameAtTheLimitIsWritable) {
    // The negative control of the test above: "<name>.tmp" is exactly NAME_MAX (255) characters, so the
    // probe of checkWritable (as long as the temp name) and the write must both succeed.
    std::string path = mDir + "/" + std::string(247, 'r') + ".csv";
    EXPECT_NO_THROW(CsvWriter::checkWritable(path));
    CsvWriter::appendRows(path, {{{"a", "1"}}});
    EXPECT_EQ(readFile(path), "a\n1\n");
}

TEST_F(CsvWriterTest, FailedRenameRemovesTempAndLeavesOriginal) {
    CsvWriter::appendRows(mPath, {{{"a", "1"}}});
    std::string before = readFile(mPath);
    gRenameMode = RenameMode::Fail;
    std::string e = errorOf({{{"b", "2"}}}, mPath); // a new column: rewritten, so renamed
    EXPECT_NE(e.find(mPath), std::string::npos) << e;
    EXPECT_NE(e.find("Input/output error"), std::string::npos) << e; // strerror(EIO) from the seam
    EXPECT_EQ(readFile(mPath), before);
    EXPECT_TRUE(strayFiles().empty());
}

TEST_F(CsvWriterTest, CrashBeforeRenameLeavesOriginalIntact) {
    CsvWriter::appendRows(mPath, {{{"a", "1"}}});
    std::string before = readFile(mPath);
    // The child process writes and fsyncs the temp file, then dies where the rename would be.
    EXPECT_EXIT(
        {
            gRenameMode = RenameMode::Crash;
            CsvWriter::appendRows(mPath, {{{"b", "2"}}}); // a new column: rewritten, so renamed
        },
        ::testing::ExitedWithCode(kCrashExitCode), "");
    EXPECT_EQ(readFile(mPath), before);
    // The crash left its complete temp file: proof the crash came after writing.
    std::vector<std::string> stray = strayFiles();
    ASSERT_EQ(stray.size(), 1u);
    EXPECT_EQ(stray[0], "results.csv.tmp");
    EXPECT_EQ(readFile(mDir + "/" + stray[0]), "a,b\n1,\n,2\n");
    // The next run is unaffected by the leftover, and reuses its name: crashes never pile up copies.
    CsvWriter::appendRows(mPath, {{{"a", "3"}}});
    EXPECT_EQ(readFile(mPath), "a\n1\n3\n");
    EXPECT_TRUE(strayFiles().empty());
}

TEST_F(CsvWriterTest, TargetThatIsADirectoryThrowsAndChangesNothing) {
    fs::create_directories(mPath);
    writeFile(mPath + "/keep.txt", "precious");
    std::string e = errorOf({{{"a", "1"}}}, mPath, ExitCode::BadInput);
    EXPECT_NE(e.find(mPath), std::string::npos) << e;
    EXPECT_EQ(readFile(mPath + "/keep.txt"), "precious");
    EXPECT_TRUE(strayFiles().empty());
    EXPECT_THROW(CsvWriter::checkWritable(mPath), Error);
}

TEST_F(CsvWriterTest, CheckWritableAcceptsNewAndExistingFilesAndLeavesNothing) {
    EXPECT_NO_THROW(CsvWriter::checkWritable(mPath));
    EXPECT_FALSE(fs::exists(mPath));
    CsvWriter::appendRows(mPath, {{{"a", "1"}}});
    EXPECT_NO_THROW(CsvWriter::checkWritable(mPath));
    EXPECT_EQ(readFile(mPath), "a\n1\n");
    EXPECT_TRUE(strayFiles().empty());
}

TEST_F(CsvWriterTest, ReplacingKeepsTheFileMode) {
    CsvWriter::appendRows(mPath, {{{"a", "1"}}});
    fs::permissions(mPath, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    CsvWriter::appendRows(mPath, {{{"a", "2"}}});
    EXPECT_EQ(fs::status(mPath).permissions() & fs::perms::mask,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
}

TEST_F(CsvWriterTest, NoRowsWritesNothing) {
    CsvWriter::appendRows(mPath, {});
    EXPECT_FALSE(fs::exists(mPath));
}

TEST_F(CsvWriterTest, RowNamingAColumnTwiceIsRejected) {
    CsvWriter::appendRows(mPath, {{{"a", "1"}}});
    std::string e = errorOf({{{"a", "2"}, {"a", "3"}}}, mPath);
    EXPECT_NE(e.find("'a'"), std::string::npos) << e;
    EXPECT_EQ(readFile(mPath), "a\n1\n");
}

} // namespace

// ---------------------------------------------------------------------------------------------------
// In-place appends: a row that fits the header is one write at the end of the file.

namespace {

struct stat statOf(const std::string& path) {
    struct stat st {};
    ::stat(path.c_str(), &st);
    return st;
}

} // namespace

TEST_F(CsvWriterTest, RowsThatFitTheHeaderAreAppendedInPlace) {
    // Same inode (no rename) and the earlier bytes unchanged; a subset of the columns gets empty cells.
    CsvWriter::appendRows(mPath, {{{"a", "1"}, {"b", "x"}}});
    const std::string before = readFile(mPath);
    const ino_t inode = statOf(mPath).st_ino;
    CsvWriter::appendRows(mPath, {{{"b", "y,z"}}, {{"a", "3"}, {"b", "w"}}});
    EXPECT_EQ(statOf(mPath).st_ino, inode);
    EXPECT_EQ(readFile(mPath), before + ",\"y,z\"\n3,w\n");
    // A new column or a cell with a line break needs the rewrite (a new inode).
    CsvWriter::appendRows(mPath, {{{"a", "two\nlines"}}});
    EXPECT_NE(statOf(mPath).st_ino, inode);
    EXPECT_EQ(readFile(mPath), "a,b\n1,x\n,\"y,z\"\n3,w\n\"two\nlines\",\n");
    EXPECT_TRUE(strayFiles().empty());
}

TEST_F(CsvWriterTest, PartialLastLineOfAKilledAppendIsSkippedThenCut) {
    // What a writer killed half-way through its in-place write leaves: complete rows, then part of one,
    // possibly inside a quoted cell. Readers skip it (a sweep's --resume measures it again); the next
    // append cuts it, keeping every complete row. A file ending in a newline inside an open quote is
    // still corrupt, not partial.
    for (const std::string& partial : {std::string("3,"), std::string("3,\"half, a cell")}) {
        writeFile(mPath, "a,b\n1,x\n2,\"y\"\n" + partial);
        const CsvTable table = CsvWriter::read(mPath);
        EXPECT_EQ(table.rows, (std::vector<std::vector<std::string>>{{"1", "x"}, {"2", "y"}})) << partial;
        CsvWriter::appendRows(mPath, {{{"a", "4"}, {"b", "z"}}});
        EXPECT_EQ(readFile(mPath), "a,b\n1,x\n2,\"y\"\n4,z\n"); // no row lost, the partial one gone
    }
    writeFile(mPath, "a,b\n1,\"open\n");
    EXPECT_THROW(CsvWriter::read(mPath), Error);
}

TEST_F(CsvWriterTest, HeaderMergeIsLinearInTheColumns) {
    // 10^4 and 10^5 columns side by side, best of three each: a linear merge takes about 10 times as
    // long for ten times the columns, the quadratic one it replaces (a find() over the header per
    // column) 100 times (20-67 s at 10^5). Bound 35: over three times the linear ratio, for a loaded
    // machine and the fixed costs that dominate at 10^4, and a third of the quadratic ratio.
    auto timeOf = [&](size_t columns) {
        double best = 1e30;
        for (int round = 0; round < 3; ++round) {
            fs::remove(mPath);
            CsvRow row;
            for (size_t c = 0; c < columns; ++c) row.emplace_back("column_" + std::to_string(c), "1");
            const auto start = std::chrono::steady_clock::now();
            CsvWriter::appendRows(mPath, {row});
            CsvWriter::appendRows(mPath, {row});
            const CsvTable table = CsvWriter::read(mPath);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            EXPECT_EQ(table.header.size(), columns);
            EXPECT_EQ(table.rows.size(), 2u);
            best = std::min(best, s);
        }
        return best;
    };
    const double small = timeOf(10000), large = timeOf(100000);
    EXPECT_LT(large / small, 35.0) << "10^4 columns: " << small << " s, 10^5: " << large << " s";
}

TEST_F(CsvWriterTest, ReplaceRowsDropsTheAcceptedRowsAndAppendsInOneRewrite) {
    // A sweep's retry: the failed row of configuration 1 goes, the new row (with a new column) comes,
    // every other row stays as it was, in its place; the filter sees the file's header and the cells.
    writeFile(mPath, "index,status\n0,ok\n1,failed\n2,failed\n");
    const ino_t inode = statOf(mPath).st_ino;
    CsvWriter::replaceRows(mPath,
                           [](const std::vector<std::string>& header, const std::vector<std::string>& cells) {
                               EXPECT_EQ(header, (std::vector<std::string>{"index", "status"}));
                               return cells[0] == "1" && cells[1] == "failed";
                           },
                           {{{"index", "1"}, {"status", "ok"}, {"wall", "2.5"}}});
    EXPECT_EQ(readFile(mPath), "index,status,wall\n0,ok,\n2,failed,\n1,ok,2.5\n");
    EXPECT_NE(statOf(mPath).st_ino, inode) << "a rewrite through the temp file and rename";
    EXPECT_TRUE(strayFiles().empty());
    // Nothing to add is nothing done: rows never leave the file without their replacement.
    CsvWriter::replaceRows(
        mPath, [](const std::vector<std::string>&, const std::vector<std::string>&) { return true; }, {});
    EXPECT_EQ(readFile(mPath), "index,status,wall\n0,ok,\n2,failed,\n1,ok,2.5\n");
}
