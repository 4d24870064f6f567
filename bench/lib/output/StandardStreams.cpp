#include "bench/lib/output/StandardStreams.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <iostream>
#include <unistd.h>

#include "core/Error.h"

namespace sb {

namespace {
bool gStdoutClosed = false;
} // namespace

void StandardStreams::protect() {
    for (int fd = 0; fd <= 2; ++fd) {
        if (::fcntl(fd, F_GETFD) != -1 || errno != EBADF) continue;
        if (fd == STDOUT_FILENO) gStdoutClosed = true;
        // open() returns the lowest free descriptor, which is `fd` itself: the others are open or were
        // filled in the iterations before.
        int opened = ::open("/dev/null", fd == STDIN_FILENO ? O_RDONLY : O_WRONLY);
        if (opened >= 0 && opened != fd) ::close(opened);
    }
}

void StandardStreams::requireStdout(const std::string& what) {
    if (gStdoutClosed)
        throw Error(what + ": stdout is closed, so the rows would be lost (redirect it to a file, or use "
                           "--csv FILE)");
}

void StandardStreams::finishStdout(const std::string& what) {
    errno = 0;
    std::cout.flush();
    if (std::cout && std::fflush(stdout) == 0) return;
    const int err = errno;
    throw Error(what + ": writing to stdout failed" + (err ? std::string(": ") + std::strerror(err) : ""),
                ExitCode::Failure);
}

} // namespace sb
