#include "runner/run.hpp"

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <deque>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "engine/fingerprint.hpp"
#include "engine/simulation.hpp"
#include "runner/append_file.hpp"
#include "runner/atomic_file.hpp"
#include "runner/checkpoint.hpp"
#include "runner/clocks.hpp"
#include "runner/cost_estimate.hpp"
#include "runner/exit_code.hpp"
#include "runner/frame_file.hpp"
#include "runner/interrupt.hpp"
#include "runner/lammps_dump.hpp"
#include "runner/progress.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_record.hpp"
#include "runner/run_summary.hpp"
#include "runner/version.hpp"

namespace rodsort::runner {
namespace {

/// Progress is looked at every this many steps: often enough for a live line, rarely enough that
/// reading the clocks costs nothing next to a step.
constexpr std::int64_t kProgressEverySteps = 16;

class RunSession {
 public:
  RunSession(const RunPlan& plan, std::filesystem::path directory, const RunOptions& options)
      : plan_(plan),
        directory_(std::move(directory)),
        options_(options),
        schedule_(plan.schedule),
        simulation_(plan.model),
        observer_(plan.metrics),
        // The base's top surface moves within [-A, A] and the lid's bottom within w + [-A, A].
        dump_(plan.model, -plan.model.drive.amplitude,
              plan.model.drive.gap + plan.model.drive.amplitude, plan.dump_style),
        frame_files_(make_frame_files(plan, directory_)) {}

  int start() {
    write_file_atomically(directory_ / kResolvedScenarioFile, plan_.resolved_yaml);
    open_files();
    for (const auto& frames : frame_files_) frames->start();
    metrics_->append(observer_.csv_header() + "\n");
    if (schedule_.trajectory_steps > 0 && !plan_.model.walls.empty()) {
      write_file_atomically(directory_ / kWallsDumpFile, dump_.walls(plan_.model));
    }
    started_at_ = utc_now_iso8601();
    begin_session(false);
    log("rodsort: running %s (%zu rods, %g s simulated) into %s; %s (docs/performance.md)\n",
        plan_.name.c_str(), plan_.model.rods.size(), plan_.duration_s, directory_.c_str(),
        describe_cost(estimate_cost(plan_.model, plan_.schedule.total_steps)).c_str());
    handle_events(0);
    write_checkpoint_now();
    return loop();
  }

  int resume(const Checkpoint& checkpoint) {
    // A failure before the state is restored leaves the run as it was, run.json included.
    record_failures_ = false;
    if (checkpoint.build != build_identity()) {
      log("rodsort: continuing with this build (%s) a run written by another (%s)\n",
          build_identity().c_str(),
          checkpoint.build.empty() ? "one that did not record itself" : checkpoint.build.c_str());
    }
    check_metrics_columns(checkpoint);
    simulation_.restore(checkpoint.state);
    prior_wall_s_ = checkpoint.wall_s;
    prior_cpu_s_ = checkpoint.cpu_s;
    sessions_ = checkpoint.sessions + 1;
    started_at_ = checkpoint.started_at;
    record_failures_ = true;
    open_files();
    for (AppendFile* file : files()) {
      const std::string name = file->path().filename().string();
      const auto recorded = checkpoint.file_bytes.find(name);
      if (recorded == checkpoint.file_bytes.end()) {
        throw std::runtime_error("the checkpoint in " + directory_.string() +
                                 " records no size for " + name);
      }
      file->truncate(recorded->second);
    }
    // The metrics observer sees again the frames of its window, as the first file holds them;
    // metrics.csv already has their rows.
    const FrameFile::Visit refill = [this](const engine::Frame& stored, std::uint64_t position) {
      remember_frame(stored.time, position);
      observer_.observe(stored);
    };
    for (std::size_t f = 0; f < frame_files_.size(); ++f) {
      frame_files_[f]->resume(checkpoint, checkpoint.metrics_replay_offset,
                              f == 0 ? refill : FrameFile::Visit());
    }
    begin_session(true);
    const RemainingCost left = remaining_cost(plan_.model, simulation_.step_count(),
                                              plan_.schedule.total_steps, prior_cpu_s_);
    const std::string left_text =
        describe_cost(left.cost) +
        (left.own_rate ? " left, at its own rate so far" : " left (docs/performance.md)");
    log("rodsort: resuming %s at t = %g s of %g s in %s; %s\n", plan_.name.c_str(),
        simulation_.time(), plan_.duration_s, directory_.c_str(), left_text.c_str());
    write_record(RunStatus::kRunning, "");
    return loop();
  }

