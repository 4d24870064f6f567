#include "bench/lib/output/AtomicFile.h"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace sb {

namespace {

constexpr mode_t kNewFileMode = 0666; // the umask decides, as for any file the user creates
// A writer that keeps losing the race to writers renaming new files over the path gives up eventually
// rather than spin; each lost round means another writer committed, so this is never reached in practice.
constexpr int kMaxLockRounds = 1000;
// Streamed replacements reach the temp file in blocks of this size: large enough that the system calls
// do not count, small enough that a million-row export holds one block.
constexpr size_t kTempBufferBytes = size_t(1) << 20;

std::string directoryOf(const std::string& path) {
    size_t slash = path.rfind('/');
    if (slash == std::string::npos) return ".";
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string baseNameOf(const std::string& path) {
    size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

/// What a non-regular file is, in words; nullptr for a regular file.
const char* kindOf(mode_t mode) {
    if (S_ISREG(mode)) return nullptr;
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

std::string notRegular(const std::string& noun, const std::string& path, const char* kind) {
    return "cannot write " + noun + " '" + path + "': it is " + kind +
           ", not a regular file (results are written by replacing the file; for rows on stdout use "
           "--format csv)";
}

std::string osFailure(const std::string& noun, const std::string& path, const std::string& what, int err) {
    return "cannot write " + noun + " '" + path + "': " + what +
           (err ? std::string(": ") + std::strerror(err) : "");
}

bool writeAll(int fd, const std::string& text) {
    size_t done = 0;
    while (done < text.size()) {
        ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return false;
        done += size_t(n);
    }
    return true;
}

/// "<base>.tmp.<digits>": the per-process temp name earlier versions used. The pid it names.
bool legacyTempPid(const std::string& entry, const std::string& base, pid_t& pid) {
    const std::string prefix = base + ".tmp.";
    if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0) return false;
    const std::string digits = entry.substr(prefix.size());
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) return false;
    pid = pid_t(std::atol(digits.c_str()));
    return pid > 0;
}

} // namespace

std::string AtomicFile::tempPathFor(const std::string& path) {
    return path + ".tmp";
}

void AtomicFile::fail(const std::string& what, int err) const {
    throw Error(osFailure(mNoun, mPath, what, err), ExitCode::Failure);
}

AtomicFile::AtomicFile(const std::string& path, std::string noun)
    : mPath(path), mResolved(path), mNoun(std::move(noun)) {
    if (path.empty()) throw Error("cannot write " + mNoun + ": the path is empty");
    lock();
    removeStaleTemps();
}

AtomicFile::~AtomicFile() {
    if (mTempFd >= 0) { // a replacement that failed or was abandoned half-way
        ::close(mTempFd);
        ::unlink(tempPathFor(mResolved).c_str());
    }
    if (mFd < 0) return;
    struct stat st {};
    // Only a file still empty and still ours is removed: another writer may have committed rows to the
    // path since (then it names another inode).
    if (mCreated && !mCommitted && ::fstat(mFd, &st) == 0 && st.st_size == 0) {
        struct stat now {};
        if (::stat(mResolved.c_str(), &now) == 0 && now.st_ino == st.st_ino && now.st_dev == st.st_dev)
            ::unlink(mResolved.c_str());
    }
    ::close(mFd); // releases the flock
}

// Steps 1 and 2 of the protocol in the header.
void AtomicFile::lock() {
    for (int round = 0; round < kMaxLockRounds; ++round) {
        struct stat st {};
        if (::stat(mPath.c_str(), &st) == 0) {
            if (const char* kind = kindOf(st.st_mode)) throw Error(notRegular(mNoun, mPath, kind));
        } else if (errno != ENOENT) {
            fail("cannot inspect it", errno);
        }
        // O_EXCL first, so that "this object created the file" is known without a race.
        mCreated = true;
        mFd = ::open(mPath.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY, kNewFileMode);
        if (mFd < 0 && errno == EEXIST) {
            mCreated = false;
            mFd = ::open(mPath.c_str(), O_RDWR | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
        }
        if (mFd < 0) {
            if (errno == ENOENT && !mCreated) continue; // removed between the two opens
            fail(mCreated ? "cannot create it" : "cannot open the existing file", errno);
        }
        struct stat locked {};
        if (::fstat(mFd, &locked) != 0) fail("cannot inspect it", errno);
        if (const char* kind = kindOf(locked.st_mode)) {
            ::close(mFd);
            mFd = -1;
            throw Error(notRegular(mNoun, mPath, kind));
        }
        int rc;
        while ((rc = ::flock(mFd, LOCK_EX)) != 0 && errno == EINTR) {
        }
        if (rc != 0) fail("cannot lock it", errno);
        // A link is followed once the file exists: the rename must replace the file, not the link.
        char resolved[PATH_MAX];
        struct stat now {};
        if (::realpath(mPath.c_str(), resolved) && ::stat(resolved, &now) == 0 &&
            now.st_ino == locked.st_ino && now.st_dev == locked.st_dev) {
            mResolved = resolved;
            mMode = locked.st_mode & 07777;
            return;
        }
        // Another writer replaced (or removed) the file while this one waited: lock the new one.
        ::close(mFd);
        mFd = -1;
        mCreated = false;
    }
    fail("could not lock it: other writers kept replacing it", 0);
}

// Only the lock holder writes "<file>.tmp", so it is removed at once; the older per-process names are removed
// once their process is gone (kill(pid, 0) fails with ESRCH), so a live writer of an older version is left
// alone.
void AtomicFile::removeStaleTemps() const {
    const std::string dir = directoryOf(mResolved), base = baseNameOf(mResolved);
    // The one temp name is written only under the lock, which this object holds: a file of that name
    // is a killed writer's leftover (an in-place append would otherwise never reuse and remove it).
    ::unlink(tempPathFor(mResolved).c_str());
    DIR* d = ::opendir(dir.c_str());
    if (!d) return; // best effort: the write itself reports a directory it cannot use
    while (const dirent* e = ::readdir(d)) {
        pid_t pid = 0;
        if (legacyTempPid(e->d_name, base, pid) && pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH)
            ::unlinkat(::dirfd(d), e->d_name, 0);
    }
    ::closedir(d);
}

std::string AtomicFile::read() const {
    std::string text;
    char buf[1 << 16];
    for (off_t at = 0;;) {
        ssize_t n = ::pread(mFd, buf, sizeof buf, at);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail("cannot read the existing file", errno);
        if (n == 0) return text;
        text.append(buf, size_t(n));
        at += n;
    }
}

// Step 3. Raw write() has no user-space buffer beyond mTempBuffer, so fsync() after the last write is
// the "flush + fsync" step. The directory fsync makes the rename itself survive a power cut; it is best
// effort (some file systems refuse fsync on directories) because the data is safe either way.
void AtomicFile::replace(const std::string& text) {
    beginReplace();
    write(text);
    commit();
}

void AtomicFile::beginReplace() {
    const std::string tmp = tempPathFor(mResolved);
    mTempFd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, kNewFileMode);
    if (mTempFd < 0) fail("cannot create temporary file '" + tmp + "'", errno);
    // Replacing the file must not change who may read it (best effort: a foreign-owned file may refuse).
    (void)::fchmod(mTempFd, mMode);
}

void AtomicFile::failTemp(const std::string& what, int err) {
    const std::string tmp = tempPathFor(mResolved);
    if (mTempFd >= 0) ::close(mTempFd);
    mTempFd = -1;
    ::unlink(tmp.c_str());
    fail(what + " '" + tmp + "'", err);
}

void AtomicFile::flushTemp() {
    if (!writeAll(mTempFd, mTempBuffer)) failTemp("cannot write temporary file", errno);
    mTempBuffer.clear();
}

void AtomicFile::write(std::string_view text) {
    mTempBuffer.append(text);
    if (mTempBuffer.size() >= kTempBufferBytes) flushTemp();
}

void AtomicFile::commit() {
    flushTemp();
    if (::fsync(mTempFd) != 0) failTemp("cannot write temporary file", errno);
    int fd = mTempFd;
    mTempFd = -1;
    if (::close(fd) != 0) {
        mTempFd = -1;
        int err = errno;
        ::unlink(tempPathFor(mResolved).c_str());
        fail("cannot write temporary file '" + tempPathFor(mResolved) + "'", err);
    }
    const std::string tmp = tempPathFor(mResolved);
    if (::rename(tmp.c_str(), mResolved.c_str()) != 0) {
        int err = errno;
        ::unlink(tmp.c_str());
        fail("cannot rename '" + tmp + "' over it", err);
    }
    mCommitted = true;
    int dirFd = ::open(directoryOf(mResolved).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dirFd >= 0) {
        (void)::fsync(dirFd);
        ::close(dirFd);
    }
}

off_t AtomicFile::size() const {
    struct stat st {};
    if (::fstat(mFd, &st) != 0) fail("cannot inspect it", errno);
    return st.st_size;
}

// One pwrite at the old end: under the lock no other writer moves the end meanwhile. A short or failed
// write is undone, so a full disk keeps every earlier row and adds no partial line.
void AtomicFile::appendInPlace(const std::string& text) {
    const off_t end = size();
    size_t done = 0;
    int err = 0;
    while (done < text.size()) {
        ssize_t n = ::pwrite(mFd, text.data() + done, text.size() - done, end + off_t(done));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            err = n < 0 ? errno : EIO;
            break;
        }
        done += size_t(n);
    }
    if (!err && ::fsync(mFd) != 0) err = errno;
    if (err) {
        (void)::ftruncate(mFd, end);
        (void)::fsync(mFd);
        fail("cannot append to it", err);
    }
    mCommitted = true;
}

