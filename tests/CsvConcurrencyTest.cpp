// Result files under hostile conditions (bench/lib/output/AtomicFile.h): several processes appending to one
// CSV at once, leftovers of killed writers, and paths that are not regular files. The expected outcome
// of each test is counted by hand (writers x rows), and every check is exact: a row is there once, or
// the test fails.
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
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

namespace {

class CsvConcurrencyTest : public ::testing::Test {
protected:
    void SetUp() override {
        mDir = test::freshTestDir("csvlock");
        mPath = mDir + "/results.csv";
    }
    void TearDown() override { fs::remove_all(mDir); }
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& e : fs::directory_iterator(mDir)) out.push_back(e.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }
    /// Forks a writer that calls `append(0)`, `append(1)`, ... until it is killed; once its first append
    /// is complete (it says so through a pipe, so a slow start is never killed before any write), waits
    /// `delay` and sends SIGKILL. False when the writer never completed an append.
    static bool killWriterMidway(const std::function<void(int)>& append, useconds_t delay) {
        int ready[2];
        if (::pipe(ready) != 0) return false;
        const pid_t pid = ::fork();
        if (pid == 0) {
            ::close(ready[0]);
            for (int i = 0;; ++i) {
                append(i);
                if (i == 0 && (::write(ready[1], "x", 1) != 1 || ::close(ready[1]) != 0)) ::_exit(1);
            }
        }
        ::close(ready[1]);
        char byte = 0;
        const bool started = ::read(ready[0], &byte, 1) == 1;
        ::close(ready[0]);
        if (started) ::usleep(delay);
        ::kill(pid, SIGKILL);
        ::waitpid(pid, nullptr, 0);
        return started;
    }
    /// Forks `writers` processes; writer w appends `rows` rows one call at a time, each naming
    /// (writer, seq) and, for odd writers, an extra column (so header merges race too). Returns the
    /// number of writers that exited 0.
    int hammer(int writers, int rows) const {
        std::vector<pid_t> pids;
        for (int w = 0; w < writers; ++w) {
            pid_t pid = ::fork();
            if (pid == 0) {
                int code = 0;
                try {
                    for (int i = 0; i < rows; ++i) {
                        CsvRow row{{"writer", std::to_string(w)}, {"seq", std::to_string(i)}};
                        if (w % 2) row.emplace_back("odd_" + std::to_string(w), "x");
                        CsvWriter::appendRows(mPath, {row});
                    }
                } catch (...) {
                    code = 1;
                }
                _exit(code);
            }
            pids.push_back(pid);
        }
        int ok = 0;
        for (pid_t pid : pids) {
            int status = 0;
            ::waitpid(pid, &status, 0);
            ok += WIFEXITED(status) && WEXITSTATUS(status) == 0;
        }
        return ok;
    }
    std::string mDir, mPath;
};

TEST_F(CsvConcurrencyTest, ManyWritersHammeringOneFileLoseNoRows) {
    // 8 processes x 40 single-row appends: 320 rows, each (writer, seq) exactly once. Without the lock
    // the read-merge-rename of one writer overwrites another's (measured: 30 of 120 rows lost with 2
    // writers of 60), so this fails on the unlocked writer.
    constexpr int kWriters = 8, kRows = 40;
    ASSERT_EQ(hammer(kWriters, kRows), kWriters);
    CsvTable t = CsvWriter::read(mPath);
    ASSERT_EQ(t.rows.size(), size_t(kWriters * kRows));
    auto col = [&](const std::string& c) {
        return size_t(std::find(t.header.begin(), t.header.end(), c) - t.header.begin());
    };
    std::map<std::pair<std::string, std::string>, int> seen;
    for (const auto& r : t.rows) ++seen[{r[col("writer")], r[col("seq")]}];
    EXPECT_EQ(seen.size(), size_t(kWriters * kRows));
    for (const auto& [key, n] : seen) EXPECT_EQ(n, 1) << key.first << "/" << key.second;
    // The header is the union: writer, seq and one column per odd writer.
    EXPECT_EQ(t.header.size(), 2u + kWriters / 2);
    for (int w = 1; w < kWriters; w += 2) EXPECT_LT(col("odd_" + std::to_string(w)), t.header.size());
    EXPECT_EQ(names(), (std::vector<std::string>{"results.csv"})); // no temp file left
}

