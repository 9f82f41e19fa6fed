#pragma once
// Each subcommand lives in its own file: it declares its options on a CLI11 subcommand and returns
// the action to run when that subcommand is chosen. A new subcommand (bench, render, ...) is a new
// file and one line in main.cpp.

#include <CLI/CLI.hpp>
#include <functional>

namespace rodsort::app {

struct Command {
  CLI::App* subcommand;
  std::function<int()> action;  ///< returns the process's exit status (runner/exit_code.hpp)
};

Command add_run_command(CLI::App& app);
Command add_validate_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_analyze_command(CLI::App& app);
Command add_convert_command(CLI::App& app);
Command add_summarize_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_plot_command(CLI::App& app);
Command add_bench_command(CLI::App& app);
Command add_single_command(CLI::App& app);

}  // namespace rodsort::app
