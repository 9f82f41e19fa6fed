#pragma once
// The files a run appends its frames to, one frame at a time: rods.csv and rods.h5. Each knows how
// to write a frame, what a checkpoint records of it, how to cut itself back to that instant when
// the run resumes, and how to give back the frames it holds: the run's metrics are computed from
// the frames as the first of its files holds them, so that `rodsort analyze` gives them back
// exactly. A new format of frames is one more FrameFile, made by make_frame_files(); the run loop
// does not change.

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <vector>

#include "engine/frame.hpp"
#include "metrics/rods_h5md.hpp"
#include "runner/checkpoint.hpp"
#include "runner/run_plan.hpp"

namespace rodsort::runner {

class FrameFile {
 public:
  /// Called with a frame as the file holds it, and the position where it starts in the file.
  using Visit = std::function<void(const engine::Frame& stored, std::uint64_t position)>;

  virtual ~FrameFile() = default;
  /// Starts the file of a new run, replacing one there.
  virtual void start() = 0;
  /// Opens the file of a stopped run and cuts it back to the instant of `checkpoint`; first, when
  /// `visit` is given, visits the frames from position `replay_from` to that instant.
  virtual void resume(const Checkpoint& checkpoint, std::uint64_t replay_from,
                      const Visit& visit) = 0;
  /// Appends a frame taken at `step`; returns the frame as the file holds it.
  virtual engine::Frame write(const engine::Frame& frame, std::int64_t step) = 0;
  /// Where the next frame will start: what resume() takes as `replay_from`.
  virtual std::uint64_t position() const = 0;
  /// Makes what was written durable, and records in `checkpoint` how far the file goes.
  virtual void record(Checkpoint& checkpoint) = 0;
  /// Makes what was written durable (at the end of a run).
  virtual void sync() = 0;
  /// The file's name in the run directory.
  virtual const char* name() const = 0;
};

/// What rods.h5 records of a run besides its frames (species, box, walls, scenario).
metrics::H5mdLayout h5md_layout(const RunPlan& plan);

/// The run's files of frames, in the order of output.rods_format (rods.csv first when written).
std::vector<std::unique_ptr<FrameFile>> make_frame_files(const RunPlan& plan,
                                                         const std::filesystem::path& directory);

}  // namespace rodsort::runner
