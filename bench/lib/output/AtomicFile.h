#pragma once
// One result file, read and replaced under an exclusive lock (docs/ARCHITECTURE.md, "Results").
//
// Every write of a result file (CSV appends, whole tables, exported text) goes through this class, so
// that two processes writing one file — two runs with the same --csv, sweep shards sharing a file —
// serialise instead of losing each other's rows. The protocol:
//   1. refuse anything that is not a regular file (a device, a FIFO, a socket, a directory) before it is
//      opened: replacing /dev/null with a file, reading /dev/zero forever or blocking on a FIFO are
//      all worse than a one-line error;
//   2. open the file (creating it empty if absent) and take flock(LOCK_EX) on it; after the lock is
//      granted, check that the path still names the locked inode — a writer that held the lock before
//      may have renamed a new file over it, and then the lock is taken again on the new one;
//   3. read the content through the locked descriptor (streamed: bench/lib/output/CsvReader.h), then
//      either append in place (appendInPlace: one write at the end, fsync) or write the new content to
//      "<file>.tmp" in the same directory (beginReplace/write/commit, streamed), fsync it, rename() it
//      over the file, fsync the directory; release the lock.
// Only the lock holder writes "<file>.tmp", so one fixed name suffices: a writer killed half-way leaves
// at most one temp file, which the next writer truncates and reuses. Temp files of the older naming
// ("<file>.tmp.<pid>") left by processes that are gone are removed by the next writer.
// A crash during a replacement leaves either the old or the new file, never a truncated one. A crash
// during an in-place append can leave a partial last line after the complete old content: the next
// writer under the lock cuts it (cutPartialLastLine), and readers skip it with a warning naming the
// file (bench/lib/output/CsvReader.h).
#include <string>
#include <string_view>
#include <sys/types.h>

#include "core/Error.h"

namespace sb {

class AtomicFile {
public:
    /// Opens and locks `path` (a symbolic link is followed: the file it names is replaced, the link
    /// kept). `noun` names the file in messages ("CSV"). Throws sb::Error: BadInput when the path is
    /// empty or names something other than a regular file, Failure for an OS error (naming the path and
    /// the OS reason).
    AtomicFile(const std::string& path, std::string noun);
    /// Releases the lock. A file this object created and never committed is removed again, so a failed
    /// first write leaves no empty file behind.
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    /// The whole current content (empty for a file created by the constructor).
    std::string read() const;
    /// Permission bits of the current file; the replacement keeps them.
    mode_t mode() const { return mMode; }
    /// Replaces the file with `text` (temp file, fsync, rename, directory fsync). On failure the temp
    /// file is removed and the old file is untouched. Call at most once.
    void replace(const std::string& text);
    /// The same, streamed: beginReplace() creates the temp file, write() adds to it (buffered), commit()
    /// fsyncs and renames it over the file. A temp file never committed is removed by the destructor.
    void beginReplace();
    void write(std::string_view text);
    void commit();

    /// The locked descriptor (for CsvReader) and the current size of the file.
    int fd() const { return mFd; }
    off_t size() const;
    /// Appends `text` at the end of the file with one write and an fsync. On failure (a full disk) the
    /// file is cut back to its old size, so nothing is lost and no partial line stays; throws Failure
    /// naming the path and the OS reason.
    void appendInPlace(const std::string& text);
    /// When the file does not end in a newline (a writer killed during appendInPlace), cuts it back to
    /// its last newline and returns the bytes cut (0 when it ends in one or is empty). A file with no
    /// newline at all is left alone (the reader then skips it with a warning).
    off_t cutPartialLastLine();

    /// The up-front check before minutes of measuring: `path` is not empty, names a regular file or
    /// nothing, its directory exists and a file can be created there (probed with a temporary name, so
    /// read-only mounts and over-long names show too). Throws sb::Error(BadInput) naming the path and
    /// why; creates nothing that stays.
    static void checkWritable(const std::string& path, const std::string& noun);
    /// "<path>.tmp": the one temporary name the lock holder writes.
    static std::string tempPathFor(const std::string& path);

    [[noreturn]] void fail(const std::string& what, int err) const;

private:
    void lock();
    void removeStaleTemps() const;
    void flushTemp();
    [[noreturn]] void failTemp(const std::string& what, int err);

    std::string mPath;     ///< as given, for messages
    std::string mResolved; ///< the file written (the target of a link)
    std::string mNoun;
    int mFd = -1;
    mode_t mMode = 0;
    bool mCreated = false;
    bool mCommitted = false;
    int mTempFd = -1;        ///< the temp file between beginReplace and commit
    std::string mTempBuffer; ///< bytes not yet written to it
};

} // namespace sb
