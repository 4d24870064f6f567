#pragma once
// One writer per shard of a result file: the lock a sweep holds for its whole run, so that a shard
// submitted twice (the same Slurm job array sent again, a requeued task while an orphaned runner of the
// first still measures, a second terminal) is refused instead of writing every row twice. The CSV's own
// lock (bench/lib/output/AtomicFile.h) serialises single writes; it does not stop a second run.
//
// The lock is flock(LOCK_EX | LOCK_NB) on a sidecar file beside the CSV, `<csv>.shard-<i>-of-<N>.lock`
// (ShardLock::pathFor), never on the CSV itself, which AtomicFile locks and replaces per write. One per
// shard, because shards of one sweep may share a file and run side by side. The holder writes into the
// sidecar who it is: host, pid, Slurm job, array job and task (SLURM_JOB_ID, SLURM_ARRAY_JOB_ID,
// SLURM_ARRAY_TASK_ID) and start time, so a refusal names it. The kernel releases a flock when the
// last descriptor of it closes, so a process that died holds nothing: a sidecar it left, with its text,
// is taken over by the next run. The descriptor is inherited by the sweep's worker processes, so a worker
// that outlives its runner (a runner killed with SIGKILL; the worker gets SIGTERM then) still holds it.
//
// A clean end (or an exception unwinding the run) removes the sidecar while still holding the lock;
// whoever locks checks afterwards that the path still names the inode it locked, and tries again when
// it does not, so the removal never lets two holders in.
#include <string>

namespace sb {

class ShardLock {
public:
    /// Takes the lock of shard `shard`/`count` of `csvPath`. Throws sb::Error(ExitCode::Failure) when
    /// another process holds it: one line naming the CSV, the shard, the holder (host, pid, Slurm job,
    /// start) and the sidecar, having written nothing. Throws Failure naming the sidecar on an OS error.
    ShardLock(const std::string& csvPath, int shard, int count);
    /// Removes the sidecar and releases the lock.
    ~ShardLock();
    ShardLock(const ShardLock&) = delete;
    ShardLock& operator=(const ShardLock&) = delete;

    /// "<csv>.shard-<i>-of-<N>.lock", <csv> made absolute with links resolved.
    static std::string pathFor(const std::string& csvPath, int shard, int count);
    const std::string& path() const { return mPath; }

private:
    bool tryLock();
    void release();
    void recordHolder() const;
    [[noreturn]] void refuse(const std::string& csvPath, const std::string& shard) const;

    std::string mPath;
    int mFd = -1;
};

} // namespace sb
