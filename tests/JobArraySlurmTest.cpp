// The Slurm launcher (scripts/slurm-submit.sh, scripts/slurm-sweep.sbatch) on a real single-node
// cluster: munged, slurmctld and slurmd from Debian's packages, started by tools/slurm/cluster.sh for
// this test and stopped after it (also when the test process dies: the cluster watches its pid). A
// sweep runs as a job array with one task cancelled, one requeued and one index resubmitted, and the
// merged rows must be the rows of the same sweep run in one process: every exact column (identity,
// work and load counters, technique counters, accuracy) equal, no configuration lost or doubled. Then
// the shard mapping of a 0-based and a stepped array, the merge after failed tasks (where afterok
// never runs), and an interrupted bench's exit code as Slurm records it.
//
// Needs root and the packages of `bash scripts/install-deps.sh slurm`; without them every test fails
// and says so (the label `slurm` keeps it out of the unit tests). About 40 s on 2 cores, most of it
// the sweeps' worker processes.
#include <chrono>
#include <filesystem>
#include <map>
#include <regex>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "TestSupport.h"
#include "bench/lib/output/ResultColumns.h"

using namespace sb;
using test::runCommand;
using test::shellQuoted;
namespace fs = std::filesystem;

namespace {

// The sweep: 2 techniques x 4 cameras = 4 combinations, 8 configurations; as 4 shards, one
// combination (2 rows) a shard. Tiny frames: the test checks where rows go, not what they measure.
const char* kDefinition =
    R"({"name": "slurm", "techniques": ["none", "shadowmap"], "scenes": ["sphere_plane"],
 "camera": ["far", "mid", "near", "top"], "size": "32x32", "frames": 1, "warmup": 0})";
constexpr size_t kConfigs = 8;
// Passed after the two positional arguments: the script must hand them to bench sweep (the rows'
// timer_verdict says whether it did).
const std::string kExtraArgs = "--no-timer-check";
constexpr int kJobLimitS = 120;
// Seconds between a requeued task's end and its release (see the first test).
constexpr int kRequeueDelayS = 3;

/// The cluster every test of this file shares, and the folder the jobs are submitted from.
struct Cluster {
    std::string dir;     ///< tools/slurm/cluster.sh's folder: config, state, logs
    std::string work;    ///< where jobs are submitted from (their logs and outputs)
    std::string problem; ///< why there is no cluster, or empty
};

Cluster& cluster() {
    static Cluster c;
    return c;
}

std::string script(const std::string& name) {
    return std::string(SB_SOURCE_DIR) + "/" + name;
}

/// `command` run in the submission folder, with the cluster's configuration.
test::CommandResult inWork(const std::string& command) {
    return runCommand("cd " + shellQuoted(cluster().work) + " && " + command);
}

/// One job's fields from `scontrol show job -o` (JobState, ExitCode, Restarts, Reason ...).
std::map<std::string, std::string> jobFields(const std::string& id) {
    const auto r = runCommand("scontrol show job -o " + id);
    std::map<std::string, std::string> out;
    static const std::regex field(R"((\w+)=(\S*))");
    const std::string line = r.output.substr(0, r.output.find('\n'));
    for (auto it = std::sregex_iterator(line.begin(), line.end(), field); it != std::sregex_iterator(); ++it)
        out.emplace((*it)[1].str(), (*it)[2].str());
    return out;
}

bool ended(const std::string& state) {
    static const std::set<std::string> kEnded = {"COMPLETED", "FAILED",    "CANCELLED",     "TIMEOUT",
                                                 "NODE_FAIL", "BOOT_FAIL", "OUT_OF_MEMORY", "DEADLINE"};
    return kEnded.count(state) > 0;
}

/// Waits until job `id` (one job or one array task) has ended; its fields then.
std::map<std::string, std::string> waitEnded(const std::string& id) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kJobLimitS);
    for (;;) {
        auto f = jobFields(id);
        if (ended(f["JobState"]) || std::chrono::steady_clock::now() > deadline) return f;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
}

