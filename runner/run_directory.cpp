#include "runner/run_directory.hpp"

#include <array>
#include <cstdio>
#include <fstream>
#include <vector>

namespace rodsort::runner {
namespace {

constexpr std::array kRunFiles = {kResolvedScenarioFile, kRodsCsvFile,    kRodsH5mdFile,
                                  kMetricsCsvFile,       kTrajectoryFile, kWallsDumpFile,
                                  kCheckpointFile,       kRunRecordFile};

bool is_snapshot(const std::filesystem::path& file) {
  const std::string name = file.filename().string();
  return name.rfind("snapshot-t", 0) == 0 && file.extension() == ".bullet";
}

}  // namespace

std::string snapshot_file_name(double time_s) {
  char text[64];
  std::snprintf(text, sizeof text, "snapshot-t%.10g.bullet", time_s);
  return text;
}

bool holds_run(const std::filesystem::path& directory) {
  if (!std::filesystem::is_directory(directory)) return false;
  for (const char* name : kRunFiles) {
    if (std::filesystem::exists(directory / name)) return true;
  }
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (is_snapshot(entry.path())) return true;
  }
  return false;
}

void clear_run(const std::filesystem::path& directory) {
  if (!std::filesystem::is_directory(directory)) return;
  for (const char* name : kRunFiles) {
    std::filesystem::remove(directory / name);
    std::filesystem::remove(directory / (std::string(name) + ".tmp"));
  }
  std::vector<std::filesystem::path> snapshots;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (is_snapshot(entry.path())) snapshots.push_back(entry.path());
  }
  for (const auto& snapshot : snapshots) std::filesystem::remove(snapshot);
}

std::string metrics_csv_header(const std::filesystem::path& directory) {
  std::ifstream in(directory / kMetricsCsvFile);
  std::string header;
  std::getline(in, header);
  return header;
}

}  // namespace rodsort::runner
