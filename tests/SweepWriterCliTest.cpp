// `bench sweep` as a batch system runs it: one writer per shard of a CSV (a second run of the same
// shard is refused naming the first, a lock left by a dead process blocks nothing), --resume refusing a
// part file of another split, --retry-failed replacing failed rows so that the file keeps one row per
// configuration, and rows that say where they ran (host, Slurm job and array task) and on how many
// CPUs (the affinity mask under `taskset`, for the row and for the reference tracer). The answers are
// written by hand: the exit codes of `bench sweep --help`, the configurations counted from the axes,
// the host from gethostname() and the CPUs from sched_getaffinity().
#include <algorithm>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <sched.h>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/file.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/CsvWriter.h"
#include "bench/lib/output/ResultColumns.h"

extern char** environ;

using namespace sb;
namespace fs = std::filesystem;

namespace {

using Rows = std::vector<std::map<std::string, std::string>>;

// Tiny runs: these tests check the machinery, not performance. No timer check: a second each saved.
const std::string kQuick = " --size 64x64 --frames 2 --warmup 1 --no-timer-check --no-progress";
// Outside Slurm whatever runs the tests: the rows' Slurm columns are then known to be empty.
const std::string kNoSlurm = "env -u SLURM_JOB_ID -u SLURM_ARRAY_JOB_ID -u SLURM_ARRAY_TASK_ID ";

std::string bench(const std::string& args) {
    return kNoSlurm + SB_BENCH_BINARY + " " + args;
}

std::string hostName() {
    char name[256] = {};
    ::gethostname(name, sizeof name - 1);
    return name;
}

/// The CPUs this test process may run on, in order (sched_getaffinity: the independent answer).
std::vector<int> allowedCpus() {
    cpu_set_t set;
    CPU_ZERO(&set);
    std::vector<int> out;
    if (::sched_getaffinity(0, sizeof set, &set) != 0) return out;
    for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu)
        if (CPU_ISSET(cpu, &set)) out.push_back(cpu);
    return out;
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);)
        if (!l.empty()) out.push_back(l);
    return out;
}

/// Each config_index and how many rows it has.
std::map<std::string, int> rowsPerIndex(const Rows& rows) {
    std::map<std::string, int> out;
    for (const auto& r : rows) ++out[r.at(col::kConfigIndex)];
    return out;
}

/// A shell command started in the background; its pid is the command's own (`exec`).
pid_t spawnShell(const std::string& command) {
    const std::string line = "exec " + command;
    const char* argv[] = {"/bin/sh", "-c", line.c_str(), nullptr};
    pid_t pid = 0;
    return posix_spawn(&pid, "/bin/sh", nullptr, nullptr, const_cast<char**>(argv), environ) == 0 ? pid : -1;
}

/// Waits until `lock` exists or `csv` holds a row (a run that takes no lock is under way too); false
/// when the deadline passed first.
bool waitForWriter(const std::string& lock, const std::string& csv) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        try {
            if (fs::exists(lock) || (fs::exists(csv) && !CsvWriter::read(csv).rows.empty())) return true;
        } catch (const std::exception&) {
        }
    }
    return false;
}

int waitExit(pid_t pid) {
    int status = 0;
    if (::waitpid(pid, &status, 0) != pid) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

/// The test's fresh folder, its path resolved as the lock files' are (ShardLock::pathFor).
std::string freshDir() {
    return fs::weakly_canonical(test::freshTestDir("sweep-writer")).string();
}

std::vector<std::string> lockFiles(const std::string& dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ".lock") out.push_back(e.path().filename().string());
    return out;
}

} // namespace

