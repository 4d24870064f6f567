#include "bench/lib/callgrind/InstructionCount.h"

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "bench/lib/callgrind/ValgrindDiagnosis.h"
#include "core/DriverTable.h"
#include "core/Error.h"
#include "core/JsonReader.h"

extern char** environ;

namespace sb {

namespace fs = std::filesystem;

namespace {

constexpr const char* kOutPrefix = "callgrind.out";

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A row's text column, "" when absent or null (the bench writes null for an empty cell).
std::string rowText(const nlohmann::json& row, const char* key) {
    auto it = row.find(key);
    return it != row.end() && it->is_string() ? it->get<std::string>() : "";
}

int rowInt(const nlohmann::json& row, const char* key) {
    auto it = row.find(key);
    return it != row.end() && it->is_number() ? it->get<int>() : 0;
}

struct ChildResult {
    int status = -1;
    bool timedOut = false;
};

/// Runs argv with exactly `env`, stdout and stderr to files; waits at most `timeoutSeconds`.
ChildResult spawnAndWait(const std::vector<std::string>& argv, const std::map<std::string, std::string>& env,
                         const fs::path& out, const fs::path& err, double timeoutSeconds) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    std::vector<std::string> envText;
    for (const auto& [k, v] : env) envText.push_back(k + "=" + v);
    std::vector<char*> envp;
    for (std::string& e : envText) envp.push_back(e.data());
    envp.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    ChildResult r;
    if (rc != 0) return r;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
    for (;;) {
        const pid_t done = waitpid(pid, &r.status, WNOHANG);
        if (done == pid) return r;
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &r.status, 0);
            r.timedOut = true;
            return r;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
}

} // namespace

std::map<std::string, std::string> InstructionCount::pinnedEnvironment() {
    return {{"PATH", "/usr/local/bin:/usr/bin:/bin"}, {"LP_NUM_THREADS", "0"},
            {"MESA_SHADER_CACHE_DISABLE", "true"},    {"GALLIUM_DRIVER", "llvmpipe"},
            {"LIBGL_ALWAYS_SOFTWARE", "1"},           {"LD_BIND_NOW", "1"}};
}

std::string InstructionCount::valgrindVersion(const std::string& valgrind) {
    const fs::path dir = fs::temp_directory_path();
    const fs::path out = dir / ("sb-valgrind-version-" + std::to_string(getpid()) + ".txt");
    std::map<std::string, std::string> env;
    if (const char* path = std::getenv("PATH")) env["PATH"] = path;
    const ChildResult r = spawnAndWait({valgrind, "--version"}, env, out, "/dev/null", 30);
    std::string text = readFile(out);
    fs::remove(out);
    if (r.timedOut || !WIFEXITED(r.status) || WEXITSTATUS(r.status) != 0) return "";
    text.erase(text.find_last_not_of(" \r\n") + 1);
    return text;
}

bool InstructionCount::valgrindAvailable(const std::string& valgrind) {
    return valgrindVersion(valgrind).rfind("valgrind-3.", 0) == 0;
}

nlohmann::json InstructionRun::toJson(size_t topN) const {
    nlohmann::json list = nlohmann::json::array();
    for (const TechniqueInstructions& t : techniques) list.push_back(t.toJson(topN));
    return {{"command", command}, {"environment", pinned}, {"wall_s", wallSeconds}, {"techniques", list}};
}

InstructionCount::InstructionCount(Options options) : mOptions(std::move(options)) {}

std::vector<std::string> InstructionCount::commandLine() const {
    std::vector<std::string> argv = {
        mOptions.valgrind, "--tool=callgrind", "--instr-atstart=no",
        "--callgrind-out-file=" + (fs::path(mOptions.outDir) / kOutPrefix).string(), mOptions.bench};
    argv.insert(argv.end(), mOptions.benchArgs.begin(), mOptions.benchArgs.end());
    argv.insert(argv.end(), {"-q", "--format", "json"});
    return argv;
}

