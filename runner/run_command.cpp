#include "runner/run_command.hpp"

#include <cstdio>
#include <ostream>
#include <stdexcept>
#include <string>

#include "engine/fingerprint.hpp"
#include "runner/atomic_file.hpp"
#include "runner/checkpoint.hpp"
#include "runner/exit_code.hpp"
#include "runner/file_kind.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_lock.hpp"
#include "runner/run_plan.hpp"
#include "runner/run_record.hpp"
#include "scenarios/scenario.hpp"

namespace rodsort::runner {
namespace {

/// What a directory holding a run holds, for the message that refuses to overwrite it.
std::string describe_existing_run(const std::filesystem::path& directory) {
  try {
    if (const auto record = read_run_record(directory)) {
      return "a run of '" + record->name + "' (" + to_string(record->status) +
             " at t = " + std::to_string(record->simulated_s) + " s of " +
             std::to_string(record->duration_s) + " s)";
    }
  } catch (const std::exception&) {
    // An unreadable run.json still means the directory is taken.
  }
  return "the files of a run";
}

void hint_if_sweep(const std::filesystem::path& file, std::ostream& err) {
  if (guess_file_kind(file) == FileKind::kSweep) {
    err << "rodsort: " << file.string() << " looks like a sweep file: run it with `rodsort sweep "
        << file.string() << "` (add --dry-run to check its points)\n";
  }
}

}  // namespace

std::filesystem::path default_run_directory(const std::string& name) {
  return std::filesystem::path("runs") / name;
}

int run_scenario_file(const RunRequest& request, std::ostream& err) {
  const scenarios::LoadResult loaded =
      scenarios::load_scenario_with_options(request.scenario, request.set_options);
  err << scenarios::format_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) {
    err << "rodsort: " << request.scenario.string() << " refused; nothing was written\n";
    hint_if_sweep(request.scenario, err);
    return kExitUsage;
  }
  const scenarios::Scenario& scenario = *loaded.scenario;
  const std::filesystem::path directory =
      request.output.empty() ? default_run_directory(scenario.name) : request.output;
  if (std::filesystem::exists(directory) && !std::filesystem::is_directory(directory)) {
    err << "rodsort: " << directory.string() << " exists and is not a directory\n";
    return kExitUsage;
  }
  std::filesystem::create_directories(directory);
  const auto lock = RunLock::acquire(directory);
  if (!lock) {
    err << "rodsort: another process is running in " << directory.string() << '\n';
    return kExitFailure;
  }
  if (holds_run(directory)) {
    if (!request.force) {
      err << "rodsort: " << directory.string() << " already holds "
          << describe_existing_run(directory) << ".\n  Continue it with `rodsort run --resume "
          << directory.string() << "`, or start over with --force (its run files are replaced).\n";
      return kExitUsage;
    }
    clear_run(directory);
  }
  const RunPlan plan = make_run_plan(scenario);
  return start_run(plan, directory, request.options);
}

int resume_run_directory(const std::filesystem::path& directory, const RunOptions& options,
                         std::ostream& err, std::optional<double> duration) {
  if (!std::filesystem::is_directory(directory)) {
    err << "rodsort: " << directory.string() << " holds no run to resume (no such directory)\n";
    return kExitUsage;
  }
  // Checked before the lock is taken, so that a directory without a run is left as it was (the
  // lock would create run.lock in it), and again under the lock.
  const auto holds_resumable_run = [&] {
    return std::filesystem::exists(directory / kRunRecordFile) &&
           std::filesystem::exists(directory / kCheckpointFile);
  };
  if (!holds_resumable_run()) {
    err << "rodsort: " << directory.string()
        << " holds no run to resume (no run.json and checkpoint.bin)\n";
    return kExitUsage;
  }
  const auto lock = RunLock::acquire(directory);
  if (!lock) {
    err << "rodsort: another process is running in " << directory.string() << '\n';
    return kExitFailure;
  }
  const auto record = read_run_record(directory);
  if (!record || !holds_resumable_run()) {
    err << "rodsort: " << directory.string()
        << " holds no run to resume (no run.json and checkpoint.bin)\n";
    return kExitUsage;
  }
  if (record->status == RunStatus::kComplete && !duration) {
    err << "rodsort: " << directory.string() << " is already complete (t = " << record->simulated_s
        << " s); nothing to do (--duration T continues it to a later time)\n";
    return kExitOk;
  }
  const std::filesystem::path resolved = directory / kResolvedScenarioFile;
  const scenarios::LoadResult loaded = scenarios::load_scenario(resolved);
  err << scenarios::format_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) {
    err << "rodsort: cannot resume: " << resolved.string() << " no longer loads\n";
    return kExitFailure;
  }
  // Checked once, here, before anything in the directory is written: a refused resume leaves the
  // run as it was and resumable by the build that started it.
  const Checkpoint checkpoint = read_checkpoint(directory / kCheckpointFile);
  if (engine::fingerprint(read_file(resolved)) != checkpoint.scenario_fingerprint) {
    throw std::runtime_error(
        resolved.string() + " has changed since the run wrote it (its fingerprint differs from " +
        "the one in " + kCheckpointFile +
        "); a run resumes only with the scenario it started with: restore the file, or start a "
        "new run from the edited scenario");
  }
  written_by_another_build(checkpoint, directory, options.any_build);
  if (!duration) {
    return continue_run(make_run_plan(*loaded.scenario), directory, checkpoint, options);
  }

  // Extending: the same scenario with another run.duration, checked as a new one would be.
  char value[64];
  std::snprintf(value, sizeof value, "run.duration=%.17g", *duration);
  const scenarios::LoadResult longer = scenarios::load_scenario_with_options(resolved, {value});
  err << scenarios::format_diagnostics(longer.diagnostics, false);
  if (!longer.ok()) {
    err << "rodsort: cannot continue " << directory.string() << " to t = " << *duration
        << " s; nothing was changed\n";
    return kExitUsage;
  }
  if (*duration < record->simulated_s) {
    err << "rodsort: " << directory.string() << " has already reached t = " << record->simulated_s
        << " s, beyond --duration " << *duration << " s; nothing was changed\n";
    return kExitUsage;
  }
  const RunPlan plan = make_run_plan(*longer.scenario);
  write_file_atomically(resolved, plan.resolved_yaml);
  return continue_run(plan, directory, checkpoint, options);
}

int validate_scenario_file(const std::filesystem::path& scenario,
                           const std::vector<std::string>& set_options, std::ostream& out,
                           std::ostream& err) {
  const scenarios::LoadResult loaded = scenarios::load_scenario_with_options(scenario, set_options);
  err << scenarios::format_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) {
    hint_if_sweep(scenario, err);
    return kExitUsage;
  }
  out << scenarios::resolved_yaml(*loaded.scenario);
  return kExitOk;
}

}  // namespace rodsort::runner
