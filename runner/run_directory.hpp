#pragma once
// The names of the files in a run directory (DESIGN §4, docs/cli.md), and the checks made before a
// run writes into one.

#include <filesystem>
#include <string>

#include "metrics/rod_frames.hpp"

namespace rodsort::runner {

inline constexpr const char* kResolvedScenarioFile = "scenario.resolved.yaml";
inline constexpr const char* kRodsCsvFile = metrics::kRodsCsvName;
inline constexpr const char* kRodsH5mdFile = metrics::kRodsH5mdName;
inline constexpr const char* kMetricsCsvFile = "metrics.csv";
inline constexpr const char* kTrajectoryFile = "trajectory.dump";
inline constexpr const char* kWallsDumpFile = "walls.dump";  ///< the trap's walls, for viewers
inline constexpr const char* kCheckpointFile = "checkpoint.bin";
inline constexpr const char* kRunRecordFile = "run.json";

/// "snapshot-t12.5.bullet": the .bullet snapshot taken at simulated time `time_s`.
std::string snapshot_file_name(double time_s);

/// Whether `directory` already holds (part of) a run: any of the files a run writes (its lock file
/// alone does not count).
bool holds_run(const std::filesystem::path& directory);

/// The first line of the run's metrics.csv, its columns; empty when the file is absent or empty.
std::string metrics_csv_header(const std::filesystem::path& directory);

/// Removes the files a run writes from `directory`, and nothing else (for --force); the lock file
/// stays, since the caller holds it.
void clear_run(const std::filesystem::path& directory);

}  // namespace rodsort::runner
