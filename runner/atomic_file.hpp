#pragma once
// Files that are replaced as a whole (checkpoints, run.json, sweep.csv) are written beside their
// final name and renamed over it, so that a run killed at any moment leaves either the old file or
// the new one, never half of one.

#include <filesystem>
#include <string_view>

namespace rodsort::runner {

/// Replaces `path` by `contents` atomically: temporary file, fsync, rename. Throws
/// std::runtime_error naming the file on failure.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

/// The whole content of a file. Throws std::runtime_error naming the file when it cannot be read.
std::string read_file(const std::filesystem::path& path);

}  // namespace rodsort::runner
