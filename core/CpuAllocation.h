#pragma once
// The CPUs this process was given, as opposed to the CPUs of the machine. A Slurm task (its cpuset),
// `taskset -c 0`, a container's cgroup or `parallel ... taskset -c {}` narrows the process's affinity
// mask; std::thread::hardware_concurrency() still counts every CPU of the node. Whatever sizes work
// by the CPUs available (the reference tracer's default thread count) and whatever records them (the
// rows' `hw_threads`) asks here, so that both say what the process may actually run on.
#include <optional>
#include <string_view>

namespace sb {

/// The number of CPUs in the process's affinity mask: what sched_getaffinity() counts (CPU_COUNT), read
/// from the `Cpus_allowed_list` the kernel publishes in /proc/self/status (core/ stands on the standard
/// library alone, docs/ARCHITECTURE.md, "Layout"). Where that is unreadable (not Linux, no /proc), the
/// machine's std::thread::hardware_concurrency(). At least 1.
int allocatedCpuCount();

/// The number of CPUs in a kernel CPU list ("0-3,8,10-11" is 7; the format of `Cpus_allowed_list` and
/// of cpuset files); nullopt when `list` is not one (empty, a descending range, other characters).
std::optional<int> countCpuList(std::string_view list);

} // namespace sb
