#pragma once
// One line's worth of a run, for sweep.csv and `rodsort summarize`: how far it got, what it cost,
// and its trapping efficiencies and sorting measures averaged over the plateau (the last half of
// the run, as the metrics layer defines it).

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "runner/run_record.hpp"

namespace rodsort::runner {

struct RunSummary {
  /// run.json's status, "stopped" for a run that says "running" but that no process holds (it was
  /// killed; `rodsort run --resume` continues it), or "pending" when there is no record.
  std::string status = "pending";
  double simulated_s = 0.0;  ///< [s]
  double wall_s = 0.0;       ///< [s]
  double cpu_per_simulated_s = 0.0;
  /// Every eta column of metrics.csv (eta, eta_trap, eta_<species>, ...) and every sorting
  /// measure (fraction_trap_<species>, purity_<species>, fraction_held_<species>,
  /// purity_held_<species>, sorting_index), in the file's order,
  /// with its mean over the last half of the run; NaN without a trap or without rows.
  std::vector<std::pair<std::string, double>> plateau_means;
  double eta_spread = 0.0;      ///< standard deviation of eta over the same samples
  double eta_time_to_90 = 0.0;  ///< [s] first time eta reaches 90% of its plateau; NaN if never

  /// The plateau mean of one column; NaN when absent.
  double plateau_mean(const std::string& column = "eta") const;
};

/// The status of a run as its record gives it, but "stopped" where the record says "running" and
/// no process holds the run's lock (it was killed; `rodsort run --resume` continues it).
std::string run_status(const std::filesystem::path& run_directory, const RunRecord& record);

/// Reads run.json and metrics.csv of a run directory. A directory without them is "pending".
/// Throws std::runtime_error naming the file when one exists but cannot be read.
RunSummary summarize_run(const std::filesystem::path& run_directory);

}  // namespace rodsort::runner
