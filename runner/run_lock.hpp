#pragma once
// One process at a time in a run directory. A run holds an exclusive lock on DIR/run.lock for as
// long as it writes there, so that a second `rodsort run --resume DIR` (or the same sweep started
// twice) is refused instead of interleaving frames. The kernel drops the lock when the process
// ends, however it ends, so a killed run never leaves a stale lock behind.

#include <filesystem>
#include <optional>

namespace rodsort::runner {

inline constexpr const char* kRunLockFile = "run.lock";

class RunLock {
 public:
  /// Takes the lock of `directory` (which must exist); nullopt when another process holds it.
  /// Throws std::runtime_error when the lock file cannot be created.
  static std::optional<RunLock> acquire(const std::filesystem::path& directory);
  /// Whether a process holds the lock of `directory` now (a run is writing there). Creates
  /// nothing; takes a shared lock for an instant, so a run starting at that very instant may be
  /// refused as if another held it.
  static bool held(const std::filesystem::path& directory);

  RunLock(RunLock&& other) noexcept;
  RunLock& operator=(RunLock&& other) noexcept;
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;
  ~RunLock();

 private:
  explicit RunLock(int fd) : fd_(fd) {}
  int fd_ = -1;
};

}  // namespace rodsort::runner
