// rodsort: the command line. It parses arguments and hands over to the runner layer; everything a
// command does lives there, where the tests reach it.

#include <exception>
#include <iostream>
#include <vector>

#include "app/command.hpp"
#include "runner/exit_code.hpp"
#include "runner/version.hpp"

namespace {

constexpr const char* kExitCodes =
    "Exit status:\n"
    "  0    success\n"
    "  1    runtime failure (I/O error, broken run directory, a sweep point failed)\n"
    "  2    usage error or refused scenario (nothing written)\n"
    "  130  interrupted by SIGINT/SIGTERM; a checkpoint was written: `rodsort run --resume DIR`\n"
    "Documentation: docs/cli.md";

}  // namespace

int main(int argc, char** argv) {
  using namespace rodsort;
  CLI::App app{"rodsort: vibrated polar granular rods sorted by a V-shaped trap"};
  app.name("rodsort");
  app.footer(kExitCodes);
  app.set_version_flag("--version", runner::version());
  app.require_subcommand(1);
  const std::vector<app::Command> commands = {
      app::add_run_command(app),     app::add_validate_command(app),
      app::add_sweep_command(app),   app::add_analyze_command(app),
      app::add_convert_command(app), app::add_summarize_command(app),
      app::add_render_command(app),  app::add_plot_command(app),
      app::add_bench_command(app),   app::add_single_command(app),
  };
  for (const app::Command& command : commands) command.subcommand->footer(kExitCodes);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? runner::kExitOk : runner::kExitUsage;
  }
  try {
    for (const app::Command& command : commands) {
      if (command.subcommand->parsed()) return command.action();
    }
  } catch (const std::exception& error) {
    std::cerr << "rodsort: error: " << error.what() << '\n';
    return runner::kExitFailure;
  }
  return runner::kExitUsage;
}
