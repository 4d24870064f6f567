#pragma once
// The Slurm job a process runs in, from the variables Slurm sets in a task's environment (all empty
// outside Slurm): recorded in every row (`slurm_job_id`, `slurm_array_task_id`) and in the lock a sweep
// holds on its part file, so that a row or a refusal names the task behind it.
#include <string>

namespace sb {

struct SlurmTask {
    std::string jobId;       ///< SLURM_JOB_ID: this task's own job id (each array task has one)
    std::string arrayJobId;  ///< SLURM_ARRAY_JOB_ID: the array's job id (a job array only)
    std::string arrayTaskId; ///< SLURM_ARRAY_TASK_ID: the index within the array (a job array only)

    static SlurmTask fromEnvironment();
    /// The job a user names: the array's job id for an array task (`squeue` and `sacct` list the task
    /// as `<array job>_<index>`), else SLURM_JOB_ID; "" outside Slurm.
    std::string job() const { return arrayJobId.empty() ? jobId : arrayJobId; }
    /// "Slurm job 70_3 (SLURM_JOB_ID 71)" for an array task, "Slurm job 71" for a job, "" outside Slurm.
    std::string describe() const;
};

} // namespace sb
