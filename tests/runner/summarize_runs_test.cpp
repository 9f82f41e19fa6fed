// `rodsort summarize RUN_DIR...`: eta(t) of runs in windows, and their nucleation attempts.

#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "rodsort_program.hpp"
#include "runner/atomic_file.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_lock.hpp"
#include "runner/run_record.hpp"
#include "runner/summarize.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::testing::TempDirectory;

namespace {

/// run.json of a complete run of `rods` rods over `simulated_s` at dt = 1e-4 s, 2 CPU-s per
/// simulated second.
void write_complete_record(const std::filesystem::path& directory, const std::string& name,
                           int rods, double simulated_s, std::uint64_t seed = 0) {
  RunRecord record;
  record.name = name;
  record.seed = seed;
  record.status = RunStatus::kComplete;
  record.rods = rods;
  record.dt_s = 1e-4;
  record.duration_s = record.simulated_s = simulated_s;
  record.steps = record.total_steps = static_cast<std::int64_t>(simulated_s / 1e-4 + 0.5);
  record.cpu_s = 2.0 * simulated_s;
  write_file_atomically(directory / kRunRecordFile, to_json(record));
}

/// A complete 100 s run whose eta_trap spikes to 0.6 between 10 and 20 s, falls back to 0 at
/// 20 s, rises again at 50 s and holds at 0.8; eta is eta_trap + 0.1 throughout.
void write_history(const std::filesystem::path& directory) {
  std::filesystem::create_directories(directory);
  write_complete_record(directory, "spiky", 40, 100.0);
  std::ofstream metrics(directory / kMetricsCsvFile);
  metrics << "t,eta,eta_trap,n_rods\n";
  for (int k = 1; k <= 1000; ++k) {
    const double t = 0.1 * k;
    const double trap = t >= 10.0 && t < 20.0 ? 0.6 : t >= 50.0 ? 0.8 : 0.0;
    metrics << t << ',' << trap + 0.1 << ',' << trap << ",40\n";
  }
}

}  // namespace

TEST_CASE("summarize reads a run's eta(t): windows, plateau and nucleation attempts",
          "[runner][summarize]") {
  TempDirectory scratch;
  write_history(scratch / "run");
  std::ostringstream out, err;
  REQUIRE(summarize_runs({scratch / "run"}, RunHistoryOptions{}, out, err) == kExitOk);
  const std::string text = out.str();
  INFO(text);
  CHECK_THAT(text, Catch::Contains("spiky, 40 rods, t = 100 of 100 s, complete, 2 CPU-s"));
  // Last half, 50.05-100 s: eta_trap 0.8 throughout, eta 0.9.
  CHECK_THAT(text, Catch::Contains("eta 0.9 (spread") && Catch::Contains("eta_trap 0.8;"));
  // Ten windows of 10 s; the second holds the spike (0.6 from 10 to 20 s: 10.0 is the window's
  // first sample after rounding, so 0.7 / 0.6 or very near).
  CHECK_THAT(text, Catch::Contains("per 10 s, eta / eta_trap:  0-10 0.10/0.00"));
  CHECK_THAT(text, Catch::Contains("90-100 0.90/0.80"));
  CHECK_THAT(text, Catch::Contains("nucleation attempts (eta_trap above 0.3, failed when back "
                                   "below 0.1): 2, 1 failed"));
  CHECK_THAT(text, Catch::Contains("from 10 s, peak 0.60 at 10 s, fell back at 20 s"));
  CHECK_THAT(text, Catch::Contains("from 50 s, peak 0.80 at 50 s, holds at the end (0.80)"));

  // Levels above the spike: only the pile that holds counts.
  RunHistoryOptions high;
  high.rise = 0.7;
  high.fall = 0.5;
  high.window_s = 50.0;
  std::ostringstream out_high, err_high;
  REQUIRE(summarize_runs({scratch / "run"}, high, out_high, err_high) == kExitOk);
  CHECK_THAT(out_high.str(),
             Catch::Contains("above 0.7, failed when back below 0.5): 1, 0 failed"));
  CHECK_THAT(out_high.str(), Catch::Contains("per 50 s, eta / eta_trap:  0-50 0.22/0.12  50-100 "
                                             "0.90/0.80"));

  // Up to 40 s: the spike alone, fallen back, and a last half (20-40 s) at 0.
  RunHistoryOptions early;
  early.until_s = 40.0;
  std::ostringstream out_early, err_early;
  REQUIRE(summarize_runs({scratch / "run"}, early, out_early, err_early) == kExitOk);
  CHECK_THAT(out_early.str(), Catch::Contains("up to t = 40 s"));
  CHECK_THAT(out_early.str(), Catch::Contains("last half (20.05-40 s): eta 0.1 (spread"));
  CHECK_THAT(out_early.str(), Catch::Contains("): 1, 1 failed"));
  CHECK_THAT(out_early.str(), Catch::Contains("per 5 s, eta / eta_trap:"));
  CHECK_THAT(out_early.str(), Catch::Contains("t = 100 of 100 s"));  // how far the run got

  // A run killed after its checkpoint at 60 s: run.json says running, no process holds its lock,
  // and metrics.csv goes on to 100 s.
  RunRecord killed = *read_run_record(scratch / "run");
  killed.status = RunStatus::kRunning;
  killed.simulated_s = 60.0;
  write_file_atomically(scratch / "run" / kRunRecordFile, to_json(killed));
  std::ofstream(scratch / "run" / kRunLockFile).flush();
  for (const double until_s : {0.0, 40.0}) {
    RunHistoryOptions options;
    options.until_s = until_s;
    std::ostringstream out_killed, err_killed;
    REQUIRE(summarize_runs({scratch / "run"}, options, out_killed, err_killed) == kExitOk);
    CHECK_THAT(out_killed.str(), Catch::Contains("t = 100 of 100 s, stopped"));
  }
}