// The same shard started twice, as a job array submitted twice does: the second run (with --resume, as
// a requeued task has) is refused while the first runs, exit 1, one line naming the first's host, pid
// and Slurm array task; the file then holds each configuration once. Before the lock, the second ran
// the configurations the first had not finished yet, and both wrote them.
TEST(SweepWriterCli, SecondWriterOfAShardIsRefusedNamingTheFirst) {
    const std::string dir = freshDir();
    const std::string csv = dir + "/part.csv", log = dir + "/first.txt";
    // 8 groups of 100 frames: seconds of work, interrupted below once the second run has been refused.
    const std::string args = "sweep -t none --instances 2,3,4,5,6,7,8,9 --frames 100 --warmup 1 --size 64x64 "
                             "--no-timer-check --no-progress --csv " +
                             csv;
    const pid_t first = spawnShell("env SLURM_JOB_ID=4243 SLURM_ARRAY_JOB_ID=4240 SLURM_ARRAY_TASK_ID=3 " +
                                   std::string(SB_BENCH_BINARY) + " " + args + " > " + log + " 2>&1");
    ASSERT_GT(first, 0);
    ASSERT_TRUE(waitForWriter(csv + ".shard-1-of-1.lock", csv)) << test::readFile(log);

    const auto second = test::runCommand("timeout 120 " + bench(args + " --resume"));
    // A row of the first run's before it is stopped, to read where it ran.
    EXPECT_TRUE(waitForWriter(dir + "/no-such.lock", csv)) << test::readFile(log);
    ::kill(first, SIGINT);
    EXPECT_EQ(waitExit(first), 130) << test::readFile(log);
    const Rows rows = test::csvRowMaps(csv);
    ASSERT_FALSE(rows.empty());
    for (const auto& [index, count] : rowsPerIndex(rows)) EXPECT_EQ(count, 1) << "config_index " << index;
    for (const auto& r : rows) {
        EXPECT_EQ(r.at(col::kHost), hostName());
        EXPECT_EQ(r.at(col::kSlurmJobId), "4240") << "an array task's job is the array's";
        EXPECT_EQ(r.at(col::kSlurmArrayTaskId), "3");
    }
    EXPECT_EQ(second.exitCode, 1) << second.output;
    const std::vector<std::string> said = lines(second.output);
    EXPECT_EQ(said.size(), 1u) << second.output;
    const std::string message = said.empty() ? "" : said[0];
    for (const std::string& word :
         {std::string("bench: error: "), "shard 1/1 of '" + csv + "'", "host " + hostName(),
          "pid " + std::to_string(first), std::string("Slurm job 4240_3 (SLURM_JOB_ID 4243)"),
          std::string("part.csv.shard-1-of-1.lock"), std::string("nothing was written")})
        EXPECT_NE(message.find(word), std::string::npos) << "lacks '" << word << "': " << message;
    EXPECT_TRUE(lockFiles(dir).empty()) << "the first run's lock stays after its end";
}

// The refusal without a race: this test process holds the shard's lock itself, with a holder's text
// as a sweep writes it. The sweep exits 1 with the holder named and writes nothing: no CSV appears.
TEST(SweepWriterCli, HeldLockIsRefusedAndNothingIsWritten) {
    const std::string dir = freshDir();
    const std::string csv = dir + "/part.csv";
    const std::string lock = csv + ".shard-2-of-3.lock";
    test::writeFile(lock, "host=node17\npid=4242\nslurm_job_id=91\nslurm_array_job_id=88\n"
                          "slurm_array_task_id=2\nstarted=2026-01-02T03:04:05Z\n");
    const int fd = ::open(lock.c_str(), O_RDWR);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
    const auto r =
        test::runCommand(bench("sweep -t none --instances 2,3,4 --shard 2/3 --csv " + csv + kQuick));
    ::close(fd);
    EXPECT_EQ(r.exitCode, 1) << r.output;
    ASSERT_EQ(lines(r.output).size(), 1u) << r.output;
    EXPECT_NE(r.output.find("host node17, pid 4242, Slurm job 88_2 (SLURM_JOB_ID 91), started "
                            "2026-01-02T03:04:05Z; lock '" +
                            lock + "'"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(csv)) << "the refused run wrote rows";
    EXPECT_TRUE(fs::exists(lock)) << "the holder's lock file is the holder's";
}

// A lock file left by a process that died (killed, a node that rebooted) is no lock: the kernel released
// its flock. The next run takes it over, measures, and removes it at its end.
TEST(SweepWriterCli, LockFileOfADeadProcessBlocksNothing) {
    const std::string dir = freshDir();
    const std::string csv = dir + "/part.csv", lock = csv + ".shard-1-of-2.lock";
    test::writeFile(lock, "host=gone\npid=999999\nstarted=2026-01-02T03:04:05Z\n");
    const auto r = test::runCommand(bench("sweep -t none --instances 2,3 --shard 1/2 --csv " + csv + kQuick));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Rows rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 1u); // group 0 of 2 (instances 2): shard 1 of 2
    EXPECT_EQ(rows[0].at(col::kStatus), "ok");
    EXPECT_EQ(rows[0].at(col::kSlurmJobId), "") << "outside Slurm";
    EXPECT_EQ(rows[0].at(col::kSlurmArrayTaskId), "");
    EXPECT_FALSE(fs::exists(lock));
}

// Resuming a part file of a 4-way split as a shard of a 2-way split would deal the configurations
// anew: refused, exit 2, naming the file and both splits, the file byte for byte as it was. Shards of
// the same split may share a file: shard 2/4 continues it.
TEST(SweepWriterCli, ResumeRefusesAPartFileOfAnotherSplit) {
    const std::string dir = freshDir();
    const std::string csv = dir + "/part.csv";
    const std::string axes = "sweep -t none --instances 2,3,4,5 --csv " + csv + kQuick;
    const auto first = test::runCommand(bench(axes + " --shard 1/4"));
    ASSERT_EQ(first.exitCode, 0) << first.output;
    const std::string written = test::readFile(csv);
    ASSERT_EQ(test::csvRowMaps(csv).size(), 1u);

    const auto other = test::runCommand(bench(axes + " --shard 1/2 --resume"));
    EXPECT_EQ(other.exitCode, 2) << other.output;
    ASSERT_EQ(lines(other.output).size(), 1u) << other.output;
    for (const std::string& word : {csv, std::string("shard 1/4"), std::string("--shard 1/2")})
        EXPECT_NE(other.output.find(word), std::string::npos) << "lacks '" << word << "': " << other.output;
    EXPECT_EQ(test::readFile(csv), written);
    EXPECT_TRUE(lockFiles(dir).empty());

    const auto same = test::runCommand(bench(axes + " --shard 2/4 --resume"));
    ASSERT_EQ(same.exitCode, 0) << same.output;
    const Rows rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1].at(col::kShard), "2/4");
}