/// Waits until no task of array job `id` is pending, running or completing.
void waitArrayEnded(const std::string& id) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kJobLimitS);
    while (std::chrono::steady_clock::now() < deadline) {
        if (runCommand("squeue -h -t PD,R,CG,S,CF -j " + id + " -o %i").output.empty()) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    ADD_FAILURE() << "array " << id << " still has tasks after " << kJobLimitS << " s:\n"
                  << runCommand("squeue -j " + id).output;
}

std::string logOf(const std::string& name) {
    return test::readFile(cluster().work + "/" + name);
}

/// Waits until the log `name` (in the submission folder) holds `text`.
void waitForLog(const std::string& name, const std::string& text) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(kJobLimitS);
    while (logOf(name).find(text) == std::string::npos) {
        if (std::chrono::steady_clock::now() > deadline) {
            ADD_FAILURE() << name << " has no '" << text << "' after " << kJobLimitS << " s:\n"
                          << logOf(name);
            return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
}

/// The job id after `label` in slurm-submit.sh's output ("array job 12 ...", "merge job 13 ...").
std::string idAfter(const std::string& output, const std::string& label) {
    std::smatch m;
    if (std::regex_search(output, m, std::regex(label + " ([0-9]+)"))) return m[1].str();
    ADD_FAILURE() << "no '" << label << " <id>' in:\n" << output;
    return "0";
}

/// sbatch's job id of a direct submission (--parsable).
std::string sbatch(const std::string& args) {
    const auto r = inWork("sbatch --parsable " + args);
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return r.output.substr(0, r.output.find_first_of(";\n"));
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

/// Columns that must be equal between a sharded and a one-process run of the same sweep: what
/// identifies a configuration and what is counted, not timed (times, host, shard, timestamps differ).
bool isExactColumn(const std::string& c) {
    static const std::set<std::string> kIdentity = {
        col::kConfigIndex,    col::kConfigGroup, col::kSweepId,     col::kSweepConfigs, col::kTechnique,
        col::kTechniqueSpec,  col::kProperties,  col::kPermutation, col::kScene,        col::kSceneHash,
        col::kSceneTriangles, col::kInstances,   col::kWidth,       col::kHeight,       col::kFrames,
        col::kStatus,         col::kTimerVerdict};
    for (const char* family : {"work_", "load_", "counter_", "acc_"})
        if (c.rfind(family, 0) == 0) return true;
    return kIdentity.count(c) > 0;
}

using Rows = std::map<size_t, std::map<std::string, std::string>>;

/// The CSV's rows by config_index; a doubled index is a failure.
Rows rowsByIndex(const std::string& path) {
    Rows out;
    for (auto& row : test::csvRowMaps(path)) {
        const size_t index = std::stoul(row[col::kConfigIndex]);
        EXPECT_TRUE(out.emplace(index, row).second) << path << ": config_index " << index << " twice";
    }
    return out;
}

class JobArraySlurm : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        Cluster& c = cluster();
        const std::string base = test::freshDir("slurm");
        c.dir = base + "/cluster";
        c.work = base + "/work";
        fs::create_directories(c.work);
        test::writeFile(c.work + "/sweep.json", kDefinition);
        const auto r = runCommand("bash " + shellQuoted(script("tools/slurm/cluster.sh")) + " start " +
                                  shellQuoted(c.dir) + " --owner " + std::to_string(getpid()));
        if (r.exitCode != 0) {
            // Exit 3: not root or a package missing, which the message says with the install command.
            c.problem =
                "tools/slurm/cluster.sh start failed (exit " + std::to_string(r.exitCode) + "):\n" + r.output;
            if (r.exitCode != 3)
                c.problem +=
                    "\nslurmctld.log:\n" + runCommand("tail -n 20 " + c.dir + "/slurmctld.log").output;
            return;
        }
        setenv("SLURM_CONF", (c.dir + "/slurm.conf").c_str(), 1);
        // The jobs inherit the submitting environment (sbatch --export=ALL): this build's bench.
        setenv("SHADOWBENCH_BENCH", SB_BENCH_BINARY, 1);
    }

    static void TearDownTestSuite() {
        const Cluster& c = cluster();
        if (c.problem.empty())
            runCommand("bash " + shellQuoted(script("tools/slurm/cluster.sh")) + " stop " +
                       shellQuoted(c.dir));
        if (!::testing::UnitTest::GetInstance()->Failed()) fs::remove_all(fs::path(c.dir).parent_path());
    }

    void SetUp() override {
        if (!cluster().problem.empty()) FAIL() << cluster().problem;
    }
};

