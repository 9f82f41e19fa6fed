#include "runner/run.hpp"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <csignal>
#include <cstring>
#include <deque>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "engine/fingerprint.hpp"
#include "engine/simulation.hpp"
#include "metrics/rods_csv.hpp"
#include "metrics/rods_h5md.hpp"
#include "runner/append_file.hpp"
#include "runner/atomic_file.hpp"
#include "runner/checkpoint.hpp"
#include "runner/clocks.hpp"
#include "runner/cost_estimate.hpp"
#include "runner/exit_code.hpp"
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

/// The time of the first line of a rods.csv chunk (its first field).
double leading_time(std::string_view line) {
  double time = 0.0;
  std::from_chars(line.data(), line.data() + line.size(), time);
  return time;
}

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
        rounding_(plan.h5md_precision, plan.model.box_x, plan.model.box_y) {}

  int start() {
    write_file_atomically(directory_ / kResolvedScenarioFile, plan_.resolved_yaml);
    open_files();
    if (rods_) rods_->append(std::string(metrics::kRodsCsvHeader) + "\n");
    if (plan_.rods_h5md) {
      h5md_ = std::make_unique<metrics::RodsH5mdWriter>(directory_ / kRodsH5mdFile, h5md_layout());
    }
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

  int resume() {
    const Checkpoint checkpoint = read_checkpoint(directory_ / kCheckpointFile);
    const std::filesystem::path resolved = directory_ / kResolvedScenarioFile;
    const bool extended = options_.extended_from_fingerprint &&
                          *options_.extended_from_fingerprint == checkpoint.scenario_fingerprint;
    if (!extended && engine::fingerprint(read_file(resolved)) != checkpoint.scenario_fingerprint) {
      throw std::runtime_error(
          resolved.string() +
          " has changed since the run wrote it (its fingerprint differs from the one in " +
          kCheckpointFile +
          "); a run resumes only with the scenario it started with: restore the file, or start "
          "a new run from the edited scenario");
    }
    if (checkpoint.build != build_identity()) {
      const std::string written_by =
          checkpoint.build.empty() ? "a build that did not record itself" : checkpoint.build;
      if (!options_.any_build) {
        throw std::runtime_error(
            "the checkpoint in " + directory_.string() +
            " was written by another build of rodsort (" + written_by + ") than this one (" +
            build_identity() +
            "); a run continues bit for bit only with the build that started it: resume it with "
            "that build, or pass --any-build to continue it with this one");
      }
      log("rodsort: continuing with this build (%s) a run written by another (%s)\n",
          build_identity().c_str(), written_by.c_str());
    }
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
    std::uint64_t h5md_frames = 0;
    if (plan_.rods_h5md) {
      const auto recorded = checkpoint.file_frames.find(kRodsH5mdFile);
      if (recorded == checkpoint.file_frames.end()) {
        throw std::runtime_error("the checkpoint in " + directory_.string() +
                                 " records no frame count for " + kRodsH5mdFile);
      }
      h5md_frames = recorded->second;
    }
    simulation_.restore(checkpoint.state);
    prior_wall_s_ = checkpoint.wall_s;
    prior_cpu_s_ = checkpoint.cpu_s;
    sessions_ = checkpoint.sessions + 1;
    started_at_ = checkpoint.started_at;
    replay_metrics(checkpoint.metrics_replay_offset, h5md_frames);
    if (plan_.rods_h5md) {
      // Opened after the replay, which reads the file on its own.
      h5md_ = std::make_unique<metrics::RodsH5mdWriter>(directory_ / kRodsH5mdFile, h5md_layout(),
                                                        h5md_frames);
    }
    begin_session(true);
    log("rodsort: resuming %s at t = %g s of %g s in %s\n", plan_.name.c_str(), simulation_.time(),
        plan_.duration_s, directory_.c_str());
    write_record(RunStatus::kRunning, "");
    return loop();
  }

  /// Records a failure in run.json, if the directory can still be written.
  void record_failure(const std::string& message) noexcept {
    try {
      write_record(RunStatus::kFailed, message);
    } catch (...) {
      // The original failure is the one to report.
    }
  }

 private:
  struct FrameOffset {
    double time_s;
    std::uint64_t offset;  ///< in rods.csv [bytes], or in rods.h5 [frames] without rods.csv
  };

  metrics::H5mdLayout h5md_layout() const {
    metrics::H5mdLayout layout;
    layout.species_names = plan_.metrics.species_names;
    for (const engine::RodInit& rod : plan_.model.rods) layout.rod_species.push_back(rod.species);
    layout.box_x = plan_.model.box_x;
    layout.box_y = plan_.model.box_y;
    layout.box_z = plan_.model.drive.gap;
    layout.walls = plan_.model.walls;
    layout.scenario_yaml = plan_.resolved_yaml;
    layout.precision = plan_.h5md_precision;
    layout.creator_version = version();
    return layout;
  }

  /// The file the frames are read back from (rods.csv when the run writes it).
  const char* frames_file() const { return plan_.rods_csv ? kRodsCsvFile : kRodsH5mdFile; }

  void open_files() {
    if (plan_.rods_csv) rods_ = std::make_unique<AppendFile>(directory_ / kRodsCsvFile);
    metrics_ = std::make_unique<AppendFile>(directory_ / kMetricsCsvFile);
    if (schedule_.trajectory_steps > 0) {
      trajectory_ = std::make_unique<AppendFile>(directory_ / kTrajectoryFile);
    }
  }

  std::vector<AppendFile*> files() const {
    std::vector<AppendFile*> open = {metrics_.get()};
    if (rods_) open.push_back(rods_.get());
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
    if (h5md_) h5md_->commit();
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

  /// Writes a frame to rods.csv and rods.h5, and feeds the metrics observer the frame as the first
  /// of them holds it, so that `rodsort analyze` computes the same rows from that file.
  void write_frame(const engine::Frame& frame, std::int64_t step) {
    std::optional<metrics::MetricsRow> row;
    if (h5md_) {
      const std::uint64_t index = h5md_->frames();
      h5md_->write(frame, step);
      if (!rods_) {
        const engine::Frame stored = rounding_.stored(frame);
        remember_frame(stored.time, index);
        row = observer_.observe(stored);
      }
    }
    if (rods_) row = write_csv_frame(frame);
    if (row) metrics_->append(observer_.csv_line(*row) + "\n");
  }

  std::optional<metrics::MetricsRow> write_csv_frame(const engine::Frame& frame) {
    frame_text_.str("");
    metrics::RodsCsvWriter writer(frame_text_, plan_.metrics.species_names);
    writer.write(frame);
    const std::string text = frame_text_.str();
    const std::uint64_t offset = rods_->size();
    rods_->append(text);
    return observe_stored(text, offset);
  }

  /// Feeds the observer one frame as rods.csv holds it, and remembers where the frame starts.
  /// `first_line`: the line of rods.csv where the frame starts, for messages (0: not known).
  std::optional<metrics::MetricsRow> observe_stored(const std::string& frame_text,
                                                    std::uint64_t offset, long first_line = 0) {
    std::istringstream in(std::string(metrics::kRodsCsvHeader) + "\n" + frame_text);
    metrics::RodsCsvReader reader(in, kRodsCsvFile, plan_.metrics.species_names,
                                  first_line > 0 ? first_line - 1 : 1);
    engine::Frame stored;
    if (!reader.next(stored)) {
      throw std::runtime_error("cannot read back a frame of rods.csv: " + reader.error());
    }
    remember_frame(stored.time, offset);
    return observer_.observe(stored);
  }

  void remember_frame(double time_s, std::uint64_t offset) {
    recent_frames_.push_back({time_s, offset});
    // Keep the latest frame at least one window and one frame older than the newest: a resumed
    // observer fed the frames from there on has every frame it would have kept.
    const double keep_after_s = time_s - plan_.metrics.window - plan_.frame_interval_s;
    while (recent_frames_.size() >= 2 && recent_frames_[1].time_s <= keep_after_s) {
      recent_frames_.pop_front();
    }
  }

  /// Refills the metrics observer from rods.csv (from byte `offset` to the end) or, without it,
  /// from rods.h5 (frames `offset` to `h5md_frames`), without writing rows (metrics.csv already
  /// has them).
  void replay_metrics(std::uint64_t offset, std::uint64_t h5md_frames) {
    if (!rods_) {
      const std::filesystem::path path = directory_ / kRodsH5mdFile;
      metrics::RodsH5mdReader reader(path, plan_.metrics.species_names);
      if (!reader.error().empty()) {
        throw std::runtime_error("cannot read back rods.h5: " + reader.error());
      }
      if (offset > h5md_frames || h5md_frames > reader.frame_count()) {
        throw std::runtime_error("the checkpoint points past the end of " + path.string());
      }
      reader.seek(offset);
      engine::Frame stored;
      for (std::uint64_t index = offset; index < h5md_frames && reader.next(stored); ++index) {
        remember_frame(stored.time, index);
        observer_.observe(stored);
      }
      if (!reader.error().empty()) {
        throw std::runtime_error("cannot read back rods.h5: " + reader.error());
      }
      return;
    }
    const std::string text = read_file(rods_->path());
    if (offset > text.size()) {
      throw std::runtime_error("the checkpoint points past the end of " + rods_->path().string());
    }
    std::size_t frame_start = offset;
    double frame_time = 0.0;
    // Line numbers of the file, for messages about a damaged frame.
    long line = 1 + static_cast<long>(std::count(text.begin(), text.begin() + offset, '\n'));
    long frame_line = line;
    for (std::size_t line_start = offset; line_start < text.size(); ++line) {
      std::size_t line_end = text.find('\n', line_start);
      line_end = line_end == std::string::npos ? text.size() : line_end + 1;
      const double time = leading_time(std::string_view(text).substr(line_start));
      if (line_start == frame_start) {
        frame_time = time;
      } else if (time != frame_time) {
        observe_stored(text.substr(frame_start, line_start - frame_start), frame_start, frame_line);
        frame_start = line_start;
        frame_line = line;
        frame_time = time;
      }
      line_start = line_end;
    }
    if (frame_start < text.size()) {
      observe_stored(text.substr(frame_start), frame_start, frame_line);
    }
  }

  void write_checkpoint_now() {
    for (AppendFile* file : files()) file->sync();
    if (h5md_) h5md_->commit();
    Checkpoint checkpoint;
    checkpoint.state = simulation_.state();
    for (AppendFile* file : files()) {
      checkpoint.file_bytes[file->path().filename().string()] = file->size();
    }
    if (h5md_) checkpoint.file_frames[kRodsH5mdFile] = h5md_->frames();
    checkpoint.wall_s = total_wall_s();
    checkpoint.cpu_s = total_cpu_s();
    checkpoint.sessions = sessions_;
    checkpoint.started_at = started_at_;
    checkpoint.scenario_fingerprint = engine::fingerprint(plan_.resolved_yaml);
    checkpoint.build = build_identity();
    checkpoint.metrics_replay_offset = !recent_frames_.empty() ? recent_frames_.front().offset
                                       : rods_                 ? rods_->size()
                                                               : h5md_->frames();
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
  metrics::H5mdRounding rounding_;
  std::unique_ptr<AppendFile> rods_, metrics_, trajectory_;
  std::unique_ptr<metrics::RodsH5mdWriter> h5md_;
  std::ostringstream frame_text_;
  std::deque<FrameOffset> recent_frames_;
  std::size_t next_snapshot_ = 0;
  std::int64_t last_checkpoint_step_ = -1;
  double prior_wall_s_ = 0.0, prior_cpu_s_ = 0.0;  ///< spent by earlier sessions
  double session_wall0_s_ = 0.0, session_cpu0_s_ = 0.0, session_start_sim_s_ = 0.0;
  int sessions_ = 1;
  std::string started_at_;
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
                 const RunOptions& options) {
  RunSession session(plan, directory, options);
  return guarded(session, [&] { return session.resume(); });
}

}  // namespace rodsort::runner