TEST_CASE("summarize writes the runs' figures to a CSV file, one row per run",
          "[runner][summarize]") {
  TempDirectory scratch;
  write_history(scratch / "long");
  write_history(scratch / "short");
  // The second run is 40 s long: only the first of the long run's windows, and its spike.
  {
    std::ofstream metrics(scratch / "short" / kMetricsCsvFile);
    metrics << "t,eta,eta_trap,n_rods\n";
    for (int k = 1; k <= 400; ++k) {
      const double t = 0.1 * k;
      metrics << t << ',' << (t >= 10.0 && t < 20.0 ? 0.7 : 0.1) << ','
              << (t >= 10.0 && t < 20.0 ? 0.6 : 0.0) << ",40\n";
    }
  }
  RunHistoryOptions options;
  options.window_s = 50.0;
  options.csv = scratch / "runs.csv";
  std::ostringstream out, err;
  REQUIRE(summarize_runs({scratch / "long", scratch / "short"}, options, out, err) == kExitOk);
  CHECK_THAT(out.str(), Catch::Contains("wrote " + options.csv.string()));
  const CsvTable table = read_csv(options.csv);
  REQUIRE(table.rows.size() == 2);
  const auto at = [&](std::size_t row, const char* column) {
    const auto index = table.column(column);
    REQUIRE(index);
    return table.rows[row][*index];
  };
  CHECK(at(0, "name") == "spiky");
  CHECK(at(0, "status") == "complete");
  CHECK(std::stod(at(0, "eta_mean")) == Approx(0.9).margin(1e-9));
  CHECK(std::stod(at(0, "eta_trap_mean")) == Approx(0.8).margin(1e-9));
  CHECK(std::stod(at(0, "eta_trap_max")) == Approx(0.8).margin(1e-9));
  CHECK(at(0, "attempts") == "2");
  CHECK(at(0, "failed_attempts") == "1");
  CHECK(at(0, "holds") == "1");
  CHECK(std::stod(at(0, "eta_trap_50-100")) == Approx(0.8).margin(1e-9));
  // The short run: read to 40 s, one failed attempt, one window of the two, the other empty.
  CHECK(std::stod(at(1, "read_to_s")) == Approx(40.0));
  CHECK(at(1, "attempts") == "1");
  CHECK(at(1, "holds") == "0");
  CHECK(std::stod(at(1, "eta_trap_max")) == Approx(0.6).margin(1e-9));
  CHECK(std::stod(at(1, "eta_trap_0-50")) == Approx(0.6 * 100.0 / 400.0).margin(0.005));
  CHECK(at(1, "eta_trap_50-100").empty());

  // A file in a folder that does not exist is refused before anything is printed.
  options.csv = scratch / "missing" / "runs.csv";
  std::ostringstream out_missing, err_missing;
  CHECK(summarize_runs({scratch / "long"}, options, out_missing, err_missing) == kExitUsage);
  CHECK_THAT(err_missing.str(), Catch::Contains("expected a file name in an existing folder"));
  CHECK(out_missing.str().empty());
  CHECK_FALSE(std::filesystem::exists(options.csv));
}