// The whole path as a user meets it: slurm-submit.sh's array and merge; task 3 cancelled before it
// ran, task 1 requeued, the merge after that (afterany) naming the missing shard; index 3 submitted
// again with its own merge, which then holds exactly the rows of a one-process run.
TEST_F(JobArraySlurm, ArrayWithCancelRequeueAndResubmitMergesToTheOneProcessSweep) {
    const std::string bench = shellQuoted(SB_BENCH_BINARY);
    const auto whole = inWork(bench + " sweep sweep.json --no-progress " + kExtraArgs + " --csv whole.csv");
    ASSERT_EQ(whole.exitCode, 0) << whole.output;

    // Submitted without -c, as a user on a small node would (a fixed --cpus-per-task=8 never ran here).
    // Held, so that task 3 can be cancelled before it runs and the array cannot end before task 1's
    // requeue (the merge waits for every task, the requeued one included).
    const auto submit = inWork("bash " + shellQuoted(script("scripts/slurm-submit.sh")) +
                               " --array=1-4 --hold -- sweep.json out/main " + kExtraArgs);
    ASSERT_EQ(submit.exitCode, 0) << submit.output;
    const std::string array = idAfter(submit.output, "array job"),
                      merge = idAfter(submit.output, "merge job");
    EXPECT_EQ(inWork("scancel " + array + "_3").exitCode, 0);
    EXPECT_EQ(inWork("scontrol release " + array + "_1").exitCode, 0);
    // Requeued once its bench runs, so that the log's first run is there to be kept.
    waitForLog("shadowbench-sweep-" + array + "_1.log", "running:");
    const auto requeue = inWork("scontrol requeue " + array + "_1");
    EXPECT_EQ(requeue.exitCode, 0) << requeue.output;
    // Slurm holds a requeued batch job back for two minutes (Reason=BeginTime) once it is pending
    // again (a running one is ended first). Made eligible a few seconds later here: slurmd refuses to
    // launch a job it has just killed ("already killed, do not launch batch job", exit 1) for a moment.
    const auto pendingBy = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (jobFields(array + "_1")["JobState"] != "PENDING" && std::chrono::steady_clock::now() < pendingBy)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::this_thread::sleep_for(std::chrono::seconds(kRequeueDelayS));
    EXPECT_EQ(inWork("scontrol update JobId=" + array + "_1 StartTime=now").exitCode, 0);
    for (const char* task : {"_2", "_4"}) EXPECT_EQ(inWork("scontrol release " + array + task).exitCode, 0);
    waitArrayEnded(array);

    auto m = waitEnded(merge);
    EXPECT_EQ(m["JobState"], "FAILED") << "the merge runs after a cancelled task, and finds shard 3 missing";
    EXPECT_EQ(m["ExitCode"], "1:0") << "bench merge's incomplete merge";
    const std::string mergeLog = logOf("shadowbench-merge-" + merge + ".log");
    EXPECT_NE(mergeLog.find("shards without a part file: 3 (submit array indices 3 again)"),
              std::string::npos)
        << mergeLog;
    // Cancelled while pending, task 3 never ran: no part file until its index is submitted again.
    EXPECT_FALSE(fs::exists(cluster().work + "/out/main.part3.csv"));
    auto t1 = jobFields(array + "_1");
    EXPECT_EQ(t1["JobState"], "COMPLETED");
    EXPECT_EQ(t1["Restarts"], "1");
    // The requeued task's log was appended to, not truncated: both runs are in it, the requeue between.
    const std::string log1 = logOf("shadowbench-sweep-" + array + "_1.log");
    EXPECT_EQ(count(log1, "array index 1 -> shard 1/4"), 2u) << log1;
    EXPECT_LT(log1.find("restart 0"), log1.find("DUE TO JOB REQUEUE")) << log1;
    EXPECT_LT(log1.find("DUE TO JOB REQUEUE"), log1.find("restart 1")) << log1;
    // No CPU count is fixed by the script: the task got the default, one CPU, and llvmpipe one thread.
    EXPECT_NE(log1.find("cpus 1, LP_NUM_THREADS=1"), std::string::npos) << log1;

    const auto again = inWork("bash " + shellQuoted(script("scripts/slurm-submit.sh")) +
                              " --array=3 -- sweep.json out/main " + kExtraArgs);
    ASSERT_EQ(again.exitCode, 0) << again.output;
    const std::string array2 = idAfter(again.output, "array job"),
                      merge2 = idAfter(again.output, "merge job");
    EXPECT_EQ(waitEnded(array2 + "_3")["ExitCode"], "0:0");
    EXPECT_NE(logOf("shadowbench-sweep-" + array2 + "_3.log").find("array index 3 -> shard 3/4"),
              std::string::npos);
    m = waitEnded(merge2);
    ASSERT_EQ(m["ExitCode"], "0:0") << logOf("shadowbench-merge-" + merge2 + ".log");

    // Nothing lost or doubled: each part holds its shard's two rows once, and the merge all eight.
    for (int shard = 1; shard <= 4; ++shard)
        EXPECT_EQ(rowsByIndex(cluster().work + "/out/main.part" + std::to_string(shard) + ".csv").size(), 2u)
            << "shard " << shard;
    const Rows one = rowsByIndex(cluster().work + "/whole.csv");
    const Rows merged = rowsByIndex(cluster().work + "/out/main.csv");
    ASSERT_EQ(one.size(), kConfigs);
    ASSERT_EQ(merged.size(), kConfigs);
    size_t compared = 0;
    for (const auto& [index, row] : one) {
        ASSERT_TRUE(merged.count(index)) << "config_index " << index << " missing";
        const auto& other = merged.at(index);
        for (const auto& [column, value] : row) {
            if (!isExactColumn(column)) continue;
            ASSERT_TRUE(other.count(column)) << "merged rows lack " << column;
            EXPECT_EQ(other.at(column), value) << "config_index " << index << ", column " << column;
            ++compared;
        }
        EXPECT_EQ(other.at(col::kTimerVerdict), "unchecked") << "the extra argument reached bench sweep";
        EXPECT_EQ(other.at(col::kStatus), col::kStatusOk);
    }
    EXPECT_GE(compared, kConfigs * 10) << "too few exact columns compared";
}

