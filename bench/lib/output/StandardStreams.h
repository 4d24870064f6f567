#pragma once
// The process's standard streams as outputs that can fail. A closed stdout (`bench >&-`) is dangerous
// twice: the rows printed there are lost while the run exits 0, and the next file the process opens
// gets descriptor 1, so the rows would land in it. protect() fills closed descriptors 0-2 with
// /dev/null before anything is opened and remembers which were closed; a command that prints its rows
// on stdout asks requireStdout() before it measures and finishStdout() after it printed.
#include <string>

namespace sb {

class StandardStreams {
public:
    /// Call first in main(). Closed descriptors 0, 1 and 2 are reopened on /dev/null.
    static void protect();
    /// Throws sb::Error(BadInput) "<what>: stdout is closed ..." when stdout was closed at start.
    static void requireStdout(const std::string& what);
    /// Flushes std::cout and throws sb::Error(Failure) naming `what` and the OS reason when a write to
    /// stdout failed (a full disk, a closed pipe that did not end the process).
    static void finishStdout(const std::string& what);
};

} // namespace sb
