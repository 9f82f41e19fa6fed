#include "bench/command.hpp"

#include <iostream>

namespace rodsort::bench {

void add_command_options(CLI::App& app, CommandOptions& command) {
  add_options(app, command.options);
  add_accuracy_options(app, command.accuracy, command.accuracy_selected);
}

int run_command(CommandOptions& command, std::ostream& out) {
  if (!command.accuracy_selected) return run(command.options, out, std::cerr);
  command.accuracy.seed = command.options.seed;
  command.accuracy.csv = command.options.csv;
  command.accuracy.solver_iterations = command.options.solver_iterations;
  return run_accuracy(command.accuracy, out);
}

}  // namespace rodsort::bench