TEST_F(CsvConcurrencyTest, LeftoversOfKilledWritersAreCleanedUp) {
    // A writer of an earlier version, killed mid-write, left "<file>.tmp.<pid>"; the pid is gone (a
    // child that has exited and been reaped). A temp of a live process (this test's parent) stays.
    CsvWriter::appendRows(mPath, {{{"a", "1"}}});
    pid_t dead = ::fork();
    if (dead == 0) _exit(0);
    ::waitpid(dead, nullptr, 0);
    const std::string stale = "results.csv.tmp." + std::to_string(dead);
    const std::string live = "results.csv.tmp." + std::to_string(::getppid());
    writeFile(mDir + "/" + stale, "a\n1\n");
    writeFile(mDir + "/" + live, "a\n1\n");
    writeFile(mDir + "/results.csv.tmp", "a\n1\nhalf"); // this version's leftover: reused
    CsvWriter::appendRows(mPath, {{{"a", "2"}}});
    EXPECT_EQ(readFile(mPath), "a\n1\n2\n");
    EXPECT_EQ(names(), (std::vector<std::string>{"results.csv", live}));
}

TEST_F(CsvConcurrencyTest, KilledWritersNeverPileUpTempFiles) {
    // 10 writers killed with SIGKILL at random points of their appends leave at most the one temp
    // name, never damage the rows already there, and the next append cleans the directory. Each
    // writer reports its first completed append through a pipe before the clock starts: on a loaded
    // machine a child can take longer than the sleep to get going, and a kill before any write
    // would test nothing (CI once killed the first writer before the file existed).
    CsvWriter::appendRows(mPath, {{{"a", "seed"}}});
    for (int k = 0; k < 10; ++k) {
        const bool started = killWriterMidway(
            [&](int i) {
                CsvWriter::appendRows(mPath, {{{"a", std::to_string(i)}}});
            },
            useconds_t(300 + 700 * k));
        ASSERT_TRUE(started) << "writer " << k << " never completed an append";
        EXPECT_LE(names().size(), 2u);
        const CsvTable table = CsvWriter::read(mPath); // never truncated: it parses
        ASSERT_FALSE(table.rows.empty());
        EXPECT_EQ(table.rows.front().front(), "seed"); // earlier rows survive every kill
    }
    CsvWriter::appendRows(mPath, {{{"a", "last"}}});
    EXPECT_EQ(names(), (std::vector<std::string>{"results.csv"}));
    const CsvTable table = CsvWriter::read(mPath);
    EXPECT_EQ(table.rows.front().front(), "seed");
    EXPECT_EQ(table.rows.back().front(), "last");
}

TEST_F(CsvConcurrencyTest, KilledInPlaceAppendsLoseNoRowAndKeepNoPartialRow) {
    // Rows of 1 MiB fit the header, so each is appended in place with one long write, which SIGKILL can
    // end half-way (a fatal signal stops a large write to a regular file early). After each kill the
    // next append must cut what was left, keep every complete row and add its own; the file then reads
    // back with every row whole. Whether a kill landed inside a write is timing; the count is printed.
    const std::string big(size_t(1) << 20, 'x');
    CsvWriter::appendRows(mPath, {{{"a", "seed"}, {"b", "0"}}});
    int partial = 0;
    for (int k = 0; k < 6; ++k) {
        const bool started = killWriterMidway(
            [&](int i) {
                CsvWriter::appendRows(mPath,
                                      {{{"a", std::to_string(k) + "-" + std::to_string(i)}, {"b", big}}});
            },
            useconds_t(2000 + 3000 * k));
        ASSERT_TRUE(started) << "writer " << k << " never completed an append";
        const std::string text = test::readFile(mPath);
        partial += !text.empty() && text.back() != '\n';
        CsvWriter::appendRows(mPath, {{{"a", "after" + std::to_string(k)}, {"b", "1"}}});
        const CsvTable table = CsvWriter::read(mPath); // no partial row: it parses
        ASSERT_GE(table.rows.size(), 3u);
        EXPECT_EQ(table.rows.front()[0], "seed");
        EXPECT_EQ(table.rows.back()[0], "after" + std::to_string(k));
        for (const auto& row : table.rows)
            EXPECT_TRUE(row[1] == "0" || row[1] == "1" || row[1] == big) << row[0] << ": " << row[1].size();
        size_t afters = 0;
        for (const auto& row : table.rows) afters += row[0].rfind("after", 0) == 0;
        EXPECT_EQ(afters, size_t(k + 1)); // every earlier "after" row survived the later kills
    }
    std::cout << "kills that left a partial last line: " << partial << " of 6\n";
}

