#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/command.hpp"
#include "app/number_checks.hpp"
#include "render/plot_script.hpp"
#include "runner/exit_code.hpp"

namespace rodsort::app {
namespace {

struct PlotOptions {
  std::vector<std::string> paths;
  std::string what;
  std::string output;
  std::string format;
  double tau = 0.0;
  double until = 0.0;
};

int plot(const PlotOptions& options) {
  std::vector<std::string> arguments = options.paths;
  if (!options.what.empty()) arguments.insert(arguments.end(), {"--what", options.what});
  if (!options.output.empty()) arguments.insert(arguments.end(), {"-o", options.output});
  if (!options.format.empty()) arguments.insert(arguments.end(), {"--format", options.format});
  if (options.tau > 0.0) arguments.insert(arguments.end(), {"--tau", std::to_string(options.tau)});
  if (options.until > 0.0) {
    arguments.insert(arguments.end(), {"--until", std::to_string(options.until)});
  }
  const render::ProgramOutput plotted = render::run_plot_script(arguments);
  (plotted.exit_status == 0 ? std::cout : std::cerr) << plotted.output;
  switch (plotted.exit_status) {
    case 0:
      return runner::kExitOk;
    case 2:  // the script's own argument errors
      return runner::kExitUsage;
    default:
      return runner::kExitFailure;
  }
}

}  // namespace

Command add_plot_command(CLI::App& app) {
  auto options = std::make_shared<PlotOptions>();
  CLI::App* plot_command = app.add_subcommand(
      "plot",
      "Plot a run (eta(t), trap population, P(dtheta)) or a sweep (eta against theta with "
      "theta_c, theta_c against eps) as PNG and SVG, with matplotlib");
  plot_command
      ->add_option("PATH", options->paths,
                   "Run directories (drawn on the same axes) or one sweep directory")
      ->required()
      ->check(CLI::ExistingDirectory);
  plot_command->add_option(
      "--what", options->what,
      "Comma-separated kinds: eta, population, dtheta (runs); eta-theta, thetac-eps (sweeps). "
      "Default: all the input has");
  plot_command->add_option("-o,--output", options->output,
                           "Directory for the plots (default: PATH/plots)");
  plot_command->add_option("--format", options->format,
                           "Comma-separated: png, svg, pdf (default: png,svg)");
  plot_command
      ->add_option("--tau", options->tau, "Window of P(dtheta) [s] (default 0.07, the paper's)")
      ->check(positive_number());
  plot_command
      ->add_option("--until", options->until,
                   "eta and population of runs: draw up to this time [s] (runs of different "
                   "lengths on one time axis)")
      ->check(positive_number());
  return {plot_command, [options] { return plot(*options); }};
}

}  // namespace rodsort::app