  /// Records a failure in run.json, if the directory can still be written and the failure did
  /// not come before a resume had restored the run's state.
  void record_failure(const std::string& message) noexcept {
    if (!record_failures_) return;
    try {
      write_record(RunStatus::kFailed, message);
    } catch (...) {
      // The original failure is the one to report.
    }
  }

 private:
  struct FrameOffset {
    double time_s;
    std::uint64_t position;  ///< in the first file of frames (FrameFile::position())
  };

  /// A run's metrics.csv takes rows of the columns its header names; a build that writes other
  /// columns (a newer one, with more measures) cannot continue it.
  void check_metrics_columns(const Checkpoint& checkpoint) const {
    if (metrics_csv_header(directory_) == observer_.csv_header()) return;
    throw std::runtime_error(
        (directory_ / kMetricsCsvFile).string() + " has other columns than this build writes (" +
        observer_.csv_header() + "): continue the run with the build that wrote it (" +
        (checkpoint.build.empty() ? std::string("an older one") : checkpoint.build) +
        "), then `rodsort analyze` it to add this build's columns");
  }

  /// The file the frames are read back from (rods.csv when the run writes it).
  const char* frames_file() const { return frame_files_.front()->name(); }

  void open_files() {
    metrics_ = std::make_unique<AppendFile>(directory_ / kMetricsCsvFile);
    if (schedule_.trajectory_steps > 0) {
      trajectory_ = std::make_unique<AppendFile>(directory_ / kTrajectoryFile);
    }
  }

  std::vector<AppendFile*> files() const {
    std::vector<AppendFile*> open = {metrics_.get()};
    if (trajectory_) open.push_back(trajectory_.get());
    return open;
  }

  /// Starts the clocks of this process's part of the run. Resuming, the events of the
  /// checkpoint's own step were handled before it was written.
  void begin_session(bool resuming) {
    session_wall0_s_ = wall_seconds();
    session_cpu0_s_ = process_cpu_seconds();
    session_start_sim_s_ = simulation_.time();
    const std::int64_t step = simulation_.step_count();
    next_snapshot_ = 0;
    while (next_snapshot_ < schedule_.snapshots.size() &&
           (schedule_.snapshots[next_snapshot_].step < step ||
            (resuming && schedule_.snapshots[next_snapshot_].step == step))) {
      ++next_snapshot_;
    }
  }

  int loop() {
    const InterruptGuard guard;
    const bool terminal = options_.log != nullptr && isatty(fileno(options_.log));
    std::optional<ProgressReporter> progress;
    if (options_.show_progress && options_.log != nullptr) progress.emplace(options_.log, terminal);
    bool stop_announced = false;
    while (simulation_.step_count() < schedule_.total_steps) {
      step_or_explain();
      const std::int64_t step = simulation_.step_count();
      handle_events(step);
      if (options_.after_step) options_.after_step(step);
      if (const int signal_number = InterruptGuard::received(); signal_number != 0) {
        // Stop where a checkpoint continues the run exactly: at a frame (see run.hpp).
        if (schedule_.is_frame(step)) return stop_on_signal(signal_number, progress);
        if (!stop_announced) {
          log("%srodsort: got SIG%s; stopping at the next frame, t = %g s\n",
              progress && terminal ? "\n" : "", sigabbrev_np(signal_number),
              plan_.model.dt *
                  static_cast<double>((step / schedule_.frame_steps + 1) * schedule_.frame_steps));
          stop_announced = true;
        }
      }
      if (progress && step % kProgressEverySteps == 0) progress->update(sample());
    }
    if (last_checkpoint_step_ != simulation_.step_count()) write_checkpoint_now();
    write_end_frame();
    write_record(RunStatus::kComplete, "");
    if (progress) progress->finish(sample());
    const double simulated_s = simulation_.time() - session_start_sim_s_;
    log("rodsort: complete: %s in %s, %.3g CPU-s per simulated s; deepest contact %.3g mm\n",
        directory_.c_str(), format_duration(total_wall_s()).c_str(),
        simulated_s > 0.0 ? (process_cpu_seconds() - session_cpu0_s_) / simulated_s : 0.0,
        simulation_.counters().deepest_overlap);
    if (plan_.metrics.trap_area > 0.0) {
      const RunSummary summary = summarize_run(directory_);
      log("rodsort: trapping efficiency eta, mean over the last half: %.3g (spread %.2g); every "
          "frame in %s\n",
          summary.plateau_mean(), summary.eta_spread, (directory_ / kMetricsCsvFile).c_str());
    }
    return kExitOk;
  }

