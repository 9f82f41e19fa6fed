// `rodsort sweep --status DIR`: what each point of a sweep is doing, read from the points' run
// directories alone, so that it works the same for a local sweep and for a Slurm array whose
// tasks run on other machines (the run directories are on a shared file system).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/progress.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_lock.hpp"
#include "runner/run_record.hpp"
#include "runner/sweep.hpp"

namespace rodsort::runner {
namespace {

struct PointStatus {
  std::string state;   ///< done, running, interrupted, stopped, failed, not started
  std::string detail;  ///< the failure's message, or how a stopped run can go on
  double simulated_s = 0.0;
  double duration_s = 0.0;
  double eta_s = NAN;  ///< wall seconds left, for running points
  double cpu_per_simulated_s = NAN;
};

PointStatus point_status(const std::filesystem::path& run_directory) {
  PointStatus status;
  std::optional<RunRecord> record;
  try {
    record = read_run_record(run_directory);
  } catch (const std::exception& error) {
    status.state = "unreadable";
    status.detail = error.what();
    return status;
  }
  if (!record) {
    status.state = RunLock::held(run_directory) ? "starting" : "not started";
    return status;
  }
  status.simulated_s = record->simulated_s;
  status.duration_s = record->duration_s;
  if (record->simulated_s > 0.0) status.cpu_per_simulated_s = record->cpu_per_simulated_second();
  const bool locked = RunLock::held(run_directory);
  switch (record->status) {
    case RunStatus::kComplete:
      status.state = "done";
      break;
    case RunStatus::kFailed:
      status.state = "failed";
      status.detail = record->message;
      break;
    case RunStatus::kInterrupted:
      status.state = locked ? "running" : "interrupted";
      if (!locked) status.detail = record->message;
      break;
    case RunStatus::kRunning:
      // A run killed without a chance to write its record (SIGKILL, a node lost) says "running"
      // but holds no lock: it continues from its last checkpoint.
      status.state = locked ? "running" : "stopped";
      if (!locked) status.detail = "killed; continues from its last checkpoint";
      break;
  }
  if (status.state == "running" && record->simulated_s > 0.0 && record->wall_s > 0.0) {
    status.eta_s =
        (record->duration_s - record->simulated_s) * record->wall_s / record->simulated_s;
  }
  return status;
}

std::string seconds_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

}  // namespace

int sweep_status(const std::filesystem::path& directory, std::ostream& out, std::ostream& err) {
  const std::filesystem::path csv = directory / "sweep.csv";
  if (!std::filesystem::exists(csv)) {
    err << "rodsort: " << directory.string()
        << " holds no sweep (no sweep.csv); give the directory a sweep wrote into\n";
    return kExitUsage;
  }
  CsvTable table;
  try {
    table = read_csv(csv);
  } catch (const std::exception& error) {
    err << "rodsort: " << error.what() << '\n';
    return kExitFailure;
  }
  const auto point_column = table.column(kSweepPointColumn);
  const auto status_column = table.column(kSweepStatusColumn);
  if (!point_column || !status_column || *point_column != 0 || *status_column < 1) {
    err << "rodsort: " << csv.string() << " is not a sweep's table (no point and status columns)\n";
    return kExitUsage;
  }
  const std::vector<std::string> keys(table.header.begin() + 1,
                                      table.header.begin() + static_cast<long>(*status_column));
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> values;
  std::size_t width = 5;
  for (const std::vector<std::string>& row : table.rows) {
    names.push_back(row[0]);
    values.emplace_back(row.begin() + 1, row.begin() + static_cast<long>(*status_column));
    width = std::max(width, row[0].size());
  }

  std::vector<std::pair<std::string, int>> counts;
  const auto count = [&counts](const std::string& state) {
    for (auto& [name, n] : counts) {
      if (name == state) {
        ++n;
        return;
      }
    }
    counts.emplace_back(state, 1);
  };
  double eta = 0.0;
  char line[512];
  std::snprintf(line, sizeof line, "%-*s  %-11s  %-17s  %11s  %s\n", static_cast<int>(width),
                "point", "state", "simulated [s]", "CPU-s/sim-s", "ETA or message");
  out << "sweep in " << directory.string() << ": " << names.size() << " points\n" << line;
  for (const std::string& name : names) {
    const PointStatus status = point_status(directory / name);
    count(status.state);
    const std::string reached = status.duration_s > 0.0 ? seconds_text(status.simulated_s) + " / " +
                                                              seconds_text(status.duration_s)
                                                        : "-";
    const std::string cost =
        std::isnan(status.cpu_per_simulated_s) ? "-" : seconds_text(status.cpu_per_simulated_s);
    std::string last = status.detail;
    if (!std::isnan(status.eta_s)) {
      last = "ETA " + format_duration(status.eta_s);
      eta = std::max(eta, status.eta_s);
    }
    std::snprintf(line, sizeof line, "%-*s  %-11s  %-17s  %11s  %s\n", static_cast<int>(width),
                  name.c_str(), status.state.c_str(), reached.c_str(), cost.c_str(), last.c_str());
    out << line;
  }
  out << "in all:";
  for (std::size_t i = 0; i < counts.size(); ++i) {
    out << (i == 0 ? " " : ", ") << counts[i].second << ' ' << counts[i].first;
  }
  if (eta > 0.0) out << "; the running points end in about " << format_duration(eta);
  out << '\n';
  try {
    write_sweep_csv(directory, keys, names, values);
    out << "sweep.csv brought up to date: " << csv.string() << '\n';
  } catch (const std::exception& error) {
    err << "rodsort: cannot update " << csv.string() << ": " << error.what() << '\n';
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace rodsort::runner
