#include "runner/sweep.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <sstream>
#include <string>

#include "rodsort_program.hpp"
#include "runner/atomic_file.hpp"
#include "runner/cost_estimate.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_lock.hpp"
#include "runner/run_record.hpp"
#include "runner/slurm.hpp"
#include "runner/summarize.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::testing::TempDirectory;

namespace {

// Two points of tiny.yaml, at trap angles 40 and 60 degrees.
const std::string kTinySweep = RODSORT_SOURCE_DIR "/tests/runner/data/tiny-sweep.yaml";

SweepRequest tiny_sweep(const std::filesystem::path& directory) {
  SweepRequest request;
  request.sweep_file = kTinySweep;
  request.output = directory;
  request.jobs = 2;
  request.executable = rodsort::runner::testing::kRodsortProgram;
  request.log = nullptr;
  return request;
}

}  // namespace

TEST_CASE("a two-point sweep runs each point into its own directory", "[runner][sweep]") {
  TempDirectory directory;
  const auto sweep = directory / "sweep";
  std::ostringstream out, err;
  REQUIRE(run_sweep(tiny_sweep(sweep), out, err) == kExitOk);

  const CsvTable table = read_csv(sweep / "sweep.csv");
  REQUIRE(table.rows.size() == 2);
  CHECK(table.header[0] == "point");
  CHECK(table.header[1] == "trap.angle");
  CHECK(table.header[2] == "status");
  REQUIRE(table.column("eta_mean"));
  REQUIRE(table.column("cpu_s_per_simulated_s"));
  for (const auto& row : table.rows) {
    INFO(row[0]);
    CHECK(row[2] == "complete");
    CHECK(std::filesystem::exists(sweep / row[0] / kRodsCsvFile));
    CHECK(std::filesystem::exists(sweep / "logs" / (row[0] + ".log")));
    CHECK(std::filesystem::exists(sweep / "scenarios" / (row[0] + ".yaml")));
    CHECK(table.numbers(*table.column("eta_mean"))[0] >= 0.0);
  }
  // The sorting measures are averaged over the last half of each run, like eta.
  REQUIRE(table.column("purity_A_mean"));
  const std::size_t fraction_column = *table.column("fraction_trap_A_mean");
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const CsvTable metrics = read_csv(sweep / table.rows[r][0] / kMetricsCsvFile);
    const std::vector<double> t = metrics.numbers(*metrics.column("t"));
    const std::vector<double> fraction = metrics.numbers(*metrics.column("fraction_trap_A"));
    double sum = 0.0;
    int samples = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] < 0.5 * (t.front() + t.back())) continue;
      sum += fraction[i];
      ++samples;
    }
    REQUIRE(samples > 0);
    CHECK(table.numbers(fraction_column)[r] == Approx(sum / samples));
  }
  CHECK(table.rows[0][1] == "40");
  CHECK(table.rows[1][1] == "60");
  CHECK_THAT(read_file(sweep / table.rows[0][0] / kResolvedScenarioFile),
             Catch::Contains("angle: 40"));
  CHECK_THAT(read_file(sweep / table.rows[1][0] / kResolvedScenarioFile),
             Catch::Contains("angle: 60"));

  SECTION("running it again skips the finished points") {
    const auto before = std::filesystem::last_write_time(sweep / table.rows[0][0] / kRodsCsvFile);
    SweepRequest again = tiny_sweep(sweep);
    std::FILE* log = std::tmpfile();
    again.log = log;
    CHECK(run_sweep(again, out, err) == kExitOk);
    CHECK(std::filesystem::last_write_time(sweep / table.rows[0][0] / kRodsCsvFile) == before);
    std::rewind(log);
    char line[256] = {};
    CHECK(std::fgets(line, sizeof line, log) != nullptr);
    CHECK_THAT(std::string(line), Catch::Contains("2 already complete, 0 to run"));
    std::fclose(log);
  }

  SECTION("--status shows every point done and brings sweep.csv up to date") {
    std::filesystem::remove(sweep / "sweep.csv");
    write_sweep_csv(sweep, {"trap.angle"}, {"angle-40", "angle-60"}, {{"40"}, {"60"}});
    CHECK(sweep_status(sweep, out, err) == kExitOk);
    CHECK_THAT(out.str(), Catch::Contains("in all: 2 done"));
    CHECK_THAT(out.str(), Catch::Contains("0.35 / 0.35"));
    CHECK(read_csv(sweep / "sweep.csv").rows[1][2] == "complete");
  }

  SECTION("--set run.duration continues every point to the new time, as if run so from the start") {
    SweepRequest longer = tiny_sweep(sweep);
    longer.set_options = {"run.duration=0.49"};
    REQUIRE(run_sweep(longer, out, err) == kExitOk);
    SweepRequest fresh = tiny_sweep(directory / "fresh");
    fresh.set_options = {"run.duration=0.49"};
    REQUIRE(run_sweep(fresh, out, err) == kExitOk);
    for (const char* point : {"angle-40", "angle-60"}) {
      INFO(point);
      CHECK(read_file(sweep / point / kRodsCsvFile) ==
            read_file(directory / "fresh" / point / kRodsCsvFile));
    }
    CHECK(read_csv(sweep / "sweep.csv").rows[0][2] == "complete");
  }

  SECTION("a dry run to a longer duration prices what is left at the runs' own rate") {
    SweepRequest longer = tiny_sweep(sweep);
    longer.set_options = {"run.duration=0.49"};
    longer.dry_run = true;
    REQUIRE(run_sweep(longer, out, err) == kExitOk);
    // 3500 of 4900 steps done: 1400 left, at each run's CPU time per step so far.
    for (const char* point : {"angle-40", "angle-60"}) {
      INFO(point);
      const RunRecord record = *read_run_record(sweep / point);
      CHECK_THAT(out.str(),
                 Catch::Contains(std::string(point) + ": to continue to the new " +
                                 "run.duration (4 rods, " +
                                 describe_cost(*cost_at_own_rate(3500, 4900, record.cpu_s)) +
                                 " left, at its own rate so far)"));
    }
    CHECK_THAT(out.str(), Catch::Contains("us per rod per step, the median of 2 runs): about"));
  }

  SECTION("a complete sweep has nothing to submit to Slurm") {
    SweepRequest slurm = tiny_sweep(sweep);
    slurm.slurm.enabled = true;
    CHECK(run_sweep(slurm, out, err) == kExitOk);
    CHECK_THAT(out.str(), Catch::Contains("nothing to submit"));
    CHECK_FALSE(std::filesystem::exists(sweep / "slurm"));
  }

  SECTION("summarize prints eta per point and looks for theta_c") {
    CHECK(summarize_sweep(sweep, out, err) == kExitOk);
    CHECK_THAT(out.str(), Catch::Contains("angle-40"));
    CHECK_THAT(out.str(), Catch::Contains("angle-60"));
    CHECK_THAT(out.str(), Catch::Contains("theta_c"));
    CHECK(std::filesystem::exists(sweep / "critical_angle.csv"));
  }
}