InstructionRun InstructionCount::run() const {
    for (const std::string& a : mOptions.benchArgs)
        if (a == "--format" || a.rfind("--format=", 0) == 0)
            throw Error("InstructionCount: bench arguments may not set --format (the rows are read as json)");
    if (mOptions.bench.empty() || !fs::exists(mOptions.bench))
        throw Error("InstructionCount: bench binary '" + mOptions.bench + "' not found");
    if (!valgrindAvailable(mOptions.valgrind))
        throw Error("InstructionCount: '" + mOptions.valgrind + " --version' does not run (install valgrind)",
                    ExitCode::Unsupported);
    const fs::path dir = mOptions.outDir;
    fs::create_directories(dir);
    // Stale dumps of an earlier run would be read as this run's techniques.
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().rfind(kOutPrefix, 0) == 0) fs::remove(entry.path());

    InstructionRun run;
    run.command = commandLine();
    for (const char* keep : {"LD_LIBRARY_PATH", "TMPDIR", "DISPLAY", "SHADOWBENCH_INJECT"})
        if (const char* v = std::getenv(keep)) run.environment[keep] = v;
    // The driver this process runs on (bench --driver X ci): without its vendor and ICD files the
    // child would load another driver's pieces, or fall back to OSMesa, and count their instructions.
    for (const std::string& keep : DriverTable::carriedVariables())
        if (const char* v = std::getenv(keep.c_str())) run.environment[keep] = v;
    for (const auto& [k, v] : mOptions.environment) run.environment[k] = v;
    run.pinned = mOptions.environment;

    const auto t0 = std::chrono::steady_clock::now();
    const ChildResult child = spawnAndWait(run.command, run.environment, dir / "stdout.json",
                                           dir / "stderr.txt", mOptions.timeoutSeconds);
    run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const std::string where = "InstructionCount: " + mOptions.bench + " under callgrind";
    if (child.timedOut)
        throw Error(where + ": killed after " + std::to_string(int(mOptions.timeoutSeconds)) + " s",
                    ExitCode::Failure);
    if (!WIFEXITED(child.status) || WEXITSTATUS(child.status) != 0) {
        // One line with the cause, not the log's last line (valgrind's summary, "I refs: 0"): an
        // instruction valgrind cannot run is this machine lacking what layer B needs (exit 3).
        const fs::path log = dir / "stderr.txt";
        const ValgrindDiagnosis why = ValgrindDiagnosis::of(child.status, readFile(log));
        throw Error(where + ": " + why.reason + " (log: " + log.string() + ")",
                    why.unsupported ? ExitCode::Unsupported : ExitCode::Failure);
    }

    run.rows = JsonReader::parse(readFile(dir / "stdout.json"), (dir / "stdout.json").string())
                   .value("rows", nlohmann::json());
    std::vector<CallgrindDump> dumps;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().filename().string().rfind(kOutPrefix, 0) == 0)
            dumps.push_back(CallgrindDump::read(entry.path().string()));
    std::sort(dumps.begin(), dumps.end(),
              [](const CallgrindDump& a, const CallgrindDump& b) { return a.part < b.part; });
    run.techniques = match(dumps, run.rows, fs::weakly_canonical(mOptions.bench).string());
    return run;
}

std::vector<TechniqueInstructions> InstructionCount::match(const std::vector<CallgrindDump>& dumps,
                                                           const nlohmann::json& rows,
                                                           const std::string& harness) {
    std::vector<TechniqueInstructions> out;
    size_t row = 0;
    const size_t rowCount = rows.is_array() ? rows.size() : 0;
    for (const CallgrindDump& dump : dumps) {
        if (dump.dumpName.empty()) continue; // the program-end dump (nothing counted after the last frame)
        while (row < rowCount && rowText(rows[row], "technique") != dump.dumpName) ++row;
        if (row == rowCount)
            throw Error("InstructionCount: callgrind dump " + std::to_string(dump.part) + " ('" +
                            dump.dumpName + "') has no matching bench row",
                        ExitCode::Failure);
        const nlohmann::json& r = rows[row++];
        out.push_back(TechniqueInstructions::fromDump(dump, dump.dumpName, rowText(r, "properties"),
                                                      rowInt(r, "frames"), harness));
    }
    if (out.empty() && rowCount > 0)
        throw Error("InstructionCount: the bench measured " + std::to_string(rowCount) +
                        " technique(s) but callgrind dumped none (bench built without SB_HAVE_VALGRIND?)",
                    ExitCode::Failure);
    return out;
}

} // namespace sb
