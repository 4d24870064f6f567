#include "bench/lib/bisect/GitRepo.h"

#include "bench/lib/bisect/ToolPath.h"
#include "bench/lib/sweep/ChildProcess.h"
#include "core/Error.h"

namespace sb {

namespace {

/// git's stdout and stderr tail; exit code -1 when git could not be started at all.
int runGit(const std::vector<std::string>& args, std::string& out, std::string& err) {
    const std::string git = ToolPath::find("git");
    if (git.empty()) return -1;
    std::vector<std::string> argv = {git};
    argv.insert(argv.end(), args.begin(), args.end());
    out.clear();
    const ChildExit e = ChildProcess::run(argv, {}, [&](const std::string& line) { out += line + "\n"; });
    err = e.stderrTail;
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    return e.signal ? -1 : e.exitCode;
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s;
}

} // namespace

std::string GitRepo::toplevelOf(const std::string& dir) {
    std::string out, err;
    return runGit({"-C", dir, "rev-parse", "--show-toplevel"}, out, err) == 0 ? trimmed(out) : "";
}

void GitRepo::requireGit() {
    std::string out, err;
    // A child that cannot exec git exits 127 (the shell's convention) or fails to start.
    int code = -1;
    try {
        code = runGit({"--version"}, out, err);
    } catch (const Error&) {
    }
    if (code != 0 || out.rfind("git version", 0) != 0)
        throw Error("bisect needs git, which does not run here (apt-get install git)", ExitCode::Unsupported);
}

GitRepo::GitRepo(std::string dir) : mDir(std::move(dir)) {
    const std::string top = toplevelOf(mDir);
    if (top.empty()) throw Error("--repo " + mDir + ": not a git checkout", ExitCode::BadInput);
    mDir = top;
}

int GitRepo::tryRun(const std::vector<std::string>& args, std::string& out, std::string& err) const {
    std::vector<std::string> all = {"-C", mDir};
    all.insert(all.end(), args.begin(), args.end());
    return runGit(all, out, err);
}

std::string GitRepo::run(const std::vector<std::string>& args) const {
    std::string out, err;
    if (tryRun(args, out, err) != 0) {
        std::string command = "git";
        for (const std::string& a : args) command += " " + a;
        throw Error(command + " in " + mDir + " failed: " + err, ExitCode::Failure);
    }
    return out;
}

std::string GitRepo::resolve(const std::string& rev) const {
    std::string out, err;
    // "--end-of-options" keeps a revision that starts with '-' from being read as an option.
    if (rev.empty() ||
        tryRun({"rev-parse", "--verify", "--quiet", "--end-of-options", rev + "^{commit}"}, out, err) != 0)
        throw Error("bisect: unknown commit '" + rev + "' in " + mDir, ExitCode::BadInput);
    return trimmed(out);
}

bool GitRepo::isAncestor(const std::string& ancestor, const std::string& descendant) const {
    std::string out, err;
    const int code = tryRun({"merge-base", "--is-ancestor", ancestor, descendant}, out, err);
    if (code != 0 && code != 1)
        throw Error("git merge-base in " + mDir + " failed: " + err, ExitCode::Failure);
    return code == 0;
}

std::vector<std::string> GitRepo::firstParentRange(const std::string& good, const std::string& bad) const {
    const std::string text = run({"rev-list", "--first-parent", "--reverse", good + ".." + bad});
    std::vector<std::string> out;
    size_t at = 0;
    while (at < text.size()) {
        const size_t end = text.find('\n', at);
        const std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
        if (!line.empty()) out.push_back(line);
        if (end == std::string::npos) break;
        at = end + 1;
    }
    return out;
}

std::string GitRepo::subject(const std::string& commit) const {
    return trimmed(run({"log", "-1", "--format=%s", commit}));
}

} // namespace sb
