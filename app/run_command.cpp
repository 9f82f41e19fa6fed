#include "runner/run_command.hpp"

#include <iostream>
#include <memory>
#include <optional>

#include "app/command.hpp"

namespace rodsort::app {

Command add_run_command(CLI::App& app) {
  struct Options {
    runner::RunRequest request;
    std::string resume;
    double duration = 0.0;
    bool quiet = false;
  };
  auto options = std::make_shared<Options>();
  CLI::App* run = app.add_subcommand(
      "run", "Run a scenario into a run directory, or continue a stopped run (--resume DIR)");
  CLI::Option* scenario =
      run->add_option("SCENARIO", options->request.scenario, "Scenario file (YAML)")
          ->check(CLI::ExistingFile);
  CLI::Option* output = run->add_option("-o,--output", options->request.output,
                                        "Run directory (default: runs/<scenario name>)");
  CLI::Option* set = run->add_option("--set", options->request.set_options,
                                     "Override a scenario key, e.g. --set trap.angle=130; "
                                     "repeat for several")
                         ->allow_extra_args(false);
  CLI::Option* force = run->add_flag("--force", options->request.force,
                                     "Replace a run already in the output directory");
  CLI::Option* resume =
      run->add_option("--resume", options->resume,
                      "Continue the run in DIR from its checkpoint (files are cut back to it)")
          ->check(CLI::ExistingDirectory)
          ->excludes(scenario, output, set, force);
  CLI::Option* duration =
      run->add_option("--duration", options->duration,
                      "With --resume: continue the run, complete or not, to this simulated time "
                      "[s] instead of its own run.duration")
          ->check(CLI::PositiveNumber)
          ->needs(resume);
  run->add_flag("--any-build", options->request.options.any_build,
                "With --resume: continue a run whose checkpoint another build of rodsort wrote "
                "(same physics, not bit for bit the same run)");
  run->add_flag("-q,--quiet", options->quiet, "No progress lines");
  run->callback([options] {
    if (options->request.scenario.empty() && options->resume.empty()) {
      throw CLI::RequiredError("SCENARIO (or --resume DIR)");
    }
  });
  return {run, [options, duration] {
            options->request.options.show_progress = !options->quiet;
            if (!options->resume.empty()) {
              return runner::resume_run_directory(
                  options->resume, options->request.options, std::cerr,
                  duration->count() > 0 ? std::optional<double>(options->duration) : std::nullopt);
            }
            return runner::run_scenario_file(options->request, std::cerr);
          }};
}

}  // namespace rodsort::app