TEST_CASE("summarize refuses a directory without a run and levels out of order",
          "[runner][summarize]") {
  TempDirectory scratch;
  write_history(scratch / "run");
  std::ostringstream out, err;
  CHECK(summarize_runs({scratch / "run", scratch.path()}, RunHistoryOptions{}, out, err) ==
        kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("is neither a sweep directory"));
  CHECK(out.str().empty());  // nothing printed before the refusal

  // A run without a trap writes no eta column: said, not read.
  std::ofstream(scratch / "run" / kMetricsCsvFile) << "t,n_rods\n0.07,40\n";
  std::ostringstream out_trapless, err_trapless;
  CHECK(summarize_runs({scratch / "run"}, RunHistoryOptions{}, out_trapless, err_trapless) ==
        kExitOk);
  CHECK_THAT(out_trapless.str(), Catch::Contains("no column eta in metrics.csv"));
  RunHistoryOptions reversed;
  reversed.rise = 0.1;
  reversed.fall = 0.3;
  std::ostringstream out_reversed, err_reversed;
  CHECK(summarize_runs({scratch / "run"}, reversed, out_reversed, err_reversed) == kExitUsage);
  CHECK_THAT(err_reversed.str(), Catch::Contains("--fall must lie in [0, --rise)"));
}

TEST_CASE("rodsort summarize takes one sweep directory or run directories, not both",
          "[runner][summarize]") {
  TempDirectory scratch;
  write_history(scratch / "run");
  const auto runs = rodsort::runner::testing::run_rodsort(
      {"summarize", (scratch / "run").string(), "--window", "25"}, scratch.path());
  CHECK(runs.status == kExitOk);
  CHECK_THAT(runs.out, Catch::Contains("per 25 s, eta / eta_trap:"));
  std::filesystem::create_directories(scratch / "sweep");
  std::ofstream(scratch / "sweep" / "sweep.csv") << "point,status\n";
  const auto mixed = rodsort::runner::testing::run_rodsort(
      {"summarize", (scratch / "sweep").string(), (scratch / "run").string()}, scratch.path());
  CHECK(mixed.status == kExitUsage);
  CHECK_THAT(mixed.err, Catch::Contains("give one sweep directory, or one or more run "
                                        "directories"));
  const auto sweep_csv = rodsort::runner::testing::run_rodsort(
      {"summarize", (scratch / "sweep").string(), "--csv", (scratch / "x.csv").string()},
      scratch.path());
  CHECK(sweep_csv.status == kExitUsage);
  CHECK_THAT(sweep_csv.err, Catch::Contains("--csv is for run directories"));
}