TEST_F(CsvConcurrencyTest, SymbolicLinkIsFollowedAndKept) {
    writeFile(mDir + "/real.csv", "a\n1\n");
    fs::create_symlink("real.csv", mPath);
    CsvWriter::appendRows(mPath, {{{"a", "2"}}});
    EXPECT_TRUE(fs::is_symlink(mPath));
    EXPECT_EQ(readFile(mDir + "/real.csv"), "a\n1\n2\n");
}

/// Expects appendRows, writeText and checkWritable on `path` to refuse with BadInput naming the path
/// and `kind`, and leaves the node as it was.
void expectRefused(const std::string& path, const std::string& kind) {
    auto check = [&](auto&& call, const char* what) {
        try {
            call();
            ADD_FAILURE() << what << "(" << path << ") accepted it";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ExitCode::BadInput) << e.what();
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find(kind), std::string::npos) << e.what();
        }
    };
    check([&] { CsvWriter::appendRows(path, {{{"a", "1"}}}); }, "appendRows");
    check([&] { CsvWriter::writeText(path, "x"); }, "writeText");
    check([&] { CsvWriter::checkWritable(path); }, "checkWritable");
}

TEST_F(CsvConcurrencyTest, FifoIsRefusedWithoutBlocking) {
    // Opening a FIFO for writing blocks until a reader comes: the old writer hung here forever (the
    // test would hit ctest's timeout). It must be refused before it is opened.
    const std::string fifo = mDir + "/pipe.csv";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0644), 0) << std::strerror(errno);
    expectRefused(fifo, "a FIFO");
    struct stat st {};
    ASSERT_EQ(::stat(fifo.c_str(), &st), 0);
    EXPECT_TRUE(S_ISFIFO(st.st_mode)); // still a FIFO, not replaced by a file
    EXPECT_EQ(names(), (std::vector<std::string>{"pipe.csv"}));
}

TEST_F(CsvConcurrencyTest, CharacterDevicesAreRefusedAndNeverReplaced) {
    // Devices made in the scratch folder, never the system's own: a null-like (1,3) and a zero-like
    // (1,5) device. The old writer replaced the first by a regular file and read the second forever.
    const std::string null = mDir + "/null", zero = mDir + "/zero";
    if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
        GTEST_SKIP() << "mknod needs root (CAP_MKNOD): " << std::strerror(errno);
    ASSERT_EQ(::mknod(zero.c_str(), S_IFCHR | 0666, makedev(1, 5)), 0) << std::strerror(errno);
    expectRefused(null, "a character device");
    expectRefused(zero, "a character device");
    EXPECT_THROW(CsvWriter::read(zero), Error); // merge and export refuse to read it too
    struct stat st {};
    ASSERT_EQ(::stat(null.c_str(), &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
    EXPECT_EQ(names(), (std::vector<std::string>{"null", "zero"}));
}

TEST_F(CsvConcurrencyTest, EmptyPathIsBadInput) {
    try {
        CsvWriter::appendRows("", {{{"a", "1"}}});
        FAIL() << "accepted";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::BadInput);
        EXPECT_NE(std::string(e.what()).find("empty"), std::string::npos) << e.what();
    }
    EXPECT_THROW(CsvWriter::checkWritable(""), Error);
}

} // namespace
