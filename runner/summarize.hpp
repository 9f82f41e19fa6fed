#pragma once
// `rodsort summarize SWEEP_DIR`: the sweep's points with their time-averaged eta (the mean over the
// last half of each run), refreshed from the points' metrics.csv, and, when the sweep is over the
// trap's angle, theta_c: the angle where eta falls through half its low-angle plateau (the metrics
// layer's critical_angle), for each combination of the other swept keys, seeds averaged.

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <vector>

#include "runner/csv_table.hpp"

namespace rodsort::runner {

/// Prints the table on `out`, rewrites sweep.csv, and writes critical_angle.csv when the angle was
/// swept.
int summarize_sweep(const std::filesystem::path& sweep_directory, std::ostream& out,
                    std::ostream& err);

/// How `rodsort summarize` reads the eta(t) of run directories.
struct RunHistoryOptions {
  /// A nucleation attempt begins when eta_trap (eta in a run without it) rises above `rise` and
  /// has failed when it falls back below `fall`.
  double rise = 0.3;
  double fall = 0.1;
  /// [s] length of the windows of the eta means; 0: a round length that makes at most 10.
  double window_s = 0.0;
  /// [s] read the rows up to this time only (0: all), to compare runs of different lengths.
  double until_s = 0.0;
  /// When not empty, the same figures also go to this CSV file, one row per run.
  std::filesystem::path csv;
};

/// `rodsort summarize RUN_DIR...`: for each run, how far it got, eta and eta_trap over the last
/// half, when eta first reached 90% of that, their means per window, and its nucleation attempts
/// (metrics::nucleation_attempts); with `options.csv`, the same as a table of one row per run.
/// When the runs are of one scenario at two angles or more (seeds aside), theta_c as for a sweep
/// over the angle and the seed. Exit 2 for a directory that holds no run or a CSV file whose folder
/// does not exist.
int summarize_runs(const std::vector<std::filesystem::path>& run_directories,
                   const RunHistoryOptions& options, std::ostream& out, std::ostream& err);

/// For `rodsort plot RUN_DIR... --what eta-theta`: runs made one by one as the rows of a sweep
/// table (sweep.csv's columns point, trap.angle, the keys where their scenarios differ as
/// `summarize_runs` groups them, seed, status, eta_mean, eta_time_to_90_s, simulated_s), eta read
/// over the last half of each run up to `options.until_s`. Only the runs that count are rows; those
/// left out are named on `err`. std::nullopt, with the reason on `err`, when the directories hold
/// no runs or the runs make no curve (one angle, no run complete, or scenarios too different).
std::optional<CsvTable> runs_sweep_table(const std::vector<std::filesystem::path>& run_directories,
                                         const RunHistoryOptions& options, std::ostream& err);

}  // namespace rodsort::runner
