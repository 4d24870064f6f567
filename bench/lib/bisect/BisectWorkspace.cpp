#include "bench/lib/bisect/BisectWorkspace.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "bench/lib/bisect/ToolPath.h"
#include "bench/lib/sweep/ChildProcess.h"
#include "core/Error.h"
#include "core/Fnv1a.h"

namespace sb {

namespace {

namespace fs = std::filesystem;

/// Runs a build tool with its output appended to `log`; returns whether it exited 0.
bool runLogged(const std::vector<std::string>& argv, const std::string& log, std::string& stderrTail) {
    std::ofstream out(log, std::ios::app);
    const ChildExit e = ChildProcess::run(argv, {}, [&](const std::string& line) { out << line << "\n"; });
    out << e.stderrTail;
    stderrTail = e.stderrTail;
    return e.ok();
}

/// The last `n` lines of a file, on one line (the error message is one line).
std::string tailOf(const std::string& path, size_t n) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    std::string out;
    for (size_t i = lines.size() > n ? lines.size() - n : 0; i < lines.size(); ++i)
        out += (out.empty() ? "" : " | ") + lines[i];
    return out;
}

bool inside(const fs::path& path, const fs::path& root) {
    const std::string p = path.lexically_normal().string() + "/", r = root.lexically_normal().string() + "/";
    return p.compare(0, r.size(), r) == 0;
}

} // namespace

std::string BisectWorkspace::folderFor(const GitRepo& repo, const std::string& cacheRoot) {
    fs::path root = cacheRoot;
    if (root.empty()) {
        const char* xdg = std::getenv("XDG_CACHE_HOME");
        const char* user = std::getenv("USER");
        root = xdg && *xdg
                   ? fs::path(xdg) / "shadowbench" / "bisect"
                   : fs::path("/var/tmp") / ("shadowbench-bisect-" + std::string(user ? user : "user"));
    }
    root = fs::weakly_canonical(fs::absolute(root)); // "repo/../cache" printed as "cache"
    const fs::path source = fs::weakly_canonical(repo.dir());
    if (inside(root, source))
        throw Error("bisect: the cache folder " + root.string() + " lies inside the source tree " +
                        source.string() + " (give --cache-dir elsewhere)",
                    ExitCode::BadInput);
    // One folder per repository: its name and a hash of its path, so two checkouts never share a worktree.
    Fnv1a hash;
    hash.string(source.string());
    char key[32];
    std::snprintf(key, sizeof key, "-%08llx", (unsigned long long)(hash.result() & 0xffffffffull));
    return (root / (source.filename().string() + key)).string();
}

void BisectWorkspace::requireBuildTools() {
    for (const char* tool : {"cmake", "ninja"})
        if (ToolPath::find(tool).empty())
            throw Error(std::string("bisect needs ") + tool +
                            " to build commits, and it is not on PATH "
                            "(scripts/install-deps.sh installs it)",
                        ExitCode::Unsupported);
}

BisectWorkspace::BisectWorkspace(const GitRepo& repo, std::string folder, const std::string& commit)
    : mRepo(repo), mFolder(std::move(folder)), mCcache(!ToolPath::find("ccache").empty()) {
    fs::create_directories(mFolder);
    const std::string src = (fs::path(mFolder) / "src").string();
    // A worktree left by a bisection that was killed (SIGKILL runs no destructor): its files go, and
    // prune drops its registration, before this one is added at the same place.
    std::error_code ec;
    fs::remove_all(src, ec);
    mRepo.run({"worktree", "prune"});
    mRepo.run({"worktree", "add", "--detach", "--force", "--quiet", src, commit});
    mRegistered = true;
}

BisectWorkspace::~BisectWorkspace() {
    removeWorktree();
}

void BisectWorkspace::removeWorktree() noexcept {
    if (!mRegistered) return;
    mRegistered = false;
    try {
        mRepo.run({"worktree", "remove", "--force", (fs::path(mFolder) / "src").string()});
    } catch (...) {
        // The files are removed by hand and the registration pruned: cleaning up never throws.
        std::error_code ec;
        fs::remove_all(fs::path(mFolder) / "src", ec);
        try {
            mRepo.run({"worktree", "prune"});
        } catch (...) {
        }
    }
}

void BisectWorkspace::checkout(const std::string& commit) {
    GitRepo((fs::path(mFolder) / "src").string()).run({"checkout", "--detach", "--force", "--quiet", commit});
}

std::string BisectWorkspace::buildFolder() const {
    return (fs::path(mFolder) / "build").string();
}

std::string BisectWorkspace::benchPath() const {
    return (fs::path(buildFolder()) / "bench").string();
}

double BisectWorkspace::build(int jobs) {
    const auto start = std::chrono::steady_clock::now();
    const std::string log = (fs::path(mFolder) / "build.log").string();
    std::ofstream(log, std::ios::trunc).close();
    std::string tail;
    if (!fs::exists(fs::path(buildFolder()) / "CMakeCache.txt")) {
        std::vector<std::string> configure = {ToolPath::find("cmake"),
                                              "-S",
                                              (fs::path(mFolder) / "src").string(),
                                              "-B",
                                              buildFolder(),
                                              "-G",
                                              "Ninja",
                                              "-DCMAKE_BUILD_TYPE=Release",
                                              "-DSHADOWBENCH_BUILD_TESTS=OFF"};
        if (mCcache)
            for (const char* l :
                 {"-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"})
                configure.push_back(l);
        if (!runLogged(configure, log, tail))
            throw Error("cmake configure failed: " + tailOf(log, 3), ExitCode::Failure);
    }
    std::vector<std::string> make = {ToolPath::find("cmake"), "--build", buildFolder(), "--target", "bench"};
    if (jobs > 0) make.insert(make.end(), {"--parallel", std::to_string(jobs)});
    // The old binary must not pass for this commit's when the build fails before linking.
    std::error_code ec;
    fs::remove(benchPath(), ec);
    if (!runLogged(make, log, tail)) throw Error("build failed: " + tailOf(log, 3), ExitCode::Failure);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace sb