  /// A step; when the model breaks down (engine::Simulation::step), the error says what of the
  /// run is left to look at.
  void step_or_explain() {
    try {
      simulation_.step();
    } catch (const std::runtime_error& error) {
      char where[160];
      std::snprintf(where, sizeof where, "; the last checkpoint, at t = %g s, is kept",
                    plan_.model.dt * static_cast<double>(last_checkpoint_step_));
      throw std::runtime_error(std::string(error.what()) + where + ", and " + frames_file() +
                               " holds the frames before the breakdown (rodsort render " +
                               directory_.string() + ")");
    }
  }

  /// A run whose duration is not a whole number of frame (or trajectory) intervals ends with one
  /// more frame, at its last step, so that a 40 s run ends at t = 40 s. It comes after the final
  /// checkpoint, which therefore does not count it: a run continued to a longer duration cuts it
  /// off and goes on exactly as a run started with that duration, which has no frame there.
  void write_end_frame() {
    const std::int64_t step = simulation_.step_count();
    const bool frame_due = !schedule_.is_frame(step);
    const bool trajectory_due = trajectory_ && !schedule_.is_trajectory(step);
    if (!frame_due && !trajectory_due) return;
    const engine::Frame frame = simulation_.frame();
    if (frame_due) write_frame(frame, step);
    if (trajectory_due) trajectory_->append(dump_.format(frame, step));
    for (AppendFile* file : files()) file->sync();
    for (const auto& frames : frame_files_) frames->sync();
  }

  int stop_on_signal(int signal_number, std::optional<ProgressReporter>& progress) {
    if (last_checkpoint_step_ != simulation_.step_count()) write_checkpoint_now();
    char message[96];
    std::snprintf(message, sizeof message, "stopped by SIG%s at t = %g s",
                  sigabbrev_np(signal_number), simulation_.time());
    write_record(RunStatus::kInterrupted, message);
    if (progress) progress->finish(sample());
    log("rodsort: %s; checkpoint written. Continue with: rodsort run --resume %s\n", message,
        directory_.c_str());
    return kExitInterrupted;
  }

  void handle_events(std::int64_t step) {
    const bool frame_due = schedule_.is_frame(step);
    const bool trajectory_due = schedule_.is_trajectory(step);
    if (frame_due || trajectory_due) {
      const engine::Frame frame = simulation_.frame();
      if (frame_due) write_frame(frame, step);
      if (trajectory_due) trajectory_->append(dump_.format(frame, step));
    }
    while (next_snapshot_ < schedule_.snapshots.size() &&
           schedule_.snapshots[next_snapshot_].step == step) {
      simulation_.write_bullet_snapshot(
          directory_ / snapshot_file_name(schedule_.snapshots[next_snapshot_].time_s));
      ++next_snapshot_;
    }
    if (schedule_.is_checkpoint(step)) write_checkpoint_now();
  }

  /// Writes a frame to every file of frames, and feeds the metrics observer the frame as the
  /// first of them holds it, so that `rodsort analyze` computes the same rows from that file.
  void write_frame(const engine::Frame& frame, std::int64_t step) {
    const std::uint64_t position = frame_files_.front()->position();
    const engine::Frame stored = frame_files_.front()->write(frame, step);
    for (std::size_t f = 1; f < frame_files_.size(); ++f) frame_files_[f]->write(frame, step);
    remember_frame(stored.time, position);
    if (const auto row = observer_.observe(stored)) {
      metrics_->append(observer_.csv_line(*row) + "\n");
    }
  }

  void remember_frame(double time_s, std::uint64_t position) {
    recent_frames_.push_back({time_s, position});
    // Keep the latest frame at least the observer's history (its window, or the held count's
    // lag) and one frame older than the newest: a resumed observer fed the frames from there on
    // has every frame it would have kept.
    const double keep_after_s = time_s - observer_.history() - plan_.frame_interval_s;
    while (recent_frames_.size() >= 2 && recent_frames_[1].time_s <= keep_after_s) {
      recent_frames_.pop_front();
    }
  }

