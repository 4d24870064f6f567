#include "bench/lib/rows/Environment.h"

#include "bench/lib/output/ResultColumns.h"
#include "bench/lib/rows/BuildInfo.h"
#include "core/CpuAllocation.h"

#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <unistd.h>

namespace sb {

namespace {
std::string trim(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    size_t i = s.find_first_not_of(' ');
    return i == std::string::npos ? "" : s.substr(i);
}

std::string readCpuModel() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("model name", 0) == 0) {
            size_t colon = line.find(':');
            if (colon != std::string::npos) return trim(line.substr(colon + 1));
        }
    return "unknown";
}

} // namespace

std::string Environment::nowIso8601() {
    std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

std::string Environment::hostName() {
    char name[256] = {}; // above HOST_NAME_MAX (64 on Linux); one byte kept for the terminator
    if (::gethostname(name, sizeof name - 1) != 0 || !name[0]) return "unknown";
    return name;
}

Environment Environment::capture() {
    Environment e;
    e.timestamp = nowIso8601();
    // The commit the binary was built from (stamped at build time), never the tree's state now: a
    // checkout or edit after the build must not relabel rows measured with the old code.
    e.gitCommit = BuildInfo::commit();
    e.cpuModel = readCpuModel();
    // The allocation's CPUs, not the node's: a Slurm task on 4 CPUs of a 64-CPU node measured with
    // 4, and a row that said 64 would describe a machine the run never had.
    e.hardwareThreads = allocatedCpuCount();
    if (const char* lp = std::getenv("LP_NUM_THREADS")) e.lpNumThreads = lp;
    e.host = hostName();
    e.slurm = SlurmTask::fromEnvironment();
    return e;
}

CsvRow Environment::placeColumns() const {
    return {{col::kHost, host}, {col::kSlurmJobId, slurm.job()}, {col::kSlurmArrayTaskId, slurm.arrayTaskId}};
}

} // namespace sb
