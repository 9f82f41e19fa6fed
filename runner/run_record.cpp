#include "runner/run_record.hpp"

#include <ctime>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "runner/atomic_file.hpp"
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
  // Keys in the order a person reads them (ordered_json keeps insertion order).
  nlohmann::ordered_json json;
  json["version"] = record.version;
  json["name"] = record.name;
  json["seed"] = record.seed;
  json["status"] = to_string(record.status);
  json["rods"] = record.rods;
  json["dt_s"] = record.dt_s;
  json["duration_s"] = record.duration_s;
  json["steps"] = record.steps;
  json["total_steps"] = record.total_steps;
  json["simulated_s"] = record.simulated_s;
  json["wall_s"] = record.wall_s;
  json["cpu_s"] = record.cpu_s;
  json["cpu_s_per_simulated_s"] = record.cpu_per_simulated_second();
  json["sessions"] = record.sessions;
  json["started_at"] = record.started_at;
  json["updated_at"] = record.updated_at;
  json["message"] = record.message;
  // Numbers in the shortest text that reads back to the same double; invalid UTF-8 in a message
  // (from a file name, say) is replaced rather than refused.
  return json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

RunRecord parse_run_record(const std::string& text) {
  try {
    const nlohmann::json json = nlohmann::json::parse(text);
    if (!json.is_object()) throw std::runtime_error("not a run record: not a JSON object");
    RunRecord record;
    record.version = json.at("version").get<std::string>();
    record.name = json.at("name").get<std::string>();
    record.seed = json.at("seed").get<std::uint64_t>();
    record.status = run_status_from_string(json.at("status").get<std::string>());
    record.rods = json.at("rods").get<int>();
    record.dt_s = json.at("dt_s").get<double>();
    record.duration_s = json.at("duration_s").get<double>();
    record.steps = json.at("steps").get<std::int64_t>();
    record.total_steps = json.at("total_steps").get<std::int64_t>();
    record.simulated_s = json.at("simulated_s").get<double>();
    record.wall_s = json.at("wall_s").get<double>();
    record.cpu_s = json.at("cpu_s").get<double>();
    record.sessions = json.at("sessions").get<int>();
    record.started_at = json.at("started_at").get<std::string>();
    record.updated_at = json.at("updated_at").get<std::string>();
    record.message = json.at("message").get<std::string>();
    return record;
  } catch (const nlohmann::json::exception& error) {
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
