#pragma once
// run.json: the small machine-readable record of a run, rewritten whole (atomically) when the run
// starts, at every checkpoint and when it ends. Sweeps read its status to skip finished points;
// benchmarks and papers read its cost.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace rodsort::runner {

enum class RunStatus { kRunning, kComplete, kInterrupted, kFailed };

std::string to_string(RunStatus status);
/// Throws std::runtime_error on an unknown word.
RunStatus run_status_from_string(const std::string& word);

struct RunRecord {
  std::string version;  ///< rodsort version that wrote the record
  std::string name;     ///< scenario name
  std::uint64_t seed = 0;
  RunStatus status = RunStatus::kRunning;
  int rods = 0;
  double dt_s = 0.0;             ///< time step [s]
  double duration_s = 0.0;       ///< simulated time the run ends at [s]
  std::int64_t steps = 0;        ///< steps taken so far
  std::int64_t total_steps = 0;  ///< steps of the whole run
  double simulated_s = 0.0;      ///< simulated time reached [s]
  double wall_s = 0.0;           ///< wall-clock seconds, summed over resumes
  double cpu_s = 0.0;            ///< CPU seconds, summed over resumes
  int sessions = 1;              ///< 1 + number of resumes
  std::string started_at;        ///< UTC, ISO 8601
  std::string updated_at;        ///< UTC, ISO 8601
  std::string message;           ///< why a run failed or was interrupted; empty otherwise

  /// The cost of the run: CPU seconds per simulated second (0 before any time has passed).
  double cpu_per_simulated_second() const;
};

std::string to_json(const RunRecord& record);
/// Throws std::runtime_error on text that is not a run record.
RunRecord parse_run_record(const std::string& json);

/// Reads DIR/run.json; nullopt when there is none. Throws when it exists but cannot be read.
std::optional<RunRecord> read_run_record(const std::filesystem::path& run_directory);
void write_run_record(const std::filesystem::path& run_directory, const RunRecord& record);

/// The current time, UTC, ISO 8601 with seconds ("2026-11-21T04:41:00Z").
std::string utc_now_iso8601();

}  // namespace rodsort::runner