// A 0-based and a stepped array both cover shards 1..4 (bench sweep --dry-run runs nothing); an index
// submitted again maps as the first submission did; a --shards that disagrees is refused, exit 2.
TEST_F(JobArraySlurm, ZeroBasedAndSteppedArraysMapToTheirShards) {
    const std::string sweep = shellQuoted(script("scripts/slurm-sweep.sbatch"));
    const std::string zero = sbatch("--array=0-3 " + sweep + " sweep.json out/zero --dry-run");
    const std::string stepped = sbatch("--array=1-7:2%2 " + sweep + " sweep.json out/step --dry-run");
    waitArrayEnded(zero);
    waitArrayEnded(stepped);
    const std::vector<std::pair<std::string, std::vector<int>>> arrays = {{zero, {0, 1, 2, 3}},
                                                                          {stepped, {1, 3, 5, 7}}};
    for (const auto& [job, indices] : arrays)
        for (size_t k = 0; k < indices.size(); ++k) {
            const std::string task = job + "_" + std::to_string(indices[k]);
            EXPECT_EQ(jobFields(task)["ExitCode"], "0:0") << task;
            const std::string log = logOf("shadowbench-sweep-" + task + ".log");
            const std::string shard = std::to_string(k + 1) + "/4";
            EXPECT_NE(log.find("array index " + std::to_string(indices[k]) + " -> shard " + shard),
                      std::string::npos)
                << log;
            EXPECT_NE(log.find("--shard " + shard + " "), std::string::npos) << log;
        }
    EXPECT_EQ(test::readFile(cluster().work + "/out/step.shards").substr(0, 29),
              "shards=4 first_index=1 step=2");

    // Index 5 of the stepped array alone: still shard 3 of 4. With --shards 3: refused.
    const std::string single = sbatch("--array=5 " + sweep + " sweep.json out/step --dry-run");
    const std::string wrong = sbatch("--array=5 " + sweep + " --shards 3 sweep.json out/step --dry-run");
    EXPECT_EQ(waitEnded(single + "_5")["ExitCode"], "0:0");
    EXPECT_NE(logOf("shadowbench-sweep-" + single + "_5.log").find("array index 5 -> shard 3/4"),
              std::string::npos);
    EXPECT_EQ(waitEnded(wrong + "_5")["ExitCode"], "2:0");
    const std::string refused = logOf("shadowbench-sweep-" + wrong + "_5.log");
    EXPECT_NE(refused.find("--shards 3, but out/step.shards fixed 4 shards"), std::string::npos) << refused;
}

