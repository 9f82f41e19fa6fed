#include "runner/sweep.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <ostream>

#include "runner/append_file.hpp"
#include "runner/atomic_file.hpp"
#include "runner/cost_estimate.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/file_kind.hpp"
#include "runner/interrupt.hpp"
#include "runner/process_pool.hpp"
#include "runner/progress.hpp"
#include "runner/run_command.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_lock.hpp"
#include "runner/run_record.hpp"
#include "runner/run_summary.hpp"
#include "runner/self_program.hpp"
#include "runner/slurm.hpp"
#include "runner/usable_cpus.hpp"
#include "scenarios/number_text.hpp"
#include "scenarios/scenario.hpp"
#include "scenarios/sweep.hpp"

namespace rodsort::runner {
namespace {

constexpr const char* kSweepCsvFile = "sweep.csv";
constexpr const char* kScenariosDirectory = "scenarios";
constexpr const char* kLogsDirectory = "logs";

enum class PointAction { kSkip, kStart, kResume, kRestart, kExtend };

struct PointPlan {
  std::string name;
  std::vector<std::string> values;  ///< of the swept keys, as written
  std::string resolved_yaml;
  PointAction action = PointAction::kStart;
  std::size_t rods = 0;
  double duration = 0.0;            ///< run.duration [s]
  std::int64_t steps_left = 0;      ///< of what is left to run
  CostEstimate cost{};              ///< of what is left to run
  std::optional<RunRecord> record;  ///< of the run this point holds, if any
  bool own_rate = false;            ///< `cost` is what is left at the run's own rate so far
  bool foreign = false;   ///< holds another scenario; left alone (only --point gets this far)
};

/// A number for sweep.csv: shortest exact text, "nan" when undefined.
std::string number_text(double value) {
  return std::isnan(value) ? "nan" : scenarios::format_real(value);
}

/// Whether the run in `run_directory` is of the point's scenario but for a shorter run.duration,
/// and has not gone beyond `duration`: it can be continued to it.
bool extendable_to(const std::filesystem::path& run_directory, const std::string& resolved_yaml,
                   double duration) {
  const auto record = read_run_record(run_directory);
  if (!record || record->simulated_s > duration ||
      !std::filesystem::exists(run_directory / kCheckpointFile)) {
    return false;
  }
  char value[64];
  std::snprintf(value, sizeof value, "run.duration=%.17g", duration);
  const scenarios::LoadResult longer =
      scenarios::load_scenario_with_options(run_directory / kResolvedScenarioFile, {value});
  return longer.ok() && scenarios::resolved_yaml(*longer.scenario) == resolved_yaml;
}

/// What to do with a point, given what its run directory holds; empty message when it may go on.
PointAction decide(const std::filesystem::path& run_directory, const PointPlan& plan, bool force,
                   std::string& conflict) {
  if (!holds_run(run_directory)) return PointAction::kStart;
  const std::filesystem::path resolved = run_directory / kResolvedScenarioFile;
  const bool same_scenario =
      std::filesystem::exists(resolved) && read_file(resolved) == plan.resolved_yaml;
  if (!same_scenario) {
    if (std::filesystem::exists(resolved) &&
        extendable_to(run_directory, plan.resolved_yaml, plan.duration)) {
      return PointAction::kExtend;
    }
    if (force) return PointAction::kRestart;
    conflict = run_directory.string() + " holds a run of a different scenario";
    return PointAction::kSkip;
  }
  const auto record = read_run_record(run_directory);
  if (record && record->status == RunStatus::kComplete) return PointAction::kSkip;
  if (record && std::filesystem::exists(run_directory / kCheckpointFile)) {
    return PointAction::kResume;
  }
  return PointAction::kRestart;
}

std::vector<std::string> point_command(const std::vector<std::string>& program,
                                       const std::filesystem::path& scenario_file,
                                       const std::filesystem::path& run_directory,
                                       const PointPlan& point, bool any_build) {
  std::vector<std::string> argv = program;
  const PointAction action = point.action;
  if (action == PointAction::kResume || action == PointAction::kExtend) {
    argv.insert(argv.end(), {"run", "--resume", run_directory.string()});
    if (action == PointAction::kExtend) {
      argv.push_back("--duration");
      argv.push_back(scenarios::format_real(point.duration));
    }
    if (any_build) argv.push_back("--any-build");
    return argv;
  }
  argv.insert(argv.end(), {"run", scenario_file.string(), "-o", run_directory.string()});
  if (action == PointAction::kRestart) argv.push_back("--force");
  return argv;
}

std::string describe_result(const JobResult& result) {
  if (result.signal != 0) return std::string("killed by SIG") + sigabbrev_np(result.signal);
  switch (result.exit_code) {
    case kExitOk:
      return "complete";
    case kExitInterrupted:
      return "interrupted";
    default:
      return "failed (exit " + std::to_string(result.exit_code) + ")";
  }
}

const char* describe_action(PointAction action) {
  switch (action) {
    case PointAction::kSkip:
      return "complete, skipped";
    case PointAction::kStart:
      return "to run";
    case PointAction::kResume:
      return "to resume from its checkpoint";
    case PointAction::kRestart:
      return "to run again (--force)";
    case PointAction::kExtend:
      return "to continue to the new run.duration";
  }
  return "";
}

void print_plan(const scenarios::Sweep& sweep, const std::vector<PointPlan>& points,
                const std::filesystem::path& directory, std::ostream& out) {
  out << "sweep " << sweep.name << ": " << points.size() << " points into " << directory.string()
      << ", over";
  for (const std::string& key : sweep.keys) out << ' ' << key;
  out << '\n';
  CostEstimate total{0.0, 0.0};
  std::vector<RunRecord> records;
  for (const PointPlan& point : points) {
    out << "  " << point.name << ": "
        << (point.foreign ? "holds another scenario, left alone" : describe_action(point.action));
    if (point.record) records.push_back(*point.record);
    if (point.action != PointAction::kSkip) {
      out << " (" << point.rods << " rods, " << describe_cost(point.cost)
          << (point.own_rate ? " left, at its own rate so far" : "") << ')';
      total.low_cpu_s += point.cost.low_cpu_s;
      total.high_cpu_s += point.cost.high_cpu_s;
    }
    out << '\n';
  }
  if (total.high_cpu_s > 0.0) {
    out << "to run: " << describe_cost(total)
        << " in all, from rods spread out to a filled trap (docs/performance.md); what is left "
           "of a point past a twentieth of its run, at its own rate so far\n";
    // The range is measured on one machine; the runs this sweep has made say what this one does.
    const auto measured = median_rod_step_cost(records);
    if (measured) {
      double at_measured = 0.0;
      for (const PointPlan& point : points) {
        if (point.action == PointAction::kSkip) continue;
        at_measured += point.own_rate ? point.cost.high_cpu_s
                                      : measured->rod_step_cpu_s * static_cast<double>(point.rods) *
                                            static_cast<double>(point.steps_left);
      }
      char rate[64];
      std::snprintf(rate, sizeof rate, "%.2f", measured->rod_step_cpu_s * 1e6);
      out << "at the cost this sweep's runs have measured here (" << rate
          << " us per rod per step, the median of " << measured->runs
          << (measured->runs == 1 ? " run" : " runs")
          << "): " << describe_cost({at_measured, at_measured}) << " in all\n";
    }
  } else {
    out << "nothing to run\n";
  }
}

/// Whether --point names this point, by its name or by its index in the sweep.
bool names_point(const std::string& requested, const std::string& name, std::size_t index) {
  return requested == name || requested == std::to_string(index);
}

/// --point: the one point, in this process (exec), as a task of a Slurm array runs it.
int run_point(const SweepRequest& request, const std::vector<std::string>& program,
              const std::filesystem::path& directory, const std::vector<PointPlan>& points,
              std::ostream& out, std::ostream& err) {
  const PointPlan* chosen = nullptr;
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (names_point(request.point, points[p].name, p)) chosen = &points[p];
  }
  if (chosen == nullptr) {
    err << "rodsort: --point " << request.point << ": the sweep has no such point (give its index, "
        << "0 to " << points.size() - 1 << ", or its name)\n";
    return kExitUsage;
  }
  if (chosen->action == PointAction::kSkip) {
    out << "rodsort: point " << chosen->name << " is complete; nothing to do\n";
    return kExitOk;
  }
  std::filesystem::create_directories(directory / kScenariosDirectory);
  const std::filesystem::path scenario_file =
      directory / kScenariosDirectory / (chosen->name + ".yaml");
  if (chosen->action == PointAction::kStart || chosen->action == PointAction::kRestart) {
    write_file_atomically(scenario_file, chosen->resolved_yaml);
  }
  const std::vector<std::string> argv =
      point_command(program, scenario_file, directory / chosen->name, *chosen, request.any_build);
  out << "rodsort: point " << chosen->name << ' ' << describe_action(chosen->action) << ":";
  for (const std::string& word : argv) out << ' ' << shell_quote(word);
  out << std::endl;
  std::vector<char*> args;
  for (const std::string& word : argv) args.push_back(const_cast<char*>(word.c_str()));
  args.push_back(nullptr);
  ::execv(args[0], args.data());
  err << "rodsort: cannot run " << argv[0] << ": " << std::strerror(errno) << '\n';
  return kExitFailure;
}

/// --slurm: the points to run as one job array.
int submit_array(const SweepRequest& request, const scenarios::Sweep& sweep,
                 const std::vector<std::string>& program, const std::filesystem::path& directory,
                 const std::vector<PointPlan>& points, std::ostream& out, std::ostream& err) {
  SlurmArray array;
  array.sweep_name = sweep.name;
  array.program = program;
  array.sweep_file = std::filesystem::absolute(request.sweep_file);
  array.directory = std::filesystem::absolute(directory);
  array.set_options = request.set_options;
  array.any_build = request.any_build;
  if (array.directory.string().find_first_of(" \t\n'\"") != std::string::npos ||
      array.sweep_file.string().find_first_of(" \t\n'\"") != std::string::npos) {
    err << "rodsort: --slurm: the sweep file's and the sweep directory's paths must not hold "
           "spaces or quotes (they go into #SBATCH lines): "
        << array.sweep_file.string() << ", " << array.directory.string() << '\n';
    return kExitUsage;
  }
  CostEstimate total{0.0, 0.0};
  std::size_t running = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (points[p].action == PointAction::kSkip) continue;
    // A point still running (a task of an earlier array) is left to it.
    if (RunLock::held(directory / points[p].name)) {
      ++running;
      continue;
    }
    array.points.push_back(p);
    total.low_cpu_s += points[p].cost.low_cpu_s;
    total.high_cpu_s += points[p].cost.high_cpu_s;
  }
  if (running > 0) {
    out << "rodsort: sweep " << sweep.name << ": " << running
        << " points are running now and are left to their tasks\n";
  }
  if (array.points.empty()) {
    out << "rodsort: sweep " << sweep.name << ": "
        << (running > 0 ? "no other point to run" : "every point is complete")
        << "; nothing to submit\n";
    return kExitOk;
  }
  const std::filesystem::path script = directory / "slurm" / "sweep.sbatch";
  std::filesystem::create_directories(script.parent_path());
  write_file_atomically(script, sbatch_script(array, request.slurm));
  std::filesystem::permissions(script, std::filesystem::perms::owner_exec,
                               std::filesystem::perm_options::add);
  out << "rodsort: sweep " << sweep.name << ": " << array.points.size() << " of " << points.size()
      << " points to run (" << describe_cost(total) << " in all), array script " << script.string()
      << '\n';
  if (!request.slurm.submit) {
    out << "rodsort: not submitted (--no-submit); submit it with: sbatch "
        << shell_quote(script.string()) << '\n';
    return kExitOk;
  }
  try {
    const std::string job = submit_sbatch(script);
    AppendFile(directory / "slurm" / "jobs.txt").append(job + ' ' + utc_now_iso8601() + '\n');
    out << "rodsort: submitted job array " << job << "; follow it with: rodsort sweep --status "
        << shell_quote(directory.string()) << '\n';
  } catch (const std::exception& error) {
    err << "rodsort: " << error.what() << '\n';
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

void write_sweep_csv(const std::filesystem::path& sweep_directory,
                     const std::vector<std::string>& keys, const std::vector<std::string>& points,
                     const std::vector<std::vector<std::string>>& values) {
  std::vector<RunSummary> summaries;
  std::vector<std::string> mean_columns;
  for (const std::string& point : points) {
    summaries.push_back(summarize_run(sweep_directory / point));
    for (const auto& [name, mean] : summaries.back().plateau_means) {
      if (std::find(mean_columns.begin(), mean_columns.end(), name) == mean_columns.end()) {
        mean_columns.push_back(name);
      }
    }
  }
  CsvTable table;
  table.header.push_back(kSweepPointColumn);
  table.header.insert(table.header.end(), keys.begin(), keys.end());
  table.header.push_back(kSweepStatusColumn);
  for (const std::string& column : mean_columns) {
    table.header.push_back(column + "_mean");
    if (column == "eta") {
      table.header.push_back("eta_spread");
      table.header.push_back("eta_time_to_90_s");
    }
  }
  for (const char* column : {"simulated_s", "wall_s", "cpu_s_per_simulated_s"}) {
    table.header.push_back(column);
  }
  for (std::size_t p = 0; p < points.size(); ++p) {
    const RunSummary& summary = summaries[p];
    std::vector<std::string> row = {points[p]};
    row.insert(row.end(), values[p].begin(), values[p].end());
    row.push_back(summary.status);
    for (const std::string& column : mean_columns) {
      row.push_back(number_text(summary.plateau_mean(column)));
      if (column == "eta") {
        row.push_back(number_text(summary.eta_spread));
        row.push_back(number_text(summary.eta_time_to_90));
      }
    }
    row.push_back(number_text(summary.simulated_s));
    row.push_back(number_text(summary.wall_s));
    row.push_back(number_text(summary.cpu_per_simulated_s));
    table.rows.push_back(std::move(row));
  }
  write_file_atomically(sweep_directory / kSweepCsvFile, csv_text(table));
}

int run_sweep(const SweepRequest& request, std::ostream& out, std::ostream& err) {
  const scenarios::SweepLoadResult loaded =
      scenarios::load_sweep(request.sweep_file, true, request.set_options);
  err << scenarios::format_diagnostics(loaded.diagnostics);
  if (!loaded.ok()) {
    err << "rodsort: " << request.sweep_file.string() << " refused; nothing was written\n";
    if (guess_file_kind(request.sweep_file) == FileKind::kScenario) {
      err << "rodsort: " << request.sweep_file.string()
          << " looks like a scenario: run it with `rodsort run " << request.sweep_file.string()
          << "`\n";
    }
    return kExitUsage;
  }
  const scenarios::Sweep& sweep = *loaded.sweep;
  const std::filesystem::path directory =
      request.output.empty() ? default_run_directory(sweep.name) : request.output;

  std::vector<PointPlan> points;
  std::vector<std::string> conflicts;
  for (const scenarios::SweepPoint& point : sweep.points) {
    const scenarios::LoadResult scenario = scenarios::load_sweep_point(sweep, point);
    if (!scenario.ok()) {
      err << scenarios::format_diagnostics(scenario.diagnostics);
      return kExitUsage;
    }
    PointPlan plan;
    plan.name = point.name;
    for (const scenarios::Override& value : point.overrides)
      plan.values.push_back(value.value_text());
    plan.resolved_yaml = scenarios::resolved_yaml(*scenario.scenario);
    plan.rods = scenario.scenario->model.rods.size();
    plan.duration = scenario.scenario->run.duration;
    const std::int64_t steps = scenario.scenario->run.steps;
    plan.steps_left = steps;
    plan.cost = estimate_cost(scenario.scenario->model, steps);
    std::string conflict;
    plan.action = decide(directory / point.name, plan, request.force, conflict);
    const bool continued =
        plan.action == PointAction::kResume || plan.action == PointAction::kExtend;
    if (continued || (plan.action == PointAction::kSkip && conflict.empty())) {
      plan.record = read_run_record(directory / point.name);
    }
    if (continued && plan.record) {
      plan.steps_left = std::max<std::int64_t>(steps - plan.record->steps, 0);
      const RemainingCost left =
          remaining_cost(scenario.scenario->model, plan.record->steps, steps, plan.record->cpu_s);
      plan.cost = left.cost;
      plan.own_rate = left.own_rate;
    }
    // --point runs one point: what the others hold (one continued beyond the sweep's duration
    // with `run --resume --duration`, say) does not stop it, nor the other tasks of a job array.
    const bool chosen =
        request.point.empty() || names_point(request.point, point.name, points.size());
    if (!conflict.empty() && chosen) conflicts.push_back(conflict);
    plan.foreign = !conflict.empty();
    points.push_back(std::move(plan));
  }
  if (!conflicts.empty()) {
    for (const std::string& conflict : conflicts) err << "rodsort: " << conflict << '\n';
    err << "rodsort: the sweep file changed since these points ran; rerun them with --force, or "
           "sweep into a new directory with -o\n";
    return kExitUsage;
  }

  if (request.dry_run) {
    print_plan(sweep, points, directory, out);
    return kExitOk;
  }
  // Absolute, for the Slurm array's script, which may start in another directory.
  const std::vector<std::string> program =
      request.executable.empty()
          ? program_command()
          : std::vector<std::string>{std::filesystem::absolute(request.executable).string()};
  if (!request.point.empty()) {
    return run_point(request, program, directory, points, out, err);
  }

  std::filesystem::create_directories(directory / kScenariosDirectory);
  std::filesystem::create_directories(directory / kLogsDirectory);
  std::vector<std::string> names;
  std::vector<std::vector<std::string>> values;
  for (const PointPlan& point : points) {
    names.push_back(point.name);
    values.push_back(point.values);
  }
  write_sweep_csv(directory, sweep.keys, names, values);
  if (request.slurm.enabled) {
    return submit_array(request, sweep, program, directory, points, out, err);
  }

  std::vector<Job> jobs;
  std::vector<std::size_t> job_point;
  std::size_t skipped = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const PointPlan& point = points[p];
    if (point.action == PointAction::kSkip) {
      ++skipped;
      continue;
    }
    const std::filesystem::path scenario_file =
        directory / kScenariosDirectory / (point.name + ".yaml");
    if (point.action == PointAction::kStart || point.action == PointAction::kRestart) {
      write_file_atomically(scenario_file, point.resolved_yaml);
    }
    jobs.push_back(
        {point_command(program, scenario_file, directory / point.name, point, request.any_build),
         directory / kLogsDirectory / (point.name + ".log")});
    job_point.push_back(p);
  }
  const int parallel =
      std::max(1, std::min(request.jobs > 0 ? request.jobs : usable_cpus(),
                           static_cast<int>(std::max<std::size_t>(jobs.size(), 1))));
  const auto log = [&request](const std::string& line) {
    if (request.log == nullptr) return;
    std::fprintf(request.log, "%s\n", line.c_str());
    std::fflush(request.log);
  };
  log("rodsort: sweep " + sweep.name + ": " + std::to_string(points.size()) + " points into " +
      directory.string() + " (" + std::to_string(skipped) + " already complete, " +
      std::to_string(jobs.size()) + " to run, " + std::to_string(parallel) + " at a time)");

  const InterruptGuard guard;
  std::size_t finished = 0;
  int failures = 0;
  PoolCallbacks callbacks;
  callbacks.on_start = [&](std::size_t job) {
    const PointPlan& point = points[job_point[job]];
    const char* how = point.action == PointAction::kResume   ? " (resuming)"
                      : point.action == PointAction::kExtend ? " (continuing to the new duration)"
                                                             : "";
    log("  started  " + point.name + how);
  };
  callbacks.on_finish = [&](std::size_t job, const JobResult& result) {
    const PointPlan& point = points[job_point[job]];
    ++finished;
    if (result.exit_code != kExitOk && result.exit_code != kExitInterrupted) ++failures;
    std::string line = "  [" + std::to_string(finished) + "/" + std::to_string(jobs.size()) + "] " +
                       point.name + ": " + describe_result(result);
    try {
      const RunSummary summary = summarize_run(directory / point.name);
      if (result.exit_code == kExitOk) {
        char text[128];
        std::snprintf(text, sizeof text, " in %s, %.3g CPU-s per sim-s, eta = %.3g",
                      format_duration(summary.wall_s).c_str(), summary.cpu_per_simulated_s,
                      summary.plateau_mean());
        line += text;
      }
      write_sweep_csv(directory, sweep.keys, names, values);
    } catch (const std::exception& error) {
      line += std::string(" (") + error.what() + ")";
    }
    if (result.exit_code != kExitOk) line += "; see " + jobs[job].log.string();
    log(line);
  };
  run_jobs(jobs, parallel, callbacks);
  write_sweep_csv(directory, sweep.keys, names, values);

  if (InterruptGuard::received() != 0) {
    log("rodsort: sweep interrupted; run the same command again to continue it");
    return kExitInterrupted;
  }
  log("rodsort: sweep " + sweep.name + " done: " + (directory / kSweepCsvFile).string() +
      (failures > 0 ? " (" + std::to_string(failures) + " points failed)" : ""));
  return failures > 0 ? kExitFailure : kExitOk;
}

}  // namespace rodsort::runner
