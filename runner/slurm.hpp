#pragma once
// `rodsort sweep --slurm`: a sweep as a Slurm job array. The sweep directory is planned as for a
// local sweep; the points still to run become the tasks of one array, whose script
// (DIR/slurm/sweep.sbatch) runs each with `rodsort sweep SWEEP -o DIR --point INDEX`, which does
// what a local sweep does for that point (start, resume or skip it) in the task's own process.
// Slurm is asked for a SIGTERM some minutes before the time limit, on which the run writes its
// checkpoint and stops; submitting the same sweep again continues the unfinished points.

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace rodsort::runner {

struct SlurmOptions {
  bool enabled = false;
  bool submit = true;        ///< false: write the script only
  std::string partition;     ///< sbatch --partition; empty: the cluster's default
  std::string time_limit;    ///< sbatch --time, e.g. "12:00:00"; empty: the partition's default
  std::string memory;        ///< sbatch --mem, e.g. "2G"; empty: the cluster's default
  std::string account;       ///< sbatch --account; empty: none
  int throttle = 0;          ///< at most this many tasks at once (--array=...%N); 0: no limit
  int signal_seconds = 300;  ///< SIGTERM this long before the time limit
  std::vector<std::string> extra_lines;  ///< further "#SBATCH ..." lines, as given
};

/// What the array script needs to know of the sweep.
struct SlurmArray {
  std::string sweep_name;
  std::vector<std::string> program;  ///< the command that starts rodsort, absolute paths
  std::filesystem::path sweep_file;  ///< absolute
  std::filesystem::path directory;   ///< the sweep directory, absolute
  std::vector<std::size_t> points;   ///< indices of the points to run, ascending
  std::vector<std::string> set_options;
  bool any_build = false;
};

/// "0-3,5,7-9": ascending indices as Slurm's --array ranges.
std::string array_ranges(const std::vector<std::size_t>& indices);

/// A word for a POSIX shell: single-quoted unless it is made of safe characters only.
std::string shell_quote(const std::string& word);

/// The sbatch script of `array`.
std::string sbatch_script(const SlurmArray& array, const SlurmOptions& options);

/// Runs `sbatch --parsable SCRIPT` and returns the job id it printed. Throws std::runtime_error
/// with sbatch's message when it cannot be run or refuses the script.
std::string submit_sbatch(const std::filesystem::path& script);

}  // namespace rodsort::runner
