#include "runner/checkpoint.hpp"

#include <charconv>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include "engine/fingerprint.hpp"
#include "runner/atomic_file.hpp"
#include "runner/version.hpp"
#include "scenarios/number_text.hpp"

namespace rodsort::runner {
namespace {

constexpr const char* kMagic = "rodsort-checkpoint 3";
constexpr const char* kFormat1Magic = "rodsort-checkpoint 1";
constexpr const char* kFormat2Magic = "rodsort-checkpoint 2";
// The file ends with this line: "checksum " and 16 hex digits of the fingerprint of every byte
// before it.
constexpr std::string_view kChecksumPrefix = "checksum ";
constexpr std::size_t kChecksumLine = 9 + 16 + 1;

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}
constexpr const char* kFileBytesPrefix = "bytes:";
constexpr const char* kFileFramesPrefix = "frames:";

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

std::uint64_t parse_hex(const std::string& text, const std::string& key) {
  std::uint64_t value = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value, 16);
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
  for (const auto& [file, frames] : checkpoint.file_frames) {
    out << kFileFramesPrefix << file << ' ' << frames << '\n';
  }
  out << "wall_s " << scenarios::format_real(checkpoint.wall_s) << '\n';
  out << "cpu_s " << scenarios::format_real(checkpoint.cpu_s) << '\n';
  out << "sessions " << checkpoint.sessions << '\n';
  out << "started_at " << checkpoint.started_at << '\n';
  out << "metrics_replay_offset " << checkpoint.metrics_replay_offset << '\n';
  out << "scenario_fingerprint " << hex(checkpoint.scenario_fingerprint) << '\n';
  if (checkpoint.build.find('\n') != std::string::npos) {
    throw std::invalid_argument("write_checkpoint: a build identity holds no line break");
  }
  out << "build " << checkpoint.build << '\n';
  out << "state\n";
  engine::write_state(out, checkpoint.state);
  std::string bytes = out.str();
  bytes += std::string(kChecksumPrefix) + hex(engine::fingerprint(bytes)) + "\n";
  write_file_atomically(path, bytes);
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  try {
    std::string bytes = read_file(path);
    if (bytes.rfind(kFormat1Magic, 0) == 0) {
      throw std::runtime_error(
          "written by an older rodsort (format 1, without a checksum); "
          "resume it with that version, or start the run again");
    }
    if (bytes.rfind(kFormat2Magic, 0) == 0) {
      throw std::runtime_error(
          "written by an older rodsort (format 2, without the rods' contacts, which a run needs "
          "to continue exactly); resume it with that version, or start the run again");
    }
    if (bytes.rfind(kMagic, 0) != 0) throw std::runtime_error("not a checkpoint");
    const std::size_t body = bytes.size() >= kChecksumLine ? bytes.size() - kChecksumLine : 0;
    const std::string_view trailer = std::string_view(bytes).substr(body);
    if (trailer.size() != kChecksumLine ||
        trailer.substr(0, kChecksumPrefix.size()) != kChecksumPrefix) {
      throw std::runtime_error("cut short: its closing checksum line is missing");
    }
    const std::string recorded(trailer.substr(kChecksumPrefix.size(), 16));
    const std::string actual = hex(engine::fingerprint(std::string_view(bytes).substr(0, body)));
    if (recorded != actual) {
      throw std::runtime_error("its checksum does not match its content (" + actual +
                               ", recorded " + recorded +
                               "): the file was changed or damaged after it was written, and "
                               "resuming from it would not continue the run");
    }
    bytes.resize(body);
    std::istringstream in(bytes, std::ios::binary);
    std::string line;
    std::getline(in, line);
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
      } else if (key.rfind(kFileFramesPrefix, 0) == 0) {
        checkpoint.file_frames[key.substr(std::string(kFileFramesPrefix).size())] =
            parse_unsigned(value, key);
      } else if (key == "wall_s") {
        checkpoint.wall_s = parse_double(value, key);
      } else if (key == "cpu_s") {
        checkpoint.cpu_s = parse_double(value, key);
      } else if (key == "sessions") {
        checkpoint.sessions = static_cast<int>(parse_unsigned(value, key));
      } else if (key == "metrics_replay_offset") {
        checkpoint.metrics_replay_offset = parse_unsigned(value, key);
      } else if (key == "scenario_fingerprint") {
        checkpoint.scenario_fingerprint = parse_hex(value, key);
      } else if (key == "build") {
        checkpoint.build = value;
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

bool written_by_another_build(const Checkpoint& checkpoint, const std::filesystem::path& directory,
                              bool any_build) {
  if (checkpoint.build == build_identity()) return false;
  if (!any_build) {
    const std::string written_by =
        checkpoint.build.empty() ? "a build that did not record itself" : checkpoint.build;
    throw std::runtime_error("the checkpoint in " + directory.string() +
                             " was written by another build of rodsort (" + written_by +
                             ") than this one (" + build_identity() +
                             "); a run continues bit for bit only with the build that started "
                             "it: resume it with that build, or pass --any-build to continue it "
                             "with this one");
  }
  return true;
}

}  // namespace rodsort::runner