  void write_checkpoint_now() {
    for (AppendFile* file : files()) file->sync();
    Checkpoint checkpoint;
    checkpoint.state = simulation_.state();
    for (AppendFile* file : files()) {
      checkpoint.file_bytes[file->path().filename().string()] = file->size();
    }
    for (const auto& frames : frame_files_) frames->record(checkpoint);
    checkpoint.wall_s = total_wall_s();
    checkpoint.cpu_s = total_cpu_s();
    checkpoint.sessions = sessions_;
    checkpoint.started_at = started_at_;
    checkpoint.scenario_fingerprint = engine::fingerprint(plan_.resolved_yaml);
    checkpoint.build = build_identity();
    checkpoint.metrics_replay_offset =
        recent_frames_.empty() ? frame_files_.front()->position() : recent_frames_.front().position;
    write_checkpoint(directory_ / kCheckpointFile, checkpoint);
    last_checkpoint_step_ = simulation_.step_count();
    write_record(RunStatus::kRunning, "");
  }

  void write_record(RunStatus status, const std::string& message) {
    RunRecord record;
    record.version = version();
    record.name = plan_.name;
    record.seed = plan_.model.seed;
    record.status = status;
    record.rods = static_cast<int>(plan_.model.rods.size());
    record.dt_s = plan_.model.dt;
    record.duration_s = plan_.duration_s;
    record.steps = simulation_.step_count();
    record.total_steps = schedule_.total_steps;
    record.simulated_s = simulation_.time();
    record.wall_s = total_wall_s();
    record.cpu_s = total_cpu_s();
    record.sessions = sessions_;
    record.started_at = started_at_;
    record.updated_at = utc_now_iso8601();
    record.message = message;
    write_run_record(directory_, record);
  }

  ProgressSample sample() const {
    ProgressSample sample;
    sample.simulated_s = simulation_.time();
    sample.duration_s = plan_.duration_s;
    sample.session_start_s = session_start_sim_s_;
    sample.session_wall_s = wall_seconds() - session_wall0_s_;
    sample.session_cpu_s = process_cpu_seconds() - session_cpu0_s_;
    return sample;
  }

  double total_wall_s() const { return prior_wall_s_ + wall_seconds() - session_wall0_s_; }
  double total_cpu_s() const { return prior_cpu_s_ + process_cpu_seconds() - session_cpu0_s_; }

  template <typename... Args>
  void log(const char* format, Args... args) const {
    if (options_.log == nullptr) return;
    std::fprintf(options_.log, format, args...);
    std::fflush(options_.log);
  }

  const RunPlan& plan_;
  std::filesystem::path directory_;
  RunOptions options_;
  RunSchedule schedule_;
  engine::Simulation simulation_;
  metrics::MetricsObserver observer_;
  LammpsDumpFormatter dump_;
  std::unique_ptr<AppendFile> metrics_, trajectory_;
  std::vector<std::unique_ptr<FrameFile>> frame_files_;  ///< the first feeds the metrics
  std::deque<FrameOffset> recent_frames_;
  std::size_t next_snapshot_ = 0;
  std::int64_t last_checkpoint_step_ = -1;
  double prior_wall_s_ = 0.0, prior_cpu_s_ = 0.0;  ///< spent by earlier sessions
  /// This process's clocks at its start; a session resets them when it begins to step.
  double session_wall0_s_ = wall_seconds(), session_cpu0_s_ = process_cpu_seconds();
  double session_start_sim_s_ = 0.0;
  int sessions_ = 1;
  std::string started_at_;
  bool record_failures_ = true;
};

template <typename Body>
int guarded(RunSession& session, Body body) {
  try {
    return body();
  } catch (const std::exception& error) {
    session.record_failure(error.what());
    throw;
  }
}

}  // namespace

int start_run(const RunPlan& plan, const std::filesystem::path& directory,
              const RunOptions& options) {
  std::filesystem::create_directories(directory);
  RunSession session(plan, directory, options);
  return guarded(session, [&] { return session.start(); });
}

int continue_run(const RunPlan& plan, const std::filesystem::path& directory,
                 const Checkpoint& checkpoint, const RunOptions& options) {
  RunSession session(plan, directory, options);
  return guarded(session, [&] { return session.resume(checkpoint); });
}

}  // namespace rodsort::runner
