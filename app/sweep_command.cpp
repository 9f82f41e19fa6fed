#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "runner/sweep.hpp"

namespace rodsort::app {

Command add_sweep_command(CLI::App& app) {
  auto request = std::make_shared<runner::SweepRequest>();
  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "Run a sweep's points as parallel processes and write sweep.csv; run it again to "
      "continue a stopped sweep");
  sweep->add_option("SWEEP", request->sweep_file, "Sweep file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  sweep->add_option("-o,--output", request->output, "Sweep directory (default: runs/<sweep name>)");
  sweep
      ->add_option("-j,--jobs", request->jobs,
                   "Points run at once (default: one per processor this process may use)")
      ->check(CLI::Range(1, 1024));
  sweep->add_flag("--force", request->force,
                  "Rerun points whose run directory holds a different scenario");
  sweep->add_flag("--any-build", request->any_build,
                  "Resume points whose checkpoint another build of rodsort wrote (same physics, "
                  "not bit for bit the same runs)");
  sweep->add_flag("--dry-run", request->dry_run,
                  "Check every point and list what would run; write nothing");
  return {sweep, [request] { return runner::run_sweep(*request, std::cout, std::cerr); }};
}

}  // namespace rodsort::app
