#pragma once
// The run loop: steps a Simulation built from a RunPlan and writes the run directory (DESIGN §4,
// docs/cli.md), checkpointing periodically and when SIGINT or SIGTERM arrives.
//
// Consistency after any stop. The growing files (rods.csv, metrics.csv, trajectory.dump) get one
// whole frame per write, so a run killed at any moment leaves whole lines. A checkpoint records
// the engine State and every file's size at that instant; resuming restores the State and cuts the
// files back to those sizes, so frames written after the checkpoint by a run that was then killed
// are written again, once. The metrics observer, which remembers the frames of the last window
// tau, is refilled by reading back the end of rods.csv.
//
// A resumed run is the same run, to the bit. Bullet keeps caches beyond engine::State (contact
// manifolds and their warm-start impulses, broadphase pair order) that a restored world starts
// without, so a world restored at a step continues differently, in its last digits and then
// chaotically, from the world it was taken from. The run therefore rebuilds its world from its own
// State at every frame (about 2 ms for 300 rods, against the ~0.8 s the 700 steps of a frame
// take), and stops and checkpoints only at frames: a run resumed from any checkpoint takes exactly
// the steps of one never stopped. A signal that arrives between frames is acted on at the next.
// (So changing output.frame_interval changes a trajectory in its details, not its statistics.)
//
// The live run feeds the metrics observer the frames as rods.csv stores them (9 significant
// digits), not the engine's full-precision ones, so that metrics.csv is the same whether it comes
// from a run, from a resumed run, or from `rodsort analyze` afterwards.

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iosfwd>

#include "runner/run_plan.hpp"

namespace rodsort::runner {

struct Checkpoint;

struct RunOptions {
  /// Where progress and messages go (nullptr: nowhere). A terminal gets a live line.
  std::FILE* log = stderr;
  bool show_progress = true;
  /// Called after every step once that step's outputs are written; tests use it to raise a signal
  /// or throw at a chosen step.
  std::function<void(std::int64_t step)> after_step;
  /// Resume a checkpoint written by another build of rodsort (runner::build_identity). The run then
  /// goes on with the same physics but not bit for bit as it would have with its own build.
  bool any_build = false;
};

/// Runs `plan` from the start into `directory`, which must not hold a run (the caller checks and
/// clears it). Returns kExitOk, kExitInterrupted (checkpoint written), or throws on failure after
/// recording it in run.json.
int start_run(const RunPlan& plan, const std::filesystem::path& directory,
              const RunOptions& options = {});

/// Continues the run in `directory` from `checkpoint`, read from it and checked by the caller
/// against the scenario the run started with and this build (resume_run_directory).
/// `plan` must be the one compiled from the directory's scenario.resolved.yaml.
int continue_run(const RunPlan& plan, const std::filesystem::path& directory,
                 const Checkpoint& checkpoint, const RunOptions& options = {});

}  // namespace rodsort::runner
