#pragma once
// How many processors this process may use: what `rodsort sweep` runs at once by default.

#include <optional>
#include <string_view>

namespace rodsort::runner {

/// From the number of processors in the affinity mask (`taskset`, cgroups' cpusets) and, inside a
/// Slurm allocation, SLURM_CPUS_PER_TASK or else SLURM_CPUS_ON_NODE: the smallest that is given
/// and valid, at least 1. Unset or unreadable variables are passed as nullopt.
int usable_cpus(int affinity_count, std::optional<std::string_view> slurm_cpus_per_task,
                std::optional<std::string_view> slurm_cpus_on_node);

/// usable_cpus() of this process: its affinity mask and its environment.
int usable_cpus();

}  // namespace rodsort::runner
