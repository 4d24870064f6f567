#include "bench/lib/rows/SlurmTask.h"

#include <cstdlib>

namespace sb {

namespace {
std::string variable(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}
} // namespace

SlurmTask SlurmTask::fromEnvironment() {
    return {variable("SLURM_JOB_ID"), variable("SLURM_ARRAY_JOB_ID"), variable("SLURM_ARRAY_TASK_ID")};
}

std::string SlurmTask::describe() const {
    if (arrayJobId.empty()) return jobId.empty() ? "" : "Slurm job " + jobId;
    std::string out = "Slurm job " + arrayJobId + "_" + (arrayTaskId.empty() ? "?" : arrayTaskId);
    return jobId.empty() ? out : out + " (SLURM_JOB_ID " + jobId + ")";
}

} // namespace sb
