#include "bench/lib/sweep/ShardLock.h"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <map>
#include <sstream>
#include <sys/file.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

#include "bench/lib/rows/Environment.h"
#include "core/Error.h"

namespace sb {

namespace {

// A taker that keeps finding the sidecar removed under it (a holder ending each time) gives up
// eventually rather than spin; each lost round means another run ended.
constexpr int kMaxLockRounds = 100;
// A holder writes its text right after its lock is granted: a refusal that finds the text empty waits
// this long for it, in steps, before it names the holder as unknown.
constexpr int kHolderWaitSteps = 20;
constexpr auto kHolderWaitStep = std::chrono::milliseconds(25);

// The sidecar's keys, one "key=value" line each.
constexpr const char* kHost = "host";
constexpr const char* kPid = "pid";
constexpr const char* kSlurmJobId = "slurm_job_id";
constexpr const char* kSlurmArrayJobId = "slurm_array_job_id";
constexpr const char* kSlurmArrayTaskId = "slurm_array_task_id";
constexpr const char* kStarted = "started";

[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
    throw Error("cannot lock the sweep's shard: " + what + " '" + path + "': " + std::strerror(err),
                ExitCode::Failure);
}

std::string readAll(int fd) {
    std::string text;
    char buf[4096];
    for (off_t at = 0;;) {
        const ssize_t n = ::pread(fd, buf, sizeof buf, at);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return text;
        text.append(buf, size_t(n));
        at += n;
    }
}

std::map<std::string, std::string> parseHolder(const std::string& text) {
    std::map<std::string, std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const size_t eq = line.find('=');
        if (eq != std::string::npos) out[line.substr(0, eq)] = line.substr(eq + 1);
    }
    return out;
}

/// "host n1, pid 4242, Slurm job 70_3 (SLURM_JOB_ID 71), started 2026-12-06T05:00:00Z" from the text.
std::string describeHolder(const std::string& text) {
    auto h = parseHolder(text);
    if (h[kHost].empty() && h[kPid].empty()) return "a process that has not recorded itself yet";
    const SlurmTask slurm{h[kSlurmJobId], h[kSlurmArrayJobId], h[kSlurmArrayTaskId]};
    std::string out = "host " + h[kHost] + ", pid " + h[kPid];
    if (const std::string job = slurm.describe(); !job.empty()) out += ", " + job;
    if (!h[kStarted].empty()) out += ", started " + h[kStarted];
    return out;
}

} // namespace

// Beside the file the CSV's path names once links and relative parts are resolved, so that two runs
// naming one file differently (a link, another working directory) meet at one lock.
std::string ShardLock::pathFor(const std::string& csvPath, int shard, int count) {
    std::error_code ec;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(csvPath, ec);
    return (ec ? csvPath : resolved.string()) + ".shard-" + std::to_string(shard) + "-of-" +
           std::to_string(count) + ".lock";
}

ShardLock::ShardLock(const std::string& csvPath, int shard, int count)
    : mPath(pathFor(csvPath, shard, count)) {
    for (int round = 0; round < kMaxLockRounds; ++round) {
        if (tryLock()) {
            try {
                recordHolder();
            } catch (...) {
                release(); // no destructor runs after a constructor throws
                throw;
            }
            return;
        }
        if (mFd >= 0) refuse(csvPath, std::to_string(shard) + "/" + std::to_string(count));
    }
    throw Error("cannot lock the sweep's shard '" + mPath + "': other runs kept removing it",
                ExitCode::Failure);
}

ShardLock::~ShardLock() {
    release();
}

void ShardLock::release() {
    // Removed while still locked: a taker that opened the old inode finds it gone and tries again. Only
    // the file this lock holds is removed (someone may have deleted it by hand and another run made a
    // new one).
    struct stat locked {
    }, now{};
    if (::fstat(mFd, &locked) == 0 && ::stat(mPath.c_str(), &now) == 0 && locked.st_ino == now.st_ino &&
        locked.st_dev == now.st_dev)
        ::unlink(mPath.c_str());
    ::close(mFd);
    mFd = -1;
}

// True: locked, and the path still names the locked file. False with mFd open: another process holds
// it. False with mFd closed: the file was removed or replaced meanwhile (a holder ending): try again.
// No O_CLOEXEC: the workers inherit the lock (see the header).
bool ShardLock::tryLock() {
    mFd = ::open(mPath.c_str(), O_RDWR | O_CREAT | O_NOCTTY, 0666);
    if (mFd < 0) fail(mPath, "cannot open", errno);
    int rc;
    while ((rc = ::flock(mFd, LOCK_EX | LOCK_NB)) != 0 && errno == EINTR) {
    }
    if (rc != 0) {
        if (errno == EWOULDBLOCK) return false;
        const int err = errno;
        ::close(mFd);
        mFd = -1;
        fail(mPath, "cannot lock", err);
    }
    struct stat locked {
    }, now{};
    if (::fstat(mFd, &locked) == 0 && ::stat(mPath.c_str(), &now) == 0 && locked.st_ino == now.st_ino &&
        locked.st_dev == now.st_dev)
        return true;
    ::close(mFd);
    mFd = -1;
    return false;
}

// A dead holder's text is simply replaced: the lock, not the file, says who holds it.
void ShardLock::recordHolder() const {
    const Environment env = Environment::capture();
    const std::string text = std::string(kHost) + "=" + env.host + "\n" + kPid + "=" +
                             std::to_string(::getpid()) + "\n" + kSlurmJobId + "=" + env.slurm.jobId + "\n" +
                             kSlurmArrayJobId + "=" + env.slurm.arrayJobId + "\n" + kSlurmArrayTaskId + "=" +
                             env.slurm.arrayTaskId + "\n" + kStarted + "=" + env.timestamp + "\n";
    if (::ftruncate(mFd, 0) != 0 || ::pwrite(mFd, text.data(), text.size(), 0) != ssize_t(text.size()))
        fail(mPath, "cannot write who holds it into", errno);
}

void ShardLock::refuse(const std::string& csvPath, const std::string& shard) const {
    std::string text = readAll(mFd);
    for (int step = 0; step < kHolderWaitSteps && text.empty(); ++step) {
        std::this_thread::sleep_for(kHolderWaitStep);
        text = readAll(mFd);
    }
    ::close(mFd);
    throw Error("cannot run shard " + shard + " of '" + csvPath + "': another sweep is writing it (" +
                    describeHolder(text) + "; lock '" + mPath +
                    "'); nothing was written: wait for it to end or stop it, or write to another --csv",
                ExitCode::Failure);
}

} // namespace sb
