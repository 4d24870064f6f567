#include "bench/lib/sweep/ChildProcess.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <deque>
#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "core/Error.h"

extern char** environ;

namespace sb {

namespace {

constexpr size_t kTailLines = 20;
std::atomic<pid_t> gCurrentChild{0};

/// The environment block for execve, built before fork (the child may only make async-signal-safe
/// calls between fork and exec, and setenv is not one).
std::vector<std::string> buildEnvironment(const std::vector<std::pair<std::string, std::string>>& extra) {
    std::vector<std::string> out;
    for (char** e = environ; *e; ++e) {
        const std::string entry(*e);
        bool replaced = false;
        for (const auto& [k, v] : extra) replaced = replaced || entry.rfind(k + "=", 0) == 0;
        if (!replaced) out.push_back(entry);
    }
    for (const auto& [k, v] : extra) out.push_back(k + "=" + v);
    return out;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
    std::vector<char*> out;
    for (std::string& s : strings) out.push_back(s.data());
    out.push_back(nullptr);
    return out;
}

/// Splits what arrives on a pipe into lines.
class LineBuffer {
public:
    template <typename F>
    void append(const char* data, size_t size, F&& onLine) {
        mPending.append(data, size);
        size_t nl;
        while ((nl = mPending.find('\n')) != std::string::npos) {
            onLine(mPending.substr(0, nl));
            mPending.erase(0, nl + 1);
        }
    }
    template <typename F>
    void flush(F&& onLine) {
        if (!mPending.empty()) onLine(mPending);
        mPending.clear();
    }

private:
    std::string mPending;
};

[[noreturn]] void execChild(int outFd, int errFd, std::vector<char*>& argv, std::vector<char*>& envp,
                            pid_t parent) {
    // Die with the parent; if it died before this line ran, do not start at all.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(127);
    ::dup2(outFd, STDOUT_FILENO);
    ::dup2(errFd, STDERR_FILENO);
    ::execve(argv[0], argv.data(), envp.data());
    const char msg[] = "bench: error: cannot start the sweep worker\n";
    (void)!::write(STDERR_FILENO, msg, sizeof msg - 1);
    ::_exit(127);
}

/// Reads both pipes until both are closed.
void pump(int outFd, int errFd, const ChildProcess::LineHandler& onStdoutLine,
          std::deque<std::string>& tail) {
    LineBuffer outLines, errLines;
    auto keepTail = [&](const std::string& line) {
        tail.push_back(line);
        if (tail.size() > kTailLines) tail.pop_front();
    };
    pollfd fds[2] = {{outFd, POLLIN, 0}, {errFd, POLLIN, 0}};
    int open = 2;
    char buf[4096];
    while (open > 0) {
        if (::poll(fds, 2, -1) < 0) {
            if (errno == EINTR) continue; // the SIGINT handler ran; the child is told and will exit
            break;
        }
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            const ssize_t n = ::read(fds[i].fd, buf, sizeof buf);
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                fds[i].fd = -1;
                --open;
                continue;
            }
            if (i == 0)
                outLines.append(buf, size_t(n), onStdoutLine);
            else
                errLines.append(buf, size_t(n), keepTail);
        }
    }
    outLines.flush(onStdoutLine);
    errLines.flush(keepTail);
}

} // namespace

std::string ChildExit::describe() const {
    if (signal == 0) return "exit code " + std::to_string(exitCode);
    const char* name = ::strsignal(signal);
    return "killed by signal " + std::to_string(signal) + (name ? std::string(" (") + name + ")" : "");
}

ChildExit ChildProcess::run(const std::vector<std::string>& argvIn,
                            const std::vector<std::pair<std::string, std::string>>& env,
                            const LineHandler& onStdoutLine) {
    std::vector<std::string> argvStrings = argvIn, envStrings = buildEnvironment(env);
    std::vector<char*> argv = pointers(argvStrings), envp = pointers(envStrings);
    int out[2], err[2];
    if (::pipe2(out, O_CLOEXEC) != 0)
        throw Error(std::string("cannot create a pipe: ") + std::strerror(errno), ExitCode::Failure);
    if (::pipe2(err, O_CLOEXEC) != 0) {
        const int e = errno;
        ::close(out[0]);
        ::close(out[1]);
        throw Error(std::string("cannot create a pipe: ") + std::strerror(e), ExitCode::Failure);
    }
    const pid_t parent = ::getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int e = errno;
        for (int fd : {out[0], out[1], err[0], err[1]}) ::close(fd);
        throw Error(std::string("cannot start a worker process: ") + std::strerror(e), ExitCode::Failure);
    }
    if (pid == 0) execChild(out[1], err[1], argv, envp, parent);
    gCurrentChild = pid;
    ::close(out[1]);
    ::close(err[1]);
    std::deque<std::string> tail;
    pump(out[0], err[0], onStdoutLine, tail);
    ::close(out[0]);
    ::close(err[0]);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    gCurrentChild = 0;
    ChildExit r;
    if (WIFSIGNALED(status))
        r.signal = WTERMSIG(status);
    else
        r.exitCode = WEXITSTATUS(status);
    for (const std::string& line : tail) r.stderrTail += line + "\n";
    return r;
}

void ChildProcess::interruptCurrent(int sig) {
    const pid_t pid = gCurrentChild.load();
    if (pid > 0) ::kill(pid, sig);
}

std::string ChildProcess::selfExecutable() {
    char buf[4096];
    const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
    if (n <= 0) throw Error("cannot find the running executable (/proc/self/exe)", ExitCode::Failure);
    return std::string(buf, size_t(n));
}

} // namespace sb
