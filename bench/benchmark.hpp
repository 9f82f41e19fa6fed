#pragma once
// The benchmark: runs standard systems for a fixed simulated time after a warm-up and reports the
// cost of the engine in the project's unit, CPU seconds per simulated second, with microseconds per
// rod per step (whose constancy across sizes shows linear scaling) and the peak resident memory.
//
// CPU time is the process's (CLOCK_PROCESS_CPUTIME_ID): the engine runs on one core, and CPU time
// is less disturbed than wall time by other processes on a shared machine. With repeats, the
// smallest of the repeats is reported: disturbances only ever add time. Peak memory is the
// process's high-water mark (getrusage ru_maxrss); systems run from the smallest to the largest,
// so the mark after a system is that system's peak.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace rodsort::bench {

struct Options {
  std::vector<std::string> systems = {"single", "319", "1276", "5104"};
  double dt = 1.0e-4;           ///< time step [s]
  double simulated_time = 0.1;  ///< measured simulated time per system [s]
  double warmup = 0.05;         ///< simulated time before the measurement [s]
  int repeats = 1;              ///< measurements per system; the fastest is reported
  int solver_iterations = 10;   ///< engine::Model::solver_iterations
  std::uint64_t seed = 1;
  bool csv = false;
  /// Where the filled systems' state is kept (bench/filled_state.hpp); default_state_directory().
  std::filesystem::path state_directory;
  double fill_time = 30.0;  ///< simulated time that fills the trap of a filled system [s]
};

/// $XDG_CACHE_HOME/rodsort/bench, or ~/.cache/rodsort/bench, or rodsort-bench-states in the
/// working directory when neither variable is set.
std::filesystem::path default_state_directory();

struct Result {
  std::string system;
  int rods = 0;
  double dt = 0.0;                        ///< [s]
  std::int64_t steps = 0;                 ///< measured steps per repeat
  double cpu_seconds = 0.0;               ///< of the fastest repeat [s]
  double wall_seconds = 0.0;              ///< of the same repeat [s]
  double cpu_per_simulated = 0.0;         ///< CPU seconds per simulated second
  double us_per_rod_step = 0.0;           ///< CPU microseconds per rod per step
  double peak_memory_mib = 0.0;           ///< process high-water mark after the system ran [MiB]
  std::int64_t kicks_per_rod_second = 0;  ///< collision events per rod per simulated second
  double deepest_overlap_mm = 0.0;        ///< deepest contact over the timed steps [mm]
};

/// Declares the benchmark's options on a CLI11 app or subcommand (rodsort_bench, `rodsort bench`).
void add_options(CLI::App& app, Options& options);

/// Runs one system: builds it (a filled system from its kept state, which is made first when it
/// is not there yet, announced on `log`), warms it up, measures it `options.repeats` times.
Result run_system(const std::string& name, const Options& options, std::ostream& log);

void write_table(std::ostream& out, const std::vector<Result>& results);
void write_csv(std::ostream& out, const std::vector<Result>& results);

/// Runs every system of `options` in order, printing each row as soon as it is measured (a table,
/// or CSV with --csv) to `out`, and what it does besides measuring (filling a trap) to `log`.
/// Returns a process exit status.
int run(const Options& options, std::ostream& out, std::ostream& log);

}  // namespace rodsort::bench
