// rodsort_bench: the engine's benchmark (see bench/benchmark.hpp and docs/performance.md); the
// same as `rodsort bench`.

#include <exception>
#include <iostream>

#include "bench/command.hpp"

int main(int argc, char** argv) {
  rodsort::bench::CommandOptions command;
  CLI::App app{"rodsort_bench: CPU seconds per simulated second of the engine's standard systems"};
  app.name("rodsort_bench");
  rodsort::bench::add_command_options(app, command);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? 0 : 2;
  }
  try {
    return rodsort::bench::run_command(command, std::cout);
  } catch (const std::exception& error) {
    std::cerr << "rodsort_bench: error: " << error.what() << '\n';
    return 1;
  }
}
