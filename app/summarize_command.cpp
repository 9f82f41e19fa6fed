#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/number_checks.hpp"
#include "runner/exit_code.hpp"
#include "runner/summarize.hpp"

namespace rodsort::app {
namespace {

struct SummarizeOptions {
  std::vector<std::string> paths;
  runner::RunHistoryOptions history;
};

int summarize(const SummarizeOptions& options) {
  const auto is_sweep = [](const std::string& path) {
    return std::filesystem::exists(std::filesystem::path(path) / "sweep.csv");
  };
  if (options.paths.size() == 1 && is_sweep(options.paths.front())) {
    if (!options.history.csv.empty()) {
      std::cerr << "rodsort: --csv is for run directories; a sweep's table is its sweep.csv ("
                << options.paths.front() << ")\n";
      return runner::kExitUsage;
    }
    return runner::summarize_sweep(options.paths.front(), std::cout, std::cerr);
  }
  for (const std::string& path : options.paths) {
    if (is_sweep(path)) {
      std::cerr << "rodsort: give one sweep directory, or one or more run directories (" << path
                << " is a sweep)\n";
      return runner::kExitUsage;
    }
  }
  const std::vector<std::filesystem::path> runs(options.paths.begin(), options.paths.end());
  return runner::summarize_runs(runs, options.history, std::cout, std::cerr);
}

}  // namespace

Command add_summarize_command(CLI::App& app) {
  auto options = std::make_shared<SummarizeOptions>();
  CLI::App* command = app.add_subcommand(
      "summarize",
      "Print a sweep's time-averaged eta per point, and theta_c when the angle was swept; or, for "
      "run directories, eta(t) in windows and the nucleation attempts, and theta_c when they are "
      "runs of one scenario at several angles");
  command->add_option("PATH", options->paths, "One sweep directory, or one or more run directories")
      ->required()
      ->check(CLI::ExistingDirectory);
  command
      ->add_option("--rise", options->history.rise,
                   "Runs: a nucleation attempt begins when eta_trap rises above this (default 0.3)")
      ->check(positive_number());
  command
      ->add_option("--fall", options->history.fall,
                   "Runs: an attempt has failed when eta_trap falls back below this (default 0.1)")
      ->check(CLI::Range(0.0, 1e9));
  command
      ->add_option("--window", options->history.window_s,
                   "Runs: length of the windows of the eta means [s] (default: a round length "
                   "that makes at most 10)")
      ->check(positive_number());
  command
      ->add_option("--until", options->history.until_s,
                   "Runs: read eta(t) up to this time [s] (runs of different lengths compared)")
      ->check(positive_number());
  command->add_option("--csv", options->history.csv,
                      "Runs: also write the figures to this CSV file, one row per run");
  return {command, [options] { return summarize(*options); }};
}

}  // namespace rodsort::app
