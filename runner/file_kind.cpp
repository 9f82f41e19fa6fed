#include "runner/file_kind.hpp"

#include <yaml-cpp/yaml.h>

#include <array>

namespace rodsort::runner {

FileKind guess_file_kind(const std::filesystem::path& path) {
  try {
    const YAML::Node root = YAML::LoadFile(path.string());
    if (!root.IsMap()) return FileKind::kUnknown;
    if (root["grid"] || root["base"]) return FileKind::kSweep;
    constexpr std::array kScenarioKeys = {"species", "trap", "run", "box", "drive", "output"};
    for (const char* key : kScenarioKeys) {
      if (root[key]) return FileKind::kScenario;
    }
  } catch (const YAML::Exception&) {
    // Its own errors are reported by whoever reads it properly.
  }
  return FileKind::kUnknown;
}

}  // namespace rodsort::runner
