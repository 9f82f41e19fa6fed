#include "runner/checkpoint.hpp"

#include <charconv>
#include <sstream>
#include <stdexcept>

#include "runner/atomic_file.hpp"
#include "runner/json_text.hpp"

namespace rodsort::runner {
namespace {

constexpr const char* kMagic = "rodsort-checkpoint 1";
constexpr const char* kFileBytesPrefix = "bytes:";

double parse_double(const std::string& text, const std::string& key) {
  double value = 0.0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) {
    throw std::runtime_error("bad value '" + text + "' for " + key);
  }
  return value;
}

std::uint64_t parse_unsigned(const std::string& text, const std::string& key) {
  std::uint64_t value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  if (result.ec != std::errc() || result.ptr != text.data() + text.size()) {
    throw std::runtime_error("bad value '" + text + "' for " + key);
  }
  return value;
}

}  // namespace

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint) {
  std::ostringstream out(std::ios::binary);
  out << kMagic << '\n';
  for (const auto& [file, bytes] : checkpoint.file_bytes) {
    out << kFileBytesPrefix << file << ' ' << bytes << '\n';
  }
  out << "wall_s " << json_number(checkpoint.wall_s) << '\n';
  out << "cpu_s " << json_number(checkpoint.cpu_s) << '\n';
  out << "sessions " << checkpoint.sessions << '\n';
  out << "started_at " << checkpoint.started_at << '\n';
  out << "metrics_replay_offset " << checkpoint.metrics_replay_offset << '\n';
  out << "state\n";
  engine::write_state(out, checkpoint.state);
  write_file_atomically(path, out.str());
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  try {
    std::istringstream in(read_file(path), std::ios::binary);
    std::string line;
    if (!std::getline(in, line) || line != kMagic) throw std::runtime_error("not a checkpoint");
    Checkpoint checkpoint;
    bool has_state = false;
    while (std::getline(in, line)) {
      if (line == "state") {
        has_state = true;
        break;
      }
      const std::size_t space = line.find(' ');
      if (space == std::string::npos) throw std::runtime_error("bad line '" + line + "'");
      const std::string key = line.substr(0, space);
      const std::string value = line.substr(space + 1);
      if (key.rfind(kFileBytesPrefix, 0) == 0) {
        checkpoint.file_bytes[key.substr(std::string(kFileBytesPrefix).size())] =
            parse_unsigned(value, key);
      } else if (key == "wall_s") {
        checkpoint.wall_s = parse_double(value, key);
      } else if (key == "cpu_s") {
        checkpoint.cpu_s = parse_double(value, key);
      } else if (key == "sessions") {
        checkpoint.sessions = static_cast<int>(parse_unsigned(value, key));
      } else if (key == "metrics_replay_offset") {
        checkpoint.metrics_replay_offset = parse_unsigned(value, key);
      } else if (key == "started_at") {
        checkpoint.started_at = value;
      } else {
        throw std::runtime_error("unknown key '" + key + "'");
      }
    }
    if (!has_state) throw std::runtime_error("truncated before the state");
    checkpoint.state = engine::read_state(in);
    return checkpoint;
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("checkpoint " + path.string() + ": " + error.what());
  }
}

}  // namespace rodsort::runner
