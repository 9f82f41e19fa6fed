#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "runner/run_command.hpp"

namespace rodsort::app {

Command add_validate_command(CLI::App& app) {
  struct Options {
    std::string scenario;
    std::vector<std::string> set_options;
  };
  auto options = std::make_shared<Options>();
  CLI::App* validate = app.add_subcommand(
      "validate", "Check a scenario; print it resolved (every default explicit), or its errors");
  validate->add_option("SCENARIO", options->scenario, "Scenario file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  validate->add_option("--set", options->set_options,
                       "Override a scenario key, e.g. --set trap.angle=130 (repeatable)");
  return {validate, [options] {
            return runner::validate_scenario_file(options->scenario, options->set_options,
                                                  std::cout, std::cerr);
          }};
}

}  // namespace rodsort::app
