#pragma once
// When a run writes each of its outputs, counted in steps rather than seconds, so that a frame
// falls on the same step in an uninterrupted run and in a resumed one, and no rounding of
// accumulated time can skip or double a frame.

#include <cstdint>
#include <vector>

namespace rodsort::runner {

struct SnapshotTime {
  std::int64_t step;
  double time_s;  ///< as the scenario lists it, for the file name
};

struct RunSchedule {
  std::int64_t total_steps = 0;
  std::int64_t frame_steps = 1;         ///< rods.csv and metrics.csv
  std::int64_t trajectory_steps = 0;    ///< trajectory.dump; 0: none
  std::int64_t checkpoint_steps = 1;    ///< rounded up to the next frame
  std::vector<SnapshotTime> snapshots;  ///< ascending, within the run

  bool is_frame(std::int64_t step) const { return step % frame_steps == 0; }
  bool is_trajectory(std::int64_t step) const {
    return trajectory_steps > 0 && step % trajectory_steps == 0;
  }
  /// Checkpoints fall on frames: the first frame at or after each multiple of checkpoint_steps.
  bool is_checkpoint(std::int64_t step) const {
    return step > 0 && is_frame(step) &&
           step / checkpoint_steps != (step - frame_steps) / checkpoint_steps;
  }
};

}  // namespace rodsort::runner
