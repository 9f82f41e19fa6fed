#include "runner/run_record.hpp"

#include <yaml-cpp/yaml.h>

#include <ctime>
#include <stdexcept>
#include <string>

#include "runner/atomic_file.hpp"
#include "runner/json_text.hpp"
#include "runner/run_directory.hpp"

namespace rodsort::runner {

std::string to_string(RunStatus status) {
  switch (status) {
    case RunStatus::kRunning:
      return "running";
    case RunStatus::kComplete:
      return "complete";
    case RunStatus::kInterrupted:
      return "interrupted";
    case RunStatus::kFailed:
      return "failed";
  }
  return "unknown";
}

RunStatus run_status_from_string(const std::string& word) {
  if (word == "running") return RunStatus::kRunning;
  if (word == "complete") return RunStatus::kComplete;
  if (word == "interrupted") return RunStatus::kInterrupted;
  if (word == "failed") return RunStatus::kFailed;
  throw std::runtime_error("unknown run status '" + word + "'");
}

double RunRecord::cpu_per_simulated_second() const {
  return simulated_s > 0.0 ? cpu_s / simulated_s : 0.0;
}

std::string to_json(const RunRecord& record) {
  std::string json = "{\n";
  const auto field = [&json](const char* key, const std::string& value, bool last = false) {
    json += "  ";
    json += json_quote(key);
    json += ": ";
    json += value;
    json += last ? "\n" : ",\n";
  };
  field("version", json_quote(record.version));
  field("name", json_quote(record.name));
  field("seed", std::to_string(record.seed));
  field("status", json_quote(to_string(record.status)));
  field("rods", std::to_string(record.rods));
  field("dt_s", json_number(record.dt_s));
  field("duration_s", json_number(record.duration_s));
  field("steps", std::to_string(record.steps));
  field("total_steps", std::to_string(record.total_steps));
  field("simulated_s", json_number(record.simulated_s));
  field("wall_s", json_number(record.wall_s));
  field("cpu_s", json_number(record.cpu_s));
  field("cpu_s_per_simulated_s", json_number(record.cpu_per_simulated_second()));
  field("sessions", std::to_string(record.sessions));
  field("started_at", json_quote(record.started_at));
  field("updated_at", json_quote(record.updated_at));
  field("message", json_quote(record.message), true);
  json += "}\n";
  return json;
}

RunRecord parse_run_record(const std::string& json) {
  try {
    // JSON is a subset of YAML 1.2 as far as this record goes.
    const YAML::Node root = YAML::Load(json);
    if (!root.IsMap()) throw std::runtime_error("not a run record: not a JSON object");
    RunRecord record;
    record.version = root["version"].as<std::string>();
    record.name = root["name"].as<std::string>();
    record.seed = root["seed"].as<std::uint64_t>();
    record.status = run_status_from_string(root["status"].as<std::string>());
    record.rods = root["rods"].as<int>();
    record.dt_s = root["dt_s"].as<double>();
    record.duration_s = root["duration_s"].as<double>();
    record.steps = root["steps"].as<std::int64_t>();
    record.total_steps = root["total_steps"].as<std::int64_t>();
    record.simulated_s = root["simulated_s"].as<double>();
    record.wall_s = root["wall_s"].as<double>();
    record.cpu_s = root["cpu_s"].as<double>();
    record.sessions = root["sessions"].as<int>();
    record.started_at = root["started_at"].as<std::string>();
    record.updated_at = root["updated_at"].as<std::string>();
    record.message = root["message"].as<std::string>();
    return record;
  } catch (const YAML::Exception& error) {
    throw std::runtime_error(std::string("not a run record: ") + error.what());
  }
}

std::optional<RunRecord> read_run_record(const std::filesystem::path& run_directory) {
  const std::filesystem::path path = run_directory / kRunRecordFile;
  if (!std::filesystem::exists(path)) return std::nullopt;
  try {
    return parse_run_record(read_file(path));
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(path.string() + ": " + error.what());
  }
}

void write_run_record(const std::filesystem::path& run_directory, const RunRecord& record) {
  write_file_atomically(run_directory / kRunRecordFile, to_json(record));
}

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

}  // namespace rodsort::runner