namespace {

/// A complete 100 s run at `angle` with eta constant at `eta` (eta_trap 0.9 of it), and a resolved
/// scenario that differs from its neighbours' only where asked.
void write_curve_run(const std::filesystem::path& directory, int seed, double angle, double eta,
                     const std::string& kick_eps = "0.01") {
  std::filesystem::create_directories(directory);
  write_complete_record(directory, "curve", 40, 100.0, seed);
  std::ofstream metrics(directory / kMetricsCsvFile);
  metrics << "t,eta,eta_trap,n_rods\n";
  for (int k = 1; k <= 1000; ++k) metrics << 0.1 * k << ',' << eta << ',' << 0.9 * eta << ",40\n";
  // What a resolved scenario holds that may differ along a curve: name, seed, the angle and the
  // apex placed from it, the length, the outputs and what is derived.
  std::ofstream(directory / kResolvedScenarioFile)
      << "name: curve\nseed: " << seed
      << "\nspecies:\n  - name: A\n    noise:\n      kick_eps: " << kick_eps
      << "\ntrap:\n  angle: " << angle << "\n  apex: [" << angle / 10
      << ", 1]\n  arm_length: 45\nrun:\n  duration: 100\n  dt: 1e-4\noutput:\n  rods_format: "
      << (seed == 1 ? "csv" : "h5md") << "\nderived:\n  rods: " << 400 - angle << "\n";
}

/// Runs at five angles from 100 to 140 degrees, seeds 1 and 2, named PREFIX-SEED-INDEX, in the
/// order angle by angle, seed 1 first. At eps = 0.01 seed 1 drops between 120 and 130 degrees and
/// seed 2 between 130 and 140 (plateau 0.8: the mean curve through 0.4 at 130 + 0.1 / 0.5 * 10 =
/// 132, the seeds alone at 120 + 0.4 / 0.6 * 10 = 126.67 and 130 + 0.4 / 0.8 * 10 = 135); at any
/// other noise both hold 0.8 to 120 degrees and 0 beyond (through 0.4 at 125).
std::vector<std::filesystem::path> write_curve_runs(const std::filesystem::path& scratch,
                                                    const std::string& prefix,
                                                    const std::string& kick_eps) {
  const std::vector<double> angles = {100, 110, 120, 130, 140};
  const std::vector<double> seed_1 = {0.8, 0.8, 0.8, 0.2, 0.0}, seed_2 = {0.8, 0.8, 0.8, 0.8, 0.0};
  std::vector<std::filesystem::path> runs;
  for (std::size_t i = 0; i < angles.size(); ++i) {
    for (const int seed : {1, 2}) {
      runs.push_back(scratch / (prefix + "-" + std::to_string(seed) + "-" + std::to_string(i)));
      const double eta =
          kick_eps != "0.01" ? (angles[i] <= 120 ? 0.8 : 0.0) : (seed == 1 ? seed_1 : seed_2)[i];
      write_curve_run(runs.back(), seed, angles[i], eta, kick_eps);
    }
  }
  return runs;
}

}  // namespace

