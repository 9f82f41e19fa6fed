#pragma once
// Scenario and sweep files are both YAML; a user who hands one to the other's command gets a page
// of unknown keys. This tells which of the two a file looks like, for a hint after those errors.

#include <filesystem>

namespace rodsort::runner {

enum class FileKind { kScenario, kSweep, kUnknown };

/// kSweep when the file's top level has `grid` or `base`, kScenario when it has scenario keys
/// (species, trap, run, ...), kUnknown when it cannot be read or says neither.
FileKind guess_file_kind(const std::filesystem::path& path);

}  // namespace rodsort::runner
