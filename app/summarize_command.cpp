#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "runner/summarize.hpp"

namespace rodsort::app {

Command add_summarize_command(CLI::App& app) {
  auto sweep_directory = std::make_shared<std::string>();
  CLI::App* summarize = app.add_subcommand(
      "summarize",
      "Print a sweep's time-averaged eta per point, and theta_c when the angle was swept");
  summarize->add_option("SWEEP_DIR", *sweep_directory, "Sweep directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  return {summarize, [sweep_directory] {
            return runner::summarize_sweep(*sweep_directory, std::cout, std::cerr);
          }};
}

}  // namespace rodsort::app
