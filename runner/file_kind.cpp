#include "runner/file_kind.hpp"

#include <array>
#include <optional>

#include "scenarios/source_node.hpp"

namespace rodsort::runner {

FileKind guess_file_kind(const std::filesystem::path& path) {
  // Its own errors are reported by whoever reads it properly; the same bounded reader keeps this
  // guess from hanging on a pipe or reading a device without end.
  scenarios::Diagnostics ignored;
  const std::optional<scenarios::SourceNode> root = scenarios::read_yaml_file(path, ignored);
  if (!root || !root->is_map()) return FileKind::kUnknown;
  if (root->find("grid") || root->find("base")) return FileKind::kSweep;
  constexpr std::array kScenarioKeys = {"species", "trap", "run", "box", "drive", "output"};
  for (const char* key : kScenarioKeys) {
    if (root->find(key)) return FileKind::kScenario;
  }
  return FileKind::kUnknown;
}

}  // namespace rodsort::runner
