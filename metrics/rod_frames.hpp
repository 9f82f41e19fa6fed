#pragma once
// The frames of a run, read back from whichever file holds them: rods.csv or rods.h5.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/frame.hpp"

namespace rodsort::metrics {

inline constexpr const char* kRodsCsvName = "rods.csv";
inline constexpr const char* kRodsH5mdName = "rods.h5";

/// A run's frames, one after the other.
class RodFrameReader {
 public:
  virtual ~RodFrameReader() = default;
  /// The next frame; false at the end or at the first error (see error()).
  virtual bool next(engine::Frame& frame) = 0;
  /// "file[:line:col]: what was found, what was expected", or empty.
  virtual const std::string& error() const = 0;
  /// Set when incomplete frames at the end (a run stopped while writing) were dropped.
  virtual const std::string& warning() const = 0;
  virtual const std::vector<std::string>& species() const = 0;
};

/// The file of a run directory that the run's metrics were computed from: rods.csv when the run
/// wrote it, rods.h5 otherwise; empty when it has neither.
std::filesystem::path rod_frames_file(const std::filesystem::path& run_directory);

/// Opens rods.csv or rods.h5 (by the file's name). Throws std::runtime_error naming the file when
/// it cannot be opened.
std::unique_ptr<RodFrameReader> open_rod_frames(const std::filesystem::path& file,
                                                std::vector<std::string> species_names = {});

}  // namespace rodsort::metrics