TEST_CASE("summarize gives theta_c of runs made one by one at several angles",
          "[runner][summarize]") {
  TempDirectory scratch;
  std::vector<std::filesystem::path> runs = write_curve_runs(scratch.path(), "s", "0.01");
  std::ostringstream out, err;
  REQUIRE(summarize_runs(runs, RunHistoryOptions{}, out, err) == kExitOk);
  INFO(out.str());
  CHECK_THAT(
      out.str(),
      Catch::Contains("these runs: theta_c = 132 deg (between 130 and 140; plateau eta 0.8)"));
  CHECK_THAT(out.str(), Catch::Contains("each seed alone: 1: 126.7, 2: 135\n"));
  CHECK_THAT(out.str(), Catch::Contains("theta_c = 130.8 +- 4.2 deg (mean +- standard error over "
                                        "the 2 of 2 seeds that have one; standard deviation 5.9)"));

  // A run that has not finished is left out, and said to be; --until takes it back in.
  RunRecord stopped = *read_run_record(runs[6]);  // seed 1 at 130 degrees
  stopped.status = RunStatus::kInterrupted;
  write_file_atomically(runs[6] / kRunRecordFile, to_json(stopped));
  std::ostringstream out_stopped, err_stopped;
  REQUIRE(summarize_runs(runs, RunHistoryOptions{}, out_stopped, err_stopped) == kExitOk);
  CHECK_THAT(out_stopped.str(), Catch::Contains("left out, not complete: " + runs[6].string()));
  // Without it seed 1 has four angles, too few alone, and the mean curve is seed 2's at 130.
  CHECK_THAT(out_stopped.str(), Catch::Contains("these runs: theta_c = 135 deg"));
  CHECK_THAT(out_stopped.str(), Catch::Contains("each seed alone: 1: none, 2: 135\n"));
  CHECK_THAT(out_stopped.str(), Catch::Contains("      seed 1: a critical angle needs at least 5 "
                                                "angles"));
  CHECK_THAT(out_stopped.str(), Catch::Contains("(why not: above)"));
  RunHistoryOptions until;
  until.until_s = 80.0;
  std::ostringstream out_until, err_until;
  REQUIRE(summarize_runs(runs, until, out_until, err_until) == kExitOk);
  CHECK_THAT(out_until.str(), Catch::Contains("each seed alone: 1: 126.7, 2: 135\n"));

  // Runs of another noise make a curve of their own, as in a sweep over the noise: one theta_c
  // per noise, in the noise's order.
  std::vector<std::filesystem::path> noises = write_curve_runs(scratch.path(), "n", "0.02");
  noises.insert(noises.end(), runs.begin(), runs.end());
  std::ostringstream out_noises, err_noises;
  REQUIRE(summarize_runs(noises, RunHistoryOptions{}, out_noises, err_noises) == kExitOk);
  const std::string by_noise = out_noises.str();
  INFO(by_noise);
  CHECK_THAT(by_noise, Catch::Contains("  one curve per value of species[0].noise.kick_eps (the "
                                       "runs differ there)\n"
                                       "  species[0].noise.kick_eps=0.01: theta_c = 135 deg"));
  CHECK_THAT(by_noise, Catch::Contains("left out, not complete: " + runs[6].string()));
  CHECK_THAT(by_noise, Catch::Contains("species[0].noise.kick_eps=0.02: theta_c = 125 deg (between "
                                       "120 and 130; plateau eta 0.8)\n    each seed alone: 1: "
                                       "125, 2: 125\n"));
  CHECK(by_noise.find("kick_eps=0.01:") < by_noise.find("kick_eps=0.02:"));
  CHECK_THAT(by_noise, !Catch::Contains("these runs:"));

  // Runs that differ in more than three keys are not compared; the first key is named.
  write_curve_run(scratch / "other", 1, 150, 0.0);
  std::ofstream(scratch / "other" / kResolvedScenarioFile)
      << "name: curve\nseed: 1\nspecies:\n  - name: B\n    noise:\n      kick_eps: 0.03"
      << "\ntrap:\n  angle: 150\n  apex: [15, 1]\n  arm_length: 60\nrun:\n  duration: 100\n"
      << "  dt: 2e-4\n";
  runs.push_back(scratch / "other");
  std::ostringstream out_mixed, err_mixed;
  REQUIRE(summarize_runs(runs, RunHistoryOptions{}, out_mixed, err_mixed) == kExitOk);
  CHECK_THAT(
      out_mixed.str(),
      Catch::Contains("not computed: the runs differ in 4 keys besides trap.angle and seed "
                      "(runs are grouped by at most 3); the first: species[0].name is A in " +
                      runs[0].string() + " and B in " + (scratch / "other").string()));
  CHECK_THAT(out_mixed.str(), !Catch::Contains("these runs:"));

  // Runs at one angle make no curve: nothing is said of theta_c.
  std::ostringstream out_one, err_one;
  REQUIRE(summarize_runs({runs[0], runs[1]}, RunHistoryOptions{}, out_one, err_one) == kExitOk);
  CHECK_THAT(out_one.str(), !Catch::Contains("theta_c"));
}

