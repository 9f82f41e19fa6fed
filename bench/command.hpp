#pragma once
// The benchmark's command line, shared by the rodsort_bench program and `rodsort bench`.

#include <CLI/CLI.hpp>
#include <iosfwd>

#include "bench/accuracy.hpp"
#include "bench/benchmark.hpp"

namespace rodsort::bench {

struct CommandOptions {
  Options options;
  AccuracyOptions accuracy;
  bool accuracy_selected = false;  ///< --accuracy: single-rod v0 and D_r against dt instead
};

/// Declares the benchmark's options on `app`.
void add_command_options(CLI::App& app, CommandOptions& command);

/// Runs what the options select; returns the process's exit status.
int run_command(CommandOptions& command, std::ostream& out);

}  // namespace rodsort::bench