TEST_CASE("summarize gives theta_c of each seed alone beside that of the seeds' mean",
          "[runner][sweep]") {
  TempDirectory directory;
  const auto sweep = directory / "sweep";
  SweepRequest request = tiny_sweep(sweep);
  request.sweep_file = RODSORT_SOURCE_DIR "/tests/runner/data/tiny-seeds-sweep.yaml";
  std::ostringstream out, err;
  REQUIRE(run_sweep(request, out, err) == kExitOk);
  std::ostringstream summary;
  REQUIRE(summarize_sweep(sweep, summary, err) == kExitOk);
  INFO(summary.str());
  // Four rods for 0.35 s fill no trap: no theta_c, for the mean nor for either seed, and why.
  CHECK_THAT(summary.str(), Catch::Contains("all points: not found"));
  CHECK_THAT(summary.str(), Catch::Contains("each seed alone: 1: none, 2: none\n"));
  CHECK_THAT(summary.str(), Catch::Contains("no error bar: 0 of 2 seeds alone have a theta_c"));
  const CsvTable seeds = read_csv(sweep / "critical_angle_seeds.csv");
  REQUIRE(seeds.rows.size() == 2);
  CHECK(seeds.header == std::vector<std::string>{"seed", "theta_c_deg", "below_deg", "above_deg",
                                                 "plateau_eta", "angles", "note"});
  for (std::size_t s = 0; s < 2; ++s) {
    CHECK(seeds.rows[s][0] == std::to_string(s + 1));
    CHECK(seeds.rows[s][1] == "nan");
    CHECK(seeds.rows[s][5] == "5");
    CHECK_THAT(seeds.rows[s][6], Catch::Contains("have not filled"));
  }
  const CsvTable pooled = read_csv(sweep / "critical_angle.csv");
  REQUIRE(pooled.rows.size() == 1);
  CHECK(pooled.rows[0][*pooled.column("seeds_found")] == "0 of 2");
  CHECK(pooled.rows[0][*pooled.column("theta_c_seed_stderr_deg")] == "nan");

  // The same points given as run directories, as if made one by one: one curve (their names and
  // apexes differ), the same verdict and the same reason.
  std::vector<std::filesystem::path> points;
  for (const auto& entry : std::filesystem::directory_iterator(sweep)) {
    if (std::filesystem::exists(entry.path() / kRunRecordFile)) points.push_back(entry.path());
  }
  std::sort(points.begin(), points.end());
  REQUIRE(points.size() == 10);
  std::ostringstream as_runs;
  REQUIRE(summarize_runs(points, RunHistoryOptions{}, as_runs, err) == kExitOk);
  INFO(as_runs.str());
  CHECK_THAT(as_runs.str(), Catch::Contains("these runs: not found (" +
                                            pooled.rows[0][*pooled.column("note")] + ")"));
  CHECK_THAT(as_runs.str(),
             Catch::Contains("each seed alone: 1: none, 2: none\n      seeds 1, 2: " +
                             seeds.rows[0][6] + "\n"));
}