TEST_CASE("Runs made one by one read as a sweep's points, one curve per noise",
          "[runner][summarize]") {
  TempDirectory scratch;
  // Two noises (write_curve_runs); seed 2 at 0.02 and 140 degrees has not finished.
  std::vector<std::filesystem::path> runs = write_curve_runs(scratch.path(), "0.02", "0.02");
  for (const auto& run : write_curve_runs(scratch.path(), "0.01", "0.01")) runs.push_back(run);
  RunRecord stopped = *read_run_record(runs[9]);
  stopped.status = RunStatus::kInterrupted;
  write_file_atomically(runs[9] / kRunRecordFile, to_json(stopped));

  std::ostringstream err;
  const std::optional<CsvTable> table = runs_sweep_table(runs, RunHistoryOptions{}, err);
  REQUIRE(table);
  CHECK(table->header == std::vector<std::string>{"point", "trap.angle",
                                                  "species[0].noise.kick_eps", "seed", "status",
                                                  "eta_mean", "eta_time_to_90_s", "simulated_s"});
  REQUIRE(table->rows.size() == 19);
  const std::vector<std::string> first = table->rows[0];
  CHECK(std::vector<std::string>(first.begin(), first.begin() + 5) ==
        std::vector<std::string>{"0.02-1-0", "100", "0.02", "1", "complete"});
  CHECK(std::stod(first[5]) == Approx(0.8));
  CHECK(first[7] == "100");
  CHECK_THAT(err.str(), Catch::Contains("note: left out, not complete: " + runs[9].string()));

  // Drawn by rodsort plot as a sweep's curves: theta_c per noise as summarize finds it (132 and
  // 125 degrees), the runs' own eta(t) beside them, and no temporary folder left behind.
  const std::filesystem::path temporary = scratch / "tmp";
  std::filesystem::create_directory(temporary);
  const char* tmpdir = std::getenv("TMPDIR");
  const std::string saved = tmpdir ? tmpdir : "";
  setenv("TMPDIR", temporary.c_str(), 1);
  std::vector<std::string> arguments = {"plot"};
  for (const auto& run : runs) arguments.push_back(run.string());
  arguments.insert(arguments.end(), {"--what", "eta-theta,thetac-eps,eta", "--format", "png", "-o",
                                     (scratch / "plots").string()});
  const auto plotted = rodsort::runner::testing::run_rodsort(arguments, scratch.path());
  if (tmpdir) {
    setenv("TMPDIR", saved.c_str(), 1);
  } else {
    unsetenv("TMPDIR");
  }
  INFO(plotted.out << plotted.err);
  REQUIRE(plotted.status == kExitOk);
  for (const char* file : {"eta-theta.png", "thetac-eps.png", "eta.png", "theta_c.csv"}) {
    CHECK(std::filesystem::is_regular_file(scratch / "plots" / file));
  }
  const CsvTable theta_c = read_csv(scratch / "plots" / "theta_c.csv");
  REQUIRE(theta_c.rows.size() == 2);
  CHECK(theta_c.rows[0][0] == "0.01");
  CHECK(std::stod(theta_c.rows[0][1]) == Approx(132.0));
  CHECK(theta_c.rows[1][0] == "0.02");
  CHECK(std::stod(theta_c.rows[1][1]) == Approx(125.0));
  // The seeds' own theta_c, as summarize gives it: at 0.01 126.67 and 135 (130.8 +- 4.2); at 0.02
  // seed 2, stopped at 140 degrees, has four angles and none.
  const std::size_t seed_mean = *theta_c.column("theta_c_seed_mean");
  CHECK(std::stod(theta_c.rows[0][seed_mean]) == Approx(130.8333).epsilon(1e-5));
  CHECK(std::stod(theta_c.rows[0][*theta_c.column("theta_c_seed_stderr")]) ==
        Approx(4.1667).epsilon(1e-4));
  CHECK(theta_c.rows[0][*theta_c.column("seeds_found")] == "2 of 2");
  CHECK(theta_c.rows[1][seed_mean] == "nan");
  CHECK(theta_c.rows[1][*theta_c.column("seeds_found")] == "1 of 2");
  CHECK(std::filesystem::is_empty(temporary));

  // An unknown kind beside them is refused before anything is drawn.
  const auto unknown = rodsort::runner::testing::run_rodsort(
      {"plot", runs[0].string(), runs[2].string(), "--what", "eta-theta,etaa", "-o",
       (scratch / "unknown").string()},
      scratch.path());
  CHECK(unknown.status == kExitUsage);
  CHECK_THAT(unknown.err, Catch::Contains("unknown kind 'etaa'"));
  CHECK(!std::filesystem::exists(scratch / "unknown" / "eta-theta.png"));

  // Runs at one angle make no curve: said, and nothing drawn.
  const auto one_angle =
      rodsort::runner::testing::run_rodsort({"plot", runs[0].string(), runs[1].string(), "--what",
                                             "eta-theta", "-o", (scratch / "one").string()},
                                            scratch.path());
  CHECK(one_angle.status == kExitFailure);
  CHECK_THAT(one_angle.err, Catch::Contains("needs runs at two trap angles or more"));
  CHECK(!std::filesystem::exists(scratch / "one" / "eta-theta.png"));
}