// Scans back from the end in blocks for the last newline: a partial line is at most one row long.
off_t AtomicFile::cutPartialLastLine() {
    const off_t end = size();
    if (end == 0) return 0;
    char block[4096];
    for (off_t stop = end; stop > 0;) {
        const off_t start = stop > off_t(sizeof block) ? stop - off_t(sizeof block) : 0;
        ssize_t n = ::pread(mFd, block, size_t(stop - start), start);
        if (n < 0 && errno == EINTR) continue;
        if (n != stop - start) fail("cannot read the existing file", n < 0 ? errno : EIO);
        if (stop == end && block[n - 1] == '\n') return 0;
        for (ssize_t i = n - 1; i >= 0; --i)
            if (block[i] == '\n') {
                const off_t keep = start + i + 1;
                if (::ftruncate(mFd, keep) != 0 || ::fsync(mFd) != 0)
                    fail("cannot cut its partial last line", errno);
                return end - keep;
            }
        stop = start;
    }
    return 0;
}

// Permission checks give the clear messages; the final probe (create and remove a file of a unique
// name beside the target) catches what they cannot see: read-only mounts, root on NFS, names too long
// for the temp file's suffix.
void AtomicFile::checkWritable(const std::string& path, const std::string& noun) {
    auto bad = [&](const std::string& what, int err) { throw Error(osFailure(noun, path, what, err)); };
    if (path.empty()) throw Error("cannot write " + noun + ": the path is empty");
    std::string target = path;
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) {
        if (const char* kind = kindOf(st.st_mode)) throw Error(notRegular(noun, path, kind));
        if (::access(path.c_str(), R_OK | W_OK) != 0) bad("existing file", errno);
        char resolved[PATH_MAX];
        if (::realpath(path.c_str(), resolved)) target = resolved;
    } else if (errno != ENOENT) {
        bad("cannot inspect it", errno);
    }
    const std::string dir = directoryOf(target);
    if (::stat(dir.c_str(), &st) != 0) bad("directory '" + dir + "'", errno);
    if (!S_ISDIR(st.st_mode)) bad("'" + dir + "'", ENOTDIR);
    if (::access(dir.c_str(), W_OK | X_OK) != 0) bad("directory '" + dir + "'", errno);
    // The probe's name is unique to this process (the temp name itself may be in use by a writer
    // holding the lock) and exactly as long as the temp name, so NAME_MAX is probed too.
    const std::string probe = tempPathFor(target);
    std::string name = ".sbprobe" + std::to_string(::getpid());
    name.resize(std::max(name.size(), baseNameOf(probe).size()), 'x');
    const std::string unique = dir + "/" + name;
    int fd = ::open(unique.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, kNewFileMode);
    if (fd < 0) bad("cannot create temporary file '" + probe + "'", errno);
    ::close(fd);
    ::unlink(unique.c_str());
}

} // namespace sb
