#pragma once
// The growing files of a run (rods.csv, metrics.csv, trajectory.dump) are appended one whole frame
// at a time with a single write, straight to the kernel: a run killed at any moment, even by
// SIGKILL, leaves complete lines. The byte size after each frame is what a checkpoint records, so
// that resuming can cut every file back to the same instant.

#include <cstdint>
#include <filesystem>
#include <string_view>

namespace rodsort::runner {

class AppendFile {
 public:
  /// Opens (creating if needed) for appending. Throws std::runtime_error naming the file.
  explicit AppendFile(std::filesystem::path path);
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  /// Appends `text` with as few system calls as the kernel allows (one for a regular file).
  void append(std::string_view text);
  /// Waits until what was appended is on disk, so that a checkpoint written next never records
  /// more than a power cut would leave.
  void sync();
  /// Cuts the file back to `bytes` (a size recorded earlier by size()).
  void truncate(std::uint64_t bytes);
  std::uint64_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

}  // namespace rodsort::runner
