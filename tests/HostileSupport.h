#pragma once
// Helpers of the hostile-input tests: a disk with no room left and the peak memory of a command.
//
// A full disk is made for real where the test may mount (root in the usual CI container): a tmpfs of
// 64 KiB, filled to the last byte, so every write() there fails with ENOSPC as it would on a full
// partition. Where mounting is refused the same outcome is made without privileges: the command runs
// under a file-size limit of zero (RLIMIT_FSIZE, SIGXFSZ ignored), so every write() that would grow a
// file fails with EFBIG. Both reach the program as a failed write of a file it just created, which is
// what the code under test must handle; the test names which of the two it used.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "TestSupport.h"

namespace sb::test {

/// A folder on a disk with no room left. Commands meant to run "on" that disk go through wrap().
class FullDisk {
public:
    /// Makes `dir` (fresh) and mounts a full tmpfs on it, or prepares the file-size-limit fallback.
    explicit FullDisk(const std::string& dir) : mDir(dir) {
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=64k,mode=0777") == 0) {
            mMounted = true;
            fill();
        }
    }
    ~FullDisk() {
        if (mMounted) ::umount2(mDir.c_str(), MNT_DETACH);
        std::error_code ec;
        std::filesystem::remove_all(mDir, ec);
    }
    FullDisk(const FullDisk&) = delete;
    FullDisk& operator=(const FullDisk&) = delete;

    const std::string& dir() const { return mDir; }
    /// "tmpfs (ENOSPC)" or "file-size limit (EFBIG)": for the test's message.
    std::string how() const { return mMounted ? "a full tmpfs (ENOSPC)" : "a file-size limit of 0 (EFBIG)"; }
    /// `command` (a shell command line) made to run against the full disk: unchanged on the tmpfs, with
    /// the file-size limit set first otherwise. Its output must go to a pipe (test::runCommand does),
    /// not to a file, which the limit would refuse too.
    std::string wrap(const std::string& command) const {
        if (mMounted) return command;
        return "sh -c " + shellQuoted("trap '' XFSZ; ulimit -f 0; " + command);
    }
    /// Creates `name` in the folder with `text` before the disk is "full" (a CSV written earlier):
    /// on the tmpfs the filler is shrunk to make room and grown again afterwards.
    void plant(const std::string& name, const std::string& text) {
        if (mMounted) std::filesystem::remove(mDir + "/.filler");
        std::ofstream(mDir + "/" + name, std::ios::binary) << text;
        if (mMounted) fill();
    }

private:
    void fill() {
        // Write until the disk refuses: the tmpfs is then full to the byte.
        FILE* f = std::fopen((mDir + "/.filler").c_str(), "ab");
        if (!f) return;
        static const char block[4096] = {};
        while (std::fwrite(block, 1, sizeof block, f) == sizeof block) {
        }
        while (std::fwrite(block, 1, 1, f) == 1 && std::fflush(f) == 0) {
        }
        std::fclose(f);
    }

    std::string mDir;
    bool mMounted = false;
};

struct PeakResult {
    int exitCode = -1;
    long peakRssKiB = 0; ///< the largest resident set of the command's process tree's largest process
    std::string output;  ///< stdout and stderr together
};

/// Runs `command` through /bin/sh and reports its exit code, output and peak resident memory (from
/// wait4's rusage: the largest of the shell and its waited-for children, in KiB). A memory bound in a
/// test is then measured, not assumed.
inline PeakResult runCommandPeak(const std::string& command) {
    PeakResult r;
    int pipeFds[2];
    if (::pipe(pipeFds) != 0) return r;
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::dup2(pipeFds[1], 1);
        ::dup2(pipeFds[1], 2);
        ::close(pipeFds[0]);
        ::close(pipeFds[1]);
        // exec sh so the measured tree is sh and what it runs; "exec" inside keeps it one process.
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(pipeFds[1]);
    char buf[4096];
    ssize_t n;
    while ((n = ::read(pipeFds[0], buf, sizeof buf)) > 0 || (n < 0 && errno == EINTR))
        if (n > 0) r.output.append(buf, size_t(n));
    ::close(pipeFds[0]);
    int status = 0;
    struct rusage usage {};
    if (::wait4(pid, &status, 0, &usage) == pid) {
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        r.peakRssKiB = usage.ru_maxrss;
    }
    return r;
}

} // namespace sb::test
