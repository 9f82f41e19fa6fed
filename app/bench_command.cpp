#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "bench/command.hpp"

namespace rodsort::app {

Command add_bench_command(CLI::App& app) {
  auto options = std::make_shared<bench::CommandOptions>();
  CLI::App* bench = app.add_subcommand(
      "bench", "CPU seconds per simulated second of the standard systems (docs/performance.md)");
  bench::add_command_options(*bench, *options);
  return {bench, [options] { return bench::run_command(*options, std::cout); }};
}

}  // namespace rodsort::app
