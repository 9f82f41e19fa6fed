#include <stdlib.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "app/command.hpp"
#include "app/number_checks.hpp"
#include "render/plot_script.hpp"
#include "runner/atomic_file.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_directory.hpp"
#include "runner/summarize.hpp"

namespace rodsort::app {
namespace {

struct PlotOptions {
  std::vector<std::string> paths;
  std::string what;
  std::string output;
  std::string format;
  double tau = 0.0;
  double until = 0.0;
};

/// The plot script's exit status as rodsort's: 2 for its own argument errors.
int exit_code(int script_status) {
  switch (script_status) {
    case 0:
      return runner::kExitOk;
    case 2:
      return runner::kExitUsage;
    default:
      return runner::kExitFailure;
  }
}

/// Runs the plot script on `paths` with `kinds` (all the input has, when empty); its output goes
/// to stdout, or to stderr when it fails.
int run_script(const std::vector<std::string>& paths, const std::string& kinds,
               const std::string& output, const PlotOptions& options) {
  std::vector<std::string> arguments = paths;
  if (!kinds.empty()) arguments.insert(arguments.end(), {"--what", kinds});
  if (!output.empty()) arguments.insert(arguments.end(), {"-o", output});
  if (!options.format.empty()) arguments.insert(arguments.end(), {"--format", options.format});
  if (options.tau > 0.0) arguments.insert(arguments.end(), {"--tau", std::to_string(options.tau)});
  if (options.until > 0.0) {
    arguments.insert(arguments.end(), {"--until", std::to_string(options.until)});
  }
  const render::ProgramOutput plotted = render::run_plot_script(arguments);
  (plotted.exit_status == 0 ? std::cout : std::cerr) << plotted.output;
  return exit_code(plotted.exit_status);
}

/// A folder of its own under the system's temporary folder, removed with this object.
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "rodsort-plot-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) {
      throw std::runtime_error("cannot make a temporary folder under " +
                               std::filesystem::temp_directory_path().string());
    }
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// The curves of a sweep (eta against theta, theta_c against eps) drawn from runs made one by
/// one: rodsort reads them as a sweep's points (runner::runs_sweep_table, as `rodsort summarize`
/// groups them), writes that table as a sweep directory of its own, and plots it; the runs' own
/// kinds (`run_kinds`) are drawn first, so that an unknown one is refused before anything is
/// written.
int plot_runs_curves(const PlotOptions& options, const std::string& kinds,
                     const std::string& run_kinds) {
  std::vector<std::filesystem::path> runs(options.paths.begin(), options.paths.end());
  runner::RunHistoryOptions reading;
  reading.until_s = options.until;
  const std::optional<runner::CsvTable> table = runner::runs_sweep_table(runs, reading, std::cerr);
  if (!table) return runner::kExitFailure;
  if (!run_kinds.empty()) {
    if (const int drawn = run_script(options.paths, run_kinds, options.output, options);
        drawn != runner::kExitOk) {
      return drawn;
    }
  }
  ScratchFolder sweep;
  runner::write_file_atomically(sweep.path() / "sweep.csv", runner::csv_text(*table));
  // Species' names for the axes and legends, from the first run's scenario.
  const std::filesystem::path scenario = runs.front() / runner::kResolvedScenarioFile;
  if (std::filesystem::exists(scenario)) {
    std::filesystem::create_directory(sweep.path() / "scenarios");
    std::filesystem::copy_file(scenario, sweep.path() / "scenarios" / "runs.yaml");
  }
  return run_script({sweep.path().string()}, kinds,
                    options.output.empty() ? std::string("plots") : options.output, options);
}

bool is_run_directory(const std::filesystem::path& path) {
  return std::filesystem::exists(path / runner::kMetricsCsvFile) &&
         !std::filesystem::exists(path / "sweep.csv") &&
         !std::filesystem::exists(path / "lags.csv");
}

int plot(const PlotOptions& options) {
  // A sweep's kinds asked of run directories: their curves are drawn apart from the runs' own.
  std::vector<std::string> curve_kinds, run_kinds;
  std::stringstream what(options.what);
  for (std::string kind; std::getline(what, kind, ',');) {
    kind.erase(0, kind.find_first_not_of(' '));
    kind.erase(kind.find_last_not_of(' ') + 1);
    if (kind.empty()) continue;
    (kind == "eta-theta" || kind == "thetac-eps" ? curve_kinds : run_kinds).push_back(kind);
  }
  const bool runs = std::all_of(options.paths.begin(), options.paths.end(),
                                [](const std::string& path) { return is_run_directory(path); });
  if (!runs || curve_kinds.empty())
    return run_script(options.paths, options.what, options.output, options);
  const auto join = [](const std::vector<std::string>& kinds) {
    std::string joined;
    for (const std::string& kind : kinds) joined += (joined.empty() ? "" : ",") + kind;
    return joined;
  };
  return plot_runs_curves(options, join(curve_kinds), join(run_kinds));
}

}  // namespace

Command add_plot_command(CLI::App& app) {
  auto options = std::make_shared<PlotOptions>();
  CLI::App* plot_command = app.add_subcommand(
      "plot",
      "Plot a run (eta(t), trap population, P(dtheta)) or a sweep (eta against theta with "
      "theta_c, theta_c against eps) as PNG and SVG, with matplotlib");
  plot_command
      ->add_option("PATH", options->paths,
                   "Run directories (drawn on the same axes) or one sweep directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  plot_command->add_option(
      "--what", options->what,
      "Comma-separated kinds: eta, population, dtheta (runs); eta-theta, thetac-eps (sweeps, or "
      "runs at several angles). Default: all the input has");
  plot_command->add_option("-o,--output", options->output,
                           "Directory for the plots (default: PATH/plots)");
  plot_command->add_option("--format", options->format,
                           "Comma-separated: png, svg, pdf (default: png,svg)");
  plot_command
      ->add_option("--tau", options->tau, "Window of P(dtheta) [s] (default 0.07, the paper's)")
      ->check(positive_number());
  plot_command
      ->add_option("--until", options->until,
                   "eta and population of runs: draw up to this time [s] (runs of different "
                   "lengths on one time axis)")
      ->check(positive_number());
  return {plot_command, [options] { return plot(*options); }};
}

}  // namespace rodsort::app