// Failed tasks: a merge chained with afterany runs and says what is missing; one chained with afterok
// never runs (DependencyNeverSatisfied), which is why the launcher does not use it.
TEST_F(JobArraySlurm, TheMergeRunsAfterFailedTasks) {
    const std::string sweep = shellQuoted(script("scripts/slurm-sweep.sbatch"));
    const std::string failing = sbatch("--array=1-2 " + sweep + " no-such-sweep.json out/fail");
    const std::string afterany =
        sbatch("--dependency=afterany:" + failing + " --output=merge-%j.log " + sweep + " --merge out/fail");
    const std::string afterok = sbatch("--dependency=afterok:" + failing + " " + sweep + " --merge out/fail");
    waitArrayEnded(failing);
    for (const char* task : {"_1", "_2"}) {
        auto f = jobFields(failing + task);
        EXPECT_EQ(f["JobState"], "FAILED");
        EXPECT_EQ(f["ExitCode"], "2:0") << "wrong input";
    }
    auto m = waitEnded(afterany);
    EXPECT_EQ(m["ExitCode"], "1:0") << "ran, and found nothing to merge";
    const std::string log = logOf("merge-" + afterany + ".log");
    EXPECT_NE(log.find("no out/fail.shards: no task of the array started"), std::string::npos) << log;
    std::map<std::string, std::string> ok;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    do {
        ok = jobFields(afterok);
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    } while (ok["Reason"] != "DependencyNeverSatisfied" && std::chrono::steady_clock::now() < deadline);
    EXPECT_EQ(ok["JobState"], "PENDING");
    EXPECT_EQ(ok["Reason"], "DependencyNeverSatisfied");
    inWork("scancel " + afterok);
}