// A crashed worker's configuration (SHADOWBENCH_FAULT_INJECT=crash:1, as SweepCliTest injects it) is run
// again by --resume --retry-failed: while it still crashes its failed row is replaced by the new failed
// one, once it succeeds by its ok row; the file holds one row per configuration throughout, and the
// configurations that were ok are not run again.
TEST(SweepWriterCli, RetryFailedReplacesTheFailedRows) {
    const std::string dir = freshDir();
    const std::string csv = dir + "/r.csv";
    // 2 techniques x 2 rounds = 4 configurations; #1 is shadowmap's first round.
    const std::string args =
        "sweep -t none -t shadowmap:resolution=256 --instances 3 --repeat 2 --csv " + csv + kQuick;
    // Under AddressSanitizer the injected SIGSEGV must stay a signal (SweepCliTest says why).
    const std::string crash =
        "ASAN_OPTIONS=\"${ASAN_OPTIONS:-}:handle_segv=0\" SHADOWBENCH_FAULT_INJECT=crash:1 ";
    auto statusOf = [&](const Rows& rows) {
        std::map<std::string, std::string> out;
        for (const auto& r : rows) out[r.at(col::kConfigIndex)] = r.at(col::kStatus);
        return out;
    };
    const std::map<std::string, std::string> oneFailed = {
        {"0", "ok"}, {"1", "failed"}, {"2", "ok"}, {"3", "ok"}};

    const auto crashed = test::runCommand(crash + bench(args));
    ASSERT_EQ(crashed.exitCode, 1) << crashed.output;
    const Rows before = test::csvRowMaps(csv);
    ASSERT_EQ(before.size(), 4u);
    ASSERT_EQ(statusOf(before), oneFailed);

    const auto again = test::runCommand(crash + bench(args + " --resume --retry-failed"));
    EXPECT_EQ(again.exitCode, 1) << again.output;
    EXPECT_NE(again.output.find("1 failed before and run again"), std::string::npos) << again.output;
    const Rows still = test::csvRowMaps(csv);
    EXPECT_EQ(still.size(), 4u) << "the new failed row replaces the old one";
    EXPECT_EQ(statusOf(still), oneFailed);

    const auto retried = test::runCommand(bench(args + " --resume --retry-failed"));
    ASSERT_EQ(retried.exitCode, 0) << retried.output;
    const Rows after = test::csvRowMaps(csv);
    ASSERT_EQ(after.size(), 4u);
    EXPECT_EQ(statusOf(after),
              (std::map<std::string, std::string>{{"0", "ok"}, {"1", "ok"}, {"2", "ok"}, {"3", "ok"}}));
    // The rows that were ok are the same rows (their own medians), not measured again.
    for (const auto& b : before) {
        if (b.at(col::kStatus) != "ok") continue;
        for (const auto& a : after)
            if (a.at(col::kConfigIndex) == b.at(col::kConfigIndex)) {
                EXPECT_EQ(a.at(col::kWallMsMedian), b.at(col::kWallMsMedian)) << b.at(col::kConfigIndex);
            }
    }
    EXPECT_TRUE(lockFiles(dir).empty());
}

// Under `taskset -c <one CPU>` on a machine of several, a row says hw_threads 1 and the reference traced
// on 1 thread (ref_threads), as the Slurm task's allocation would have it; the row names this host and
// the Slurm job of the environment (a job outside an array: SLURM_JOB_ID, no array task).
TEST(SweepWriterCli, RowsSayWhereTheyRanAndOnHowManyCpus) {
    const std::vector<int> cpus = allowedCpus();
    if (cpus.size() < 2) GTEST_SKIP() << "needs at least 2 CPUs to pin a run to 1 of them";
    const std::string dir = freshDir();
    const std::string csv = dir + "/a.csv";
    const auto r =
        test::runCommand("taskset -c " + std::to_string(cpus.front()) + " " + kNoSlurm + "SLURM_JOB_ID=777 " +
                         SB_BENCH_BINARY +
                         " sweep --mode accuracy -t none --instances 2 --ref-samples 1 --no-stability "
                         "--csv " +
                         csv + kQuick);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const Rows rows = test::csvRowMaps(csv);
    ASSERT_EQ(rows.size(), 1u);
    EXPECT_EQ(rows[0].at(col::kHwThreads), "1") << "the machine has " << cpus.size();
    EXPECT_EQ(std::stod(rows[0].at(col::kRefThreads)), 1.0);
    EXPECT_EQ(rows[0].at(col::kHost), hostName());
    EXPECT_EQ(rows[0].at(col::kSlurmJobId), "777");
    EXPECT_EQ(rows[0].at(col::kSlurmArrayTaskId), "");
}
