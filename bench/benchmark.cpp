#include "bench/benchmark.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <stdexcept>

#include "bench/filled_state.hpp"
#include "bench/measures.hpp"
#include "bench/standard_system.hpp"
#include "engine/simulation.hpp"

// Under valgrind --tool=callgrind --collect-atstart=no, only the measured steps are profiled; the
// macros do nothing in a normal run.
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define RODSORT_PROFILE_START() CALLGRIND_START_INSTRUMENTATION; CALLGRIND_TOGGLE_COLLECT
#define RODSORT_PROFILE_STOP() CALLGRIND_TOGGLE_COLLECT; CALLGRIND_STOP_INSTRUMENTATION
#else
#define RODSORT_PROFILE_START()
#define RODSORT_PROFILE_STOP()
#endif

namespace rodsort::bench {
namespace {

double wall_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace

std::filesystem::path default_state_directory() {
  if (const char* cache = std::getenv("XDG_CACHE_HOME"); cache != nullptr && *cache != '\0') {
    return std::filesystem::path(cache) / "rodsort" / "bench";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".cache" / "rodsort" / "bench";
  }
  return "rodsort-bench-states";
}

void add_options(CLI::App& app, Options& options) {
  app.add_option("--systems", options.systems,
                 "systems to run, smallest first: single (one free rod), 319, 1276, 5104 (the "
                 "paper's trap system, side x1, x2, x4), 319-full, 1276-full, 5104-full (the "
                 "same with the trap packed at the start), 319-filled, 319-filled-x4, "
                 "319-filled-x16 (the paper's system after its trap has filled, alone and in "
                 "2 x 2 and 4 x 4 copies)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--dt", options.dt, "time step [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--time", options.simulated_time, "measured simulated time per system [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--warmup", options.warmup, "simulated time before measuring [s]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option("--repeats", options.repeats, "measurements per system; the fastest is reported")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--solver-iterations", options.solver_iterations,
                 "iterations of Bullet's contact solver (the engine's default: 10)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--seed", options.seed, "seed of placement and noise")->capture_default_str();
  app.add_flag("--csv", options.csv, "print CSV instead of a table");
  app.add_option("--state-dir", options.state_directory,
                 "where the filled systems' state is kept, made once per seed, dt, solver "
                 "iterations and fill time (default: $XDG_CACHE_HOME/rodsort/bench or "
                 "~/.cache/rodsort/bench)");
  app.add_option("--fill-time", options.fill_time,
                 "simulated time that fills the trap of a filled system, from the packed start [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

Result run_system(const std::string& name, const Options& options, std::ostream& log) {
  const SystemSpec system = find_system(name);
  engine::State filled;
  if (system.filled_tiles > 0) {
    FillOptions fill;
    fill.directory =
        options.state_directory.empty() ? default_state_directory() : options.state_directory;
    fill.dt = options.dt;
    fill.seed = options.seed;
    fill.solver_iterations = options.solver_iterations;
    fill.fill_time = options.fill_time;
    filled = filled_paper_state(fill, log);
  }
  const std::int64_t warmup_steps = std::llround(options.warmup / options.dt);
  const std::int64_t steps =
      std::max<std::int64_t>(1, std::llround(options.simulated_time / options.dt));

  Result result;
  result.system = system.name;
  result.rods = system.rod_count;
  result.dt = options.dt;
  result.steps = steps;
  for (int repeat = 0; repeat < options.repeats; ++repeat) {
    engine::Model model = build_model(system, options.dt, options.seed);
    model.solver_iterations = options.solver_iterations;
    engine::Simulation simulation(std::move(model));
    if (system.filled_tiles > 0) {
      const engine::Model one_cell = build_model(find_system("319-full"), options.dt, options.seed);
      simulation.restore(tile_state(filled, one_cell, simulation.state(), system.filled_tiles));
    }
    simulation.advance(warmup_steps);
    simulation.reset_counters();
    const double cpu_start = process_cpu_seconds();
    const double wall_start = wall_seconds();
    RODSORT_PROFILE_START();
    simulation.advance(steps);
    RODSORT_PROFILE_STOP();
    const double cpu = process_cpu_seconds() - cpu_start;
    const double wall = wall_seconds() - wall_start;
    if (repeat == 0 || cpu < result.cpu_seconds) {
      result.cpu_seconds = cpu;
      result.wall_seconds = wall;
    }
    const double simulated = static_cast<double>(steps) * options.dt;
    result.kicks_per_rod_second = std::llround(static_cast<double>(simulation.counters().kicks) /
                                               simulated / system.rod_count);
    result.deepest_overlap_mm =
        std::max(result.deepest_overlap_mm, simulation.counters().deepest_overlap);
  }
  const double simulated = static_cast<double>(steps) * options.dt;
  result.cpu_per_simulated = result.cpu_seconds / simulated;
  result.us_per_rod_step = 1e6 * result.cpu_seconds / static_cast<double>(steps) / system.rod_count;
  result.peak_memory_mib = peak_memory_mib();
  return result;
}

namespace {

constexpr const char* kTableHeader =
    "system           rods        dt   steps    CPU [s]  CPU-s/sim-s  us/rod/step  kicks/rod/s  "
    "peak [MiB]"
    "  overlap [mm]";

void write_row(std::ostream& out, const Result& r) {
  char line[160];
  std::snprintf(line, sizeof line,
                "%-14s %6d %9.3g %7lld %10.3f %12.3f %12.3f %12lld %11.1f %13.3f", r.system.c_str(),
                r.rods, r.dt, static_cast<long long>(r.steps), r.cpu_seconds, r.cpu_per_simulated,
                r.us_per_rod_step, static_cast<long long>(r.kicks_per_rod_second),
                r.peak_memory_mib, r.deepest_overlap_mm);
  out << line << '\n';
}

constexpr const char* kCsvHeader =
    "system,rods,dt_s,steps,cpu_s,wall_s,cpu_s_per_simulated_s,us_per_rod_step,"
    "kicks_per_rod_s,peak_rss_mib,deepest_overlap_mm";

void write_csv_row(std::ostream& out, const Result& r) {
  out << r.system << ',' << r.rods << ',' << format("%.6g", r.dt) << ',' << r.steps << ','
      << format("%.4f", r.cpu_seconds) << ',' << format("%.4f", r.wall_seconds) << ','
      << format("%.4f", r.cpu_per_simulated) << ',' << format("%.4f", r.us_per_rod_step) << ','
      << r.kicks_per_rod_second << ',' << format("%.1f", r.peak_memory_mib) << ','
      << format("%.4f", r.deepest_overlap_mm) << '\n';
}

}  // namespace

void write_table(std::ostream& out, const std::vector<Result>& results) {
  out << kTableHeader << '\n';
  for (const Result& r : results) write_row(out, r);
}

void write_csv(std::ostream& out, const std::vector<Result>& results) {
  out << kCsvHeader << '\n';
  for (const Result& r : results) write_csv_row(out, r);
}

int run(const Options& options, std::ostream& out, std::ostream& log) {
  for (const std::string& name : options.systems) find_system(name);  // fail before running any
  out << (options.csv ? kCsvHeader : kTableHeader) << '\n' << std::flush;
  for (const std::string& name : options.systems) {
    const Result result = run_system(name, options, log);
    if (options.csv) {
      write_csv_row(out, result);
    } else {
      write_row(out, result);
    }
    out << std::flush;
  }
  return 0;
}

}  // namespace rodsort::bench
