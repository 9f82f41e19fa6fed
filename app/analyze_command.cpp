#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "runner/analyze.hpp"

namespace rodsort::app {

Command add_analyze_command(CLI::App& app) {
  auto request = std::make_shared<runner::AnalyzeRequest>();
  CLI::App* analyze = app.add_subcommand(
      "analyze",
      "Recompute a run's metrics.csv from its rods.csv (or other metrics settings into -o FILE)");
  analyze->add_option("RUN_DIR", request->run_directory, "Run directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  analyze
      ->add_option("--set", request->set_options,
                   "Override a metrics setting, e.g. --set metrics.stationary_threshold=0.5")
      ->allow_extra_args(false);
  analyze->add_option("-o,--output", request->output,
                      "Where to write the metrics (default: RUN_DIR/metrics.csv)");
  return {analyze, [request] { return runner::analyze_run(*request, std::cerr); }};
}

}  // namespace rodsort::app
