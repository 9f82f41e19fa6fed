#include "runner/run_summary.hpp"

#include <limits>

#include "metrics/time_series.hpp"
#include "runner/csv_table.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_lock.hpp"
#include "runner/run_record.hpp"

namespace rodsort::runner {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double RunSummary::plateau_mean(const std::string& column) const {
  for (const auto& [name, mean] : plateau_means) {
    if (name == column) return mean;
  }
  return kNaN;
}

std::string run_status(const std::filesystem::path& run_directory, const RunRecord& record) {
  // run.json says "running" until the run ends; a run killed outright (SIGKILL, power cut) never
  // ends, so only a held lock says it is still going.
  if (record.status == RunStatus::kRunning &&
      std::filesystem::exists(run_directory / kRunLockFile) && RunLock::acquire(run_directory)) {
    return "stopped";
  }
  return to_string(record.status);
}

RunSummary summarize_run(const std::filesystem::path& run_directory) {
  RunSummary summary;
  summary.eta_spread = kNaN;
  summary.eta_time_to_90 = kNaN;
  const auto record = read_run_record(run_directory);
  if (!record) return summary;
  summary.status = run_status(run_directory, *record);
  summary.simulated_s = record->simulated_s;
  summary.wall_s = record->wall_s;
  summary.cpu_per_simulated_s = record->cpu_per_simulated_second();

  const std::filesystem::path metrics_path = run_directory / kMetricsCsvFile;
  if (!std::filesystem::exists(metrics_path)) return summary;
  const CsvTable table = read_csv(metrics_path);
  const auto time_column = table.column("t");
  if (!time_column) throw std::runtime_error(metrics_path.string() + ": no column t");
  const std::vector<double> times = table.numbers(*time_column);
  for (std::size_t column = 0; column < table.header.size(); ++column) {
    const std::string& name = table.header[column];
    const bool averaged = name.rfind("eta", 0) == 0 || name.rfind("fraction_trap_", 0) == 0 ||
                          name.rfind("purity_", 0) == 0 || name.rfind("fraction_held_", 0) == 0 ||
                          name == "sorting_index" || name == "n_wall";
    if (!averaged) continue;
    if (table.rows.empty()) {
      summary.plateau_means.emplace_back(name, kNaN);
      continue;
    }
    const metrics::PlateauStats stats = metrics::plateau_stats(times, table.numbers(column));
    summary.plateau_means.emplace_back(name, stats.mean);
    if (name == "eta") {
      summary.eta_spread = stats.spread;
      summary.eta_time_to_90 = stats.time_to_90;
    }
  }
  return summary;
}

}  // namespace rodsort::runner
