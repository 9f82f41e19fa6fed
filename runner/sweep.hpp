#pragma once
// `rodsort sweep`: every point of a sweep file run as its own `rodsort run` process, N at a time
// (one simulation uses one core). The sweep directory holds:
//
//   scenarios/<point>.yaml  the point's resolved scenario, which its run reads
//   <point>/                the point's run directory (see docs/cli.md)
//   logs/<point>.log        what the point's process printed
//   sweep.csv               one row per point: swept values, status, time-averaged eta, cost
//
// Running a sweep again continues it: complete points are skipped, stopped ones resumed from their
// checkpoints, and with `--set run.duration=T` complete ones continued to the new time.
// With --slurm the points to run become a Slurm job array instead (runner/slurm.hpp). A point whose
// run directory holds a different scenario (the sweep file changed) is refused unless --force, so
// that sweep.csv never mixes two definitions of a point.

#include <cstdio>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "runner/slurm.hpp"

namespace rodsort::runner {

struct SweepRequest {
  std::filesystem::path sweep_file;
  std::filesystem::path output;  ///< the sweep directory; empty: runs/<sweep name>
  int jobs = 0;                  ///< points run at once; 0: runner::usable_cpus()
  bool force = false;            ///< rerun points whose run holds a different scenario
  bool dry_run = false;          ///< check and list the points, run nothing, write nothing
  bool any_build = false;  ///< resume points whose checkpoint another build wrote (RunOptions)
  /// "key.path=value" for every point, after the sweep file's own `set`. A point that ran with
  /// another run.duration only is continued to the new one (`rodsort run --resume --duration`).
  std::vector<std::string> set_options;
  /// Run only this point (its index in the grid, or its name), in this process: what each task
  /// of a Slurm array does. Complete: nothing to do.
  std::string point;
  SlurmOptions slurm;
  /// The rodsort program the points run with; empty: this program (program_command()).
  std::filesystem::path executable;
  std::FILE* log = stderr;  ///< progress lines; nullptr: none
};

/// Runs a sweep (with dry_run, lists its points on `out`). kExitUsage when the sweep file or a
/// point is refused (nothing written) or a point conflicts; kExitFailure when a point failed;
/// kExitInterrupted when stopped by a signal.
int run_sweep(const SweepRequest& request, std::ostream& out, std::ostream& err);

/// `rodsort sweep --status DIR`: every point's state (done, running, interrupted, stopped,
/// failed with its message, not started), the simulated time it reached and, while it runs, an
/// ETA; then sweep.csv is brought up to date. kExitUsage when DIR holds no sweep.
int sweep_status(const std::filesystem::path& directory, std::ostream& out, std::ostream& err);

/// The sweep.csv columns before the swept keys and after them, for readers of the file.
inline constexpr const char* kSweepPointColumn = "point";
inline constexpr const char* kSweepStatusColumn = "status";

/// Rewrites sweep.csv of `sweep_directory` from the points' run directories: the rows `points`
/// (names) with their swept `values` under `keys`.
void write_sweep_csv(const std::filesystem::path& sweep_directory,
                     const std::vector<std::string>& keys, const std::vector<std::string>& points,
                     const std::vector<std::vector<std::string>>& values);

}  // namespace rodsort::runner