TEST_CASE("a sweep with a bad point is refused before anything is written", "[runner][sweep]") {
  TempDirectory directory;
  write_file_atomically(directory / "tiny.yaml",
                        read_file(RODSORT_SOURCE_DIR "/tests/runner/data/tiny.yaml"));
  write_file_atomically(directory / "bad-sweep.yaml",
                        "base: tiny.yaml\ngrid:\n  - trap.angle: [60, 190]\n");
  SweepRequest request = tiny_sweep(directory / "sweep");
  request.sweep_file = directory / "bad-sweep.yaml";
  std::ostringstream out, err;
  CHECK(run_sweep(request, out, err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("trap.angle"));
  CHECK_FALSE(std::filesystem::exists(directory / "sweep"));
}

TEST_CASE("a dry run lists the points and writes nothing", "[runner][sweep]") {
  TempDirectory directory;
  SweepRequest request = tiny_sweep(directory / "sweep");
  request.dry_run = true;
  std::ostringstream out, err;
  CHECK(run_sweep(request, out, err) == kExitOk);
  CHECK_THAT(out.str(), Catch::Contains("2 points"));
  CHECK_THAT(out.str(), Catch::Contains("angle-40: to run"));
  CHECK_THAT(out.str(), Catch::Contains("angle-60: to run"));
  CHECK_FALSE(std::filesystem::exists(directory / "sweep"));
  // Each point's rods and cost, from the measured cost per rod and step: tiny.yaml is 4 rods for
  // 3500 steps, 4 x 3500 x (0.63 to 1.36) us = 0.0088 to 0.019 CPU-s.
  CHECK_THAT(out.str(), Catch::Contains("angle-40: to run (4 rods, about 0.0088-0.019 CPU-s)"));
  CHECK_THAT(out.str(), Catch::Contains("to run: about 0.018-0.038 CPU-s in all"));
}

TEST_CASE("a cost estimate scales with rods and steps, and rough plates cost more",
          "[runner][sweep]") {
  rodsort::engine::Model model;
  model.rods.resize(100);
  const CostEstimate flat = estimate_cost(model, 10000);
  CHECK(flat.low_cpu_s == Approx(100 * 10000 * kRodStepCostDispersed));
  CHECK(flat.high_cpu_s == Approx(100 * 10000 * kRodStepCostFilled));
  model.roughness.base_slope = 0.05;
  const CostEstimate rough = estimate_cost(model, 10000);
  // The roughness study's A at slope 0.05: 0.054 CPU-s per rod-second, 5.4 us per rod-step.
  CHECK(rough.low_cpu_s / (100 * 10000) == Approx(5.6e-6).epsilon(0.1));
  CHECK(describe_cost({90.0, 200.0}) == "about 1.5-3.3 CPU-min");
  CHECK(describe_cost({3.0 * 3600, 8.0 * 3600}) == "about 3-8 CPU-h");
  CHECK(describe_cost({3.1 * 3600, 3.1 * 3600}) == "about 3.1 CPU-h");
}

TEST_CASE("what runs have cost so far prices what is left of them", "[runner][sweep]") {
  // 1268 rods, 60 of 300 s at dt = 1e-4 in 2100 CPU-s: 35 CPU-s per simulated s.
  const auto own = cost_at_own_rate(600000, 3000000, 2100.0);
  REQUIRE(own.has_value());
  CHECK(own->low_cpu_s == Approx(35.0 * 240.0));
  CHECK(own->high_cpu_s == own->low_cpu_s);
  // Before a twentieth of the run the rate is its first moments' and is not used.
  CHECK_FALSE(cost_at_own_rate(149999, 3000000, 60.0).has_value());
  CHECK(cost_at_own_rate(150000, 3000000, 60.0).has_value());

  RunRecord record;
  record.rods = 1268;
  record.total_steps = 3000000;
  record.steps = 600000;
  record.cpu_s = 2100.0;
  RunRecord slower = record;
  slower.cpu_s = 2 * record.cpu_s;
  RunRecord early = record;
  early.steps = 1000;
  early.cpu_s = 1.0;
  const auto one_per_rod_step = record.cpu_s / (1268.0 * 600000.0);
  REQUIRE(measured_rod_step_cost(record).has_value());
  CHECK(*measured_rod_step_cost(record) == Approx(one_per_rod_step));
  CHECK_FALSE(measured_rod_step_cost(early).has_value());
  CHECK_FALSE(median_rod_step_cost({early}).has_value());
  const auto median = median_rod_step_cost({record, early, slower});
  REQUIRE(median.has_value());
  CHECK(median->runs == 2);
  CHECK(median->rod_step_cpu_s == Approx(1.5 * one_per_rod_step));
  CHECK(median_rod_step_cost({record, slower, slower})->rod_step_cpu_s ==
        Approx(2 * one_per_rod_step));
}

TEST_CASE("summarize refuses a directory that is not a sweep", "[runner][sweep]") {
  TempDirectory directory;
  std::ostringstream out, err;
  CHECK(summarize_sweep(directory.path(), out, err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("not a sweep directory"));
}

TEST_CASE("sweep --set applies to every point of a sweep but cannot change a swept key",
          "[runner][sweep]") {
  TempDirectory directory;
  SweepRequest request = tiny_sweep(directory / "sweep");
  request.dry_run = true;
  request.set_options = {"trap.angle=50"};
  std::ostringstream out, err;
  CHECK(run_sweep(request, out, err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("trap.angle"));
  CHECK_THAT(err.str(), Catch::Contains("is swept by the grid"));
  request.set_options = {"seed=11"};
  std::ostringstream out2, err2;
  CHECK(run_sweep(request, out2, err2) == kExitOk);
}

TEST_CASE("sweep --point runs one point of a sweep, by index or by name", "[runner][sweep]") {
  TempDirectory directory;
  const auto sweep = directory / "sweep";
  const std::filesystem::path scratch = directory / "scratch";
  std::filesystem::create_directories(scratch);
  const auto point = [&](const std::string& which) {
    return rodsort::runner::testing::run_rodsort(
        {"sweep", kTinySweep, "-o", sweep.string(), "--point", which}, scratch);
  };
  const auto second = point("1");
  INFO(second.out << second.err);
  CHECK(second.status == kExitOk);
  CHECK(read_run_record(sweep / "angle-60")->status == RunStatus::kComplete);
  CHECK_FALSE(std::filesystem::exists(sweep / "angle-40"));
  CHECK(point("angle-40").status == kExitOk);
  CHECK(read_run_record(sweep / "angle-40")->status == RunStatus::kComplete);
  const auto again = point("0");
  CHECK(again.status == kExitOk);
  CHECK_THAT(again.out, Catch::Contains("angle-40 is complete; nothing to do"));
  const auto missing = point("2");
  CHECK(missing.status == kExitUsage);
  CHECK_THAT(missing.err, Catch::Contains("no such point (give its index, 0 to 1, or its name)"));

  // One point continued beyond the sweep's duration holds another scenario: the whole sweep
  // refuses to touch it, --point still runs (or skips) the other one, and not the changed one.
  const auto longer = rodsort::runner::testing::run_rodsort(
      {"run", "--resume", (sweep / "angle-40").string(), "--duration", "0.49"}, scratch);
  REQUIRE(longer.status == kExitOk);
  std::filesystem::remove_all(sweep / "angle-60");
  const auto whole =
      rodsort::runner::testing::run_rodsort({"sweep", kTinySweep, "-o", sweep.string()}, scratch);
  CHECK(whole.status == kExitUsage);
  CHECK_THAT(whole.err, Catch::Contains("angle-40 holds a run of a different scenario"));
  CHECK_FALSE(std::filesystem::exists(sweep / "angle-60"));
  const auto other = point("angle-60");
  INFO(other.out << other.err);
  CHECK(other.status == kExitOk);
  CHECK(read_run_record(sweep / "angle-60")->status == RunStatus::kComplete);
  const auto plan = rodsort::runner::testing::run_rodsort(
      {"sweep", kTinySweep, "-o", sweep.string(), "--point", "1", "--dry-run"}, scratch);
  CHECK(plan.status == kExitOk);
  CHECK_THAT(plan.out, Catch::Contains("angle-40: holds another scenario, left alone"));
  CHECK_THAT(plan.out, Catch::Contains("angle-60: complete, skipped"));
  const auto changed = point("0");
  CHECK(changed.status == kExitUsage);
  CHECK_THAT(changed.err, Catch::Contains("angle-40 holds a run of a different scenario"));
  CHECK(read_run_record(sweep / "angle-40")->simulated_s == Approx(0.49));
}

TEST_CASE("sweep --slurm --no-submit writes a job array of the points still to run",
          "[runner][sweep]") {
  TempDirectory directory;
  const auto sweep = directory / "sweep";
  SweepRequest request = tiny_sweep(sweep);
  request.slurm.enabled = true;
  request.slurm.submit = false;
  request.slurm.partition = "short";
  request.slurm.time_limit = "2:00:00";
  request.slurm.memory = "1G";
  request.slurm.account = "lab";
  request.slurm.throttle = 3;
  request.slurm.extra_lines = {"--qos=long"};
  request.set_options = {"seed=11"};
  std::ostringstream out, err;
  REQUIRE(run_sweep(request, out, err) == kExitOk);
  CHECK_THAT(out.str(), Catch::Contains("2 of 2 points to run"));
  CHECK_THAT(out.str(), Catch::Contains("not submitted (--no-submit)"));
  const std::string script = read_file(sweep / "slurm" / "sweep.sbatch");
  for (const char* line :
       {"#SBATCH --array=0-1%3\n", "#SBATCH --partition=short\n", "#SBATCH --time=2:00:00\n",
        "#SBATCH --mem=1G\n", "#SBATCH --account=lab\n", "#SBATCH --qos=long\n",
        "#SBATCH --cpus-per-task=1\n", "#SBATCH --signal=B:TERM@300\n"}) {
    CHECK_THAT(script, Catch::Contains(line));
  }
  CHECK_THAT(script, Catch::Contains("--point \"$SLURM_ARRAY_TASK_ID\" --set seed=11\n"));
  CHECK_THAT(script,
             Catch::Contains("exec " + rodsort::runner::testing::kRodsortProgram + " sweep "));
  // The table lists the points before any has run.
  CHECK(read_csv(sweep / "sweep.csv").rows.size() == 2);

  // A point that a task of an earlier array is running is left to it.
  std::filesystem::create_directories(sweep / "angle-40");
  const auto held = RunLock::acquire(sweep / "angle-40");
  REQUIRE(held);
  std::ostringstream again;
  REQUIRE(run_sweep(request, again, err) == kExitOk);
  CHECK_THAT(again.str(), Catch::Contains("1 points are running now"));
  CHECK_THAT(again.str(), Catch::Contains("1 of 2 points to run"));
  CHECK_THAT(read_file(sweep / "slurm" / "sweep.sbatch"), Catch::Contains("#SBATCH --array=1%3\n"));
}

TEST_CASE("Slurm's array ranges and shell words", "[runner][sweep]") {
  CHECK(array_ranges({0, 1, 2, 3, 5, 7, 8, 9}) == "0-3,5,7-9");
  CHECK(array_ranges({4}) == "4");
  CHECK(shell_quote("/data/runs/fig2b") == "/data/runs/fig2b");
  CHECK(shell_quote("my runs/it's") == "'my runs/it'\\''s'");
  CHECK(shell_quote("") == "''");
}