// bench interrupted (SIGINT: its exit code 130) ends the job with the documented 66: below 128, so
// that no accounting reads it as a signal (sacct with slurmdbd showed 130 as 2:0, bad input; this
// cluster's scontrol keeps 130:0, which the old script, exec'ing bench, left).
TEST_F(JobArraySlurm, AnInterruptedSweepEndsWithTheDocumentedCode) {
    const std::string sweep = shellQuoted(script("scripts/slurm-sweep.sbatch"));
    // Each configuration measured for 60 s: the task is still in its first when the signal comes.
    const std::string job =
        sbatch("--array=1 " + sweep + " sweep.json out/int " + kExtraArgs + " --seconds 60");
    const std::string task = job + "_1";
    waitForLog("shadowbench-sweep-" + task + ".log", "running:");
    // bench installs its handler at the start of the sweep: give it a moment past the log line.
    std::this_thread::sleep_for(std::chrono::seconds(1));
    const auto signal = inWork("scancel --full --signal=INT " + task);
    EXPECT_EQ(signal.exitCode, 0) << signal.output;
    auto f = waitEnded(task);
    const std::string log = logOf("shadowbench-sweep-" + task + ".log");
    EXPECT_EQ(f["ExitCode"], "66:0") << log;
    EXPECT_NE(log.find("bench exited 130; job exit code 66"), std::string::npos) << log;
}

// The GPU pass-through needs no cluster, only the variables Slurm sets with --gres=gpu (a stub bench
// prints what it was given): the first of the job's GPUs becomes --gpu, unless the arguments choose the
// device or SHADOWBENCH_SLURM_GPU says otherwise.
TEST(JobArraySlurmGpu, TheJobsFirstGpuIsPassedAsTheEglDevice) {
    const std::string dir = test::freshDir("slurm-gpu");
    test::writeFile(dir + "/bench", "#!/bin/sh\necho \"stub bench: $*\"\n");
    fs::permissions(dir + "/bench", fs::perms::owner_all);
    test::writeFile(dir + "/sweep.json", kDefinition);
    const std::string task = "cd " + shellQuoted(dir) +
                             " && env -u SLURM_JOB_GPUS -u CUDA_VISIBLE_DEVICES -u SHADOWBENCH_SLURM_GPU "
                             "SHADOWBENCH_BENCH=./bench SLURM_ARRAY_JOB_ID=7 SLURM_ARRAY_TASK_ID=1 "
                             "SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=1 SLURM_ARRAY_TASK_COUNT=1 "
                             "SLURM_ARRAY_TASK_STEP=1 ";
    const std::string run =
        " bash " + shellQuoted(script("scripts/slurm-sweep.sbatch")) + " sweep.json out/g";
    const struct {
        const char* name;
        std::string variables, args, expected; ///< expected: the stub's line, or the refusal
        int exitCode;
    } kCases[] = {
        {"two GPUs", "SLURM_JOB_GPUS=3,5", "", "--csv out/g.part1.csv --gpu 3\n", 0},
        {"CUDA only", "CUDA_VISIBLE_DEVICES=2", "", "--csv out/g.part1.csv --gpu 2\n", 0},
        {"no GPU", "", "", "--csv out/g.part1.csv\n", 0},
        {"--gpu given", "SLURM_JOB_GPUS=3", " --gpu 1", "--csv out/g.part1.csv --gpu 1\n", 0},
        {"--backend given", "SLURM_JOB_GPUS=3", " --backend osmesa",
         "--csv out/g.part1.csv --backend osmesa\n", 0},
        {"chosen", "SLURM_JOB_GPUS=3 SHADOWBENCH_SLURM_GPU=0", "", "--csv out/g.part1.csv --gpu 0\n", 0},
        {"none", "SLURM_JOB_GPUS=3 SHADOWBENCH_SLURM_GPU=none", "", "--csv out/g.part1.csv\n", 0},
        {"bad", "SLURM_JOB_GPUS=3 SHADOWBENCH_SLURM_GPU=first", "",
         "SHADOWBENCH_SLURM_GPU=first: expected auto, none or an EGL device index", 2},
    };
    for (const auto& c : kCases) {
        const auto r = runCommand(task + c.variables + run + c.args);
        EXPECT_EQ(r.exitCode, c.exitCode) << c.name << ":\n" << r.output;
        EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.name << ":\n" << r.output;
    }
    fs::remove_all(dir);
}

} // namespace
