#pragma once
// checkpoint.bin: everything needed to continue a run exactly where it stopped. The engine's State
// carries the physics; beside it the checkpoint records how long each growing output file was at
// that instant, so that a resumed run cuts them back and they stay consistent with the state even
// if the run wrote more frames before it was killed. Written atomically, so a crash while writing
// one leaves the previous checkpoint.
//
// Layout: a text header of "key value" lines opened by "rodsort-checkpoint 3" and closed by a line
// "state", followed by engine::write_state's bytes, and a last line "checksum <16 hex digits>", the
// fingerprint of everything before it: a checkpoint changed or damaged after it was written is
// refused. The header also records the fingerprint of scenario.resolved.yaml as the run wrote it,
// so that a resumed run can refuse an edited scenario, and the build of rodsort that wrote it, so
// that a run is not continued by another build without being asked to.

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include "engine/state.hpp"

namespace rodsort::runner {

struct Checkpoint {
  engine::State state;
  std::map<std::string, std::uint64_t> file_bytes;  ///< output file name -> its size at the state
  /// Output files of frames (rods.h5) -> the frames they held at the state.
  std::map<std::string, std::uint64_t> file_frames;
  double wall_s = 0.0;  ///< wall-clock seconds spent on the run up to the state, over all sessions
  double cpu_s = 0.0;   ///< CPU seconds spent on the run up to the state, over all sessions
  int sessions = 1;     ///< processes that have worked on the run so far
  std::string started_at;  ///< UTC, ISO 8601, when the first session started
  /// Where the metrics observer must start seeing frames again on resume, so that the frames from
  /// there on cover its window: a byte offset in rods.csv, or a frame's index in rods.h5 when the
  /// run writes no rods.csv.
  std::uint64_t metrics_replay_offset = 0;
  /// engine::fingerprint of scenario.resolved.yaml as the run wrote it.
  std::uint64_t scenario_fingerprint = 0;
  /// runner::build_identity() of the program that wrote the checkpoint; empty when not recorded.
  std::string build;
};

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);
/// Throws std::runtime_error naming the file when it is missing, truncated, changed after it was
/// written (its checksum), or not a checkpoint.
Checkpoint read_checkpoint(const std::filesystem::path& path);

/// Whether `checkpoint` (of the run in `directory`) was written by another build than this one.
/// Throws std::runtime_error naming both builds when it was and `any_build` is false: a run
/// continues bit for bit only with the build that started it.
bool written_by_another_build(const Checkpoint& checkpoint, const std::filesystem::path& directory,
                              bool any_build);

}  // namespace rodsort::runner