TEST_CASE("A sweep's theta_c groups come in the numeric order of their values",
          "[runner][summarize]") {
  // The runs of two noises laid out as a sweep's points: 5e-3 comes after 0.01 as text and before
  // it as a number; the groups, printed and in critical_angle.csv, follow the number.
  TempDirectory scratch;
  const std::filesystem::path sweep = scratch / "sweep";
  std::vector<std::filesystem::path> runs = write_curve_runs(sweep, "a", "0.01");
  for (const auto& run : write_curve_runs(sweep, "b", "5e-3")) runs.push_back(run);
  std::ostringstream err;
  const std::optional<CsvTable> table = runs_sweep_table(runs, RunHistoryOptions{}, err);
  REQUIRE(table);
  write_file_atomically(sweep / "sweep.csv", csv_text(*table));

  std::ostringstream out;
  REQUIRE(summarize_sweep(sweep, out, err) == kExitOk);
  const std::string summary = out.str();
  INFO(summary << err.str());
  const std::size_t small = summary.find("species[0].noise.kick_eps=5e-3: theta_c = 125 deg");
  const std::size_t large = summary.find("species[0].noise.kick_eps=0.01: theta_c = 132 deg");
  REQUIRE(small != std::string::npos);
  REQUIRE(large != std::string::npos);
  CHECK(small < large);
  const CsvTable critical = read_csv(sweep / "critical_angle.csv");
  REQUIRE(critical.rows.size() == 2);
  CHECK(critical.rows[0][0] == "5e-3");
  CHECK(std::stod(critical.rows[0][1]) == Approx(125.0));
  CHECK(critical.rows[1][0] == "0.01");
  CHECK(std::stod(critical.rows[1][1]) == Approx(132.0));
  const CsvTable seeds = read_csv(sweep / "critical_angle_seeds.csv");
  REQUIRE(seeds.rows.size() == 4);
  CHECK(seeds.rows[0][0] == "5e-3");
  CHECK(seeds.rows[3][0] == "0.01");
}

TEST_CASE("summarize prints a mixture sweep's sorting measures", "[runner][summarize]") {
  // Two points of a sweep over RnT's noise, their measures constant in time.
  TempDirectory scratch;
  const std::filesystem::path sweep = scratch / "sweep";
  const std::vector<std::pair<std::string, std::string>> points = {
      {"white_Dr-0", "0.7,0.5,0.49,0.51,0.17,0.48"}, {"white_Dr-2", "0.84,0.25,0.7,0.3,0.55,0.76"}};
  std::string sweep_csv = "point,species[1].noise.white_Dr,status\n";
  for (const auto& [point, values] : points) {
    const std::filesystem::path run = sweep / point;
    std::filesystem::create_directories(run);
    write_complete_record(run, "mixture", 397, 10.0);
    std::ofstream metrics(run / kMetricsCsvFile);
    metrics << "t,eta,eta_trap,fraction_trap_A,fraction_trap_RnT,purity_A,purity_RnT,"
               "sorting_index,purity_held_A\n";
    for (int k = 1; k <= 100; ++k) metrics << 0.1 * k << ",0.6,0.5," << values << '\n';
    sweep_csv += point + "," + point.substr(9) + ",complete\n";
  }
  write_file_atomically(sweep / "sweep.csv", sweep_csv);
  std::ostringstream out, err;
  REQUIRE(summarize_sweep(sweep, out, err) == kExitOk);
  INFO(out.str() << err.str());
  CHECK_THAT(out.str(), Catch::Contains("sorting: averaged over the last half of each run"));
  CHECK_THAT(out.str(), Catch::Contains("A's share of the rods inside, and of the held ones"));
  CHECK_THAT(out.str(), Catch::Contains("fraction_trap_A_mean  fraction_trap_RnT_mean  "
                                        "purity_A_mean  purity_held_A_mean  sorting_index_mean"));
  CHECK_THAT(out.str(), Catch::Contains("white_Dr-2  2                          complete  0.84"
                                        "                  0.25                    0.7            "
                                        "0.76                0.55\n"));
}
