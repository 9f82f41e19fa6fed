// The rodsort program as a user meets it: help, exit codes, messages, and a run stopped by a real
// signal and resumed.

#include <catch2/catch.hpp>
#include <csignal>
#include <string>
#include <thread>
#include <vector>

#include "metrics/rods_csv.hpp"
#include "rodsort_program.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_record.hpp"
#include "runner/run_summary.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::runner::testing::run_rodsort;
using rodsort::testing::TempDirectory;

namespace {

const std::string kTiny = RODSORT_SOURCE_DIR "/tests/runner/data/tiny.yaml";

/// Starts a 10 s run of the tiny scenario in `run` and returns its process once its first frames
/// are on disk: long enough that it is still running then.
pid_t start_tiny_run(const TempDirectory& scratch, const std::filesystem::path& run) {
  const pid_t pid = rodsort::runner::testing::start_rodsort(
      {"run", kTiny, "-o", run.string(), "--set", "run.duration=10", "--set",
       "output.checkpoint_interval=5"},
      scratch / "out.txt", scratch / "err.txt");
  const auto rods = run / kRodsCsvFile;
  while (!std::filesystem::exists(rods) || std::filesystem::file_size(rods) < 2000) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return pid;
}

}  // namespace

TEST_CASE("every subcommand has help", "[runner][cli]") {
  TempDirectory scratch;
  const auto top = run_rodsort({"--help"}, scratch.path());
  CHECK(top.status == kExitOk);
  CHECK_THAT(top.out, Catch::Contains("130"));  // the exit codes are documented
  for (const char* command : {"run", "validate", "sweep", "analyze", "summarize"}) {
    INFO(command);
    const auto help = run_rodsort({command, "--help"}, scratch.path());
    CHECK(help.status == kExitOk);
    CHECK_THAT(help.out, Catch::Contains(std::string("rodsort ") + command));
  }
}

TEST_CASE("bad arguments exit with status 2", "[runner][cli]") {
  TempDirectory scratch;
  CHECK(run_rodsort({}, scratch.path()).status == kExitUsage);
  CHECK(run_rodsort({"frobnicate"}, scratch.path()).status == kExitUsage);
  const auto no_scenario = run_rodsort({"run"}, scratch.path());
  CHECK(no_scenario.status == kExitUsage);
  CHECK_THAT(no_scenario.err, Catch::Contains("SCENARIO"));
  CHECK(run_rodsort({"run", "missing.yaml"}, scratch.path()).status == kExitUsage);
  CHECK(run_rodsort({"run", kTiny, "--resume", scratch.path().string()}, scratch.path()).status ==
        kExitUsage);
  // A refused number is named with its bound in a line, not a 309-digit range.
  const auto no_jobs = run_rodsort({"sweep", kTiny, "-j", "0"}, scratch.path());
  CHECK(no_jobs.status == kExitUsage);
  CHECK_THAT(no_jobs.err, Catch::Contains("--jobs: Value 0 not in range 1 to 1024"));
  const auto negative = run_rodsort({"single", kTiny, "--duration", "-1"}, scratch.path());
  CHECK(negative.status == kExitUsage);
  CHECK_THAT(negative.err, Catch::Contains("--duration: expected a number > 0, got -1"));
  CHECK(negative.err.size() < 200);
}

TEST_CASE("validate prints the resolved scenario, or the errors", "[runner][cli]") {
  TempDirectory scratch;
  const auto valid = run_rodsort({"validate", kTiny}, scratch.path());
  CHECK(valid.status == kExitOk);
  CHECK_THAT(valid.out, Catch::Contains("name: tiny"));
  CHECK_THAT(valid.out, Catch::Contains("frame_interval: 0.035"));
  const auto refused = run_rodsort(
      {"validate", kTiny, "--set", "trap.angle=190", "--set", "run.dt=-1"}, scratch.path());
  CHECK(refused.status == kExitUsage);
  CHECK(refused.out.empty());
  CHECK_THAT(refused.err, Catch::Contains("--set trap.angle=190"));
  CHECK_THAT(refused.err, Catch::Contains("run.dt"));
  CHECK_THAT(refused.err, Catch::Contains("2 errors"));
}

TEST_CASE("a run stopped by SIGINT exits 130 and resumes to completion", "[runner][cli]") {
  TempDirectory scratch;
  const auto run = scratch / "run";
  const pid_t pid = start_tiny_run(scratch, run);
  kill(pid, SIGINT);
  REQUIRE(rodsort::runner::testing::wait_rodsort(pid) == kExitInterrupted);
  const auto stopped = read_run_record(run);
  REQUIRE(stopped.has_value());
  CHECK(stopped->status == RunStatus::kInterrupted);
  CHECK(stopped->simulated_s < 10.0);
  CHECK_THAT(read_file(scratch / "err.txt"), Catch::Contains("rodsort run --resume"));

  const auto resumed = run_rodsort({"run", "--resume", run.string(), "-q"}, scratch.path());
  CHECK(resumed.status == kExitOk);
  const auto done = read_run_record(run);
  CHECK(done->status == RunStatus::kComplete);
  CHECK(done->steps == 100000);
  CHECK(done->sessions == 2);
}

TEST_CASE("a run sent SIGTERM twice at once, as timeout does, still writes its checkpoint",
          "[runner][cli]") {
  TempDirectory scratch;
  const auto run = scratch / "run";
  const pid_t pid = start_tiny_run(scratch, run);
  // The child and then its process group: the second copy comes while the first is handled.
  kill(pid, SIGTERM);
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, SIGTERM);
  REQUIRE(rodsort::runner::testing::wait_rodsort(pid) == kExitInterrupted);
  const auto stopped = read_run_record(run);
  REQUIRE(stopped.has_value());
  CHECK(stopped->status == RunStatus::kInterrupted);
  CHECK_THAT(read_file(scratch / "err.txt"), Catch::Contains("stopped by SIGTERM"));
}

TEST_CASE("a run killed with SIGKILL leaves readable files and resumes", "[runner][cli]") {
  TempDirectory scratch;
  const auto run = scratch / "run";
  const pid_t pid = rodsort::runner::testing::start_rodsort(
      {"run", kTiny, "-o", run.string(), "--set", "run.duration=6", "--set",
       "output.checkpoint_interval=0.7"},
      scratch / "out.txt", scratch / "err.txt");
  // Kill it once it has checkpointed past t = 0 and written frames after that checkpoint.
  std::int64_t checkpointed_steps = 0;
  while (checkpointed_steps == 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    const auto record = read_run_record(run);
    if (record && record->steps > 0) checkpointed_steps = record->steps;
  }
  const auto rods = run / kRodsCsvFile;
  const auto size_at_checkpoint = std::filesystem::file_size(rods);
  while (std::filesystem::file_size(rods) < size_at_checkpoint + 2000) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, SIGKILL);
  REQUIRE(rodsort::runner::testing::wait_rodsort(pid) == 128 + SIGKILL);

  const auto killed = read_run_record(run);
  REQUIRE(killed.has_value());
  CHECK(killed->status == RunStatus::kRunning);  // it had no chance to say otherwise
  // ... but no process holds the run any more, and its summary (sweep.csv, summarize) says so.
  CHECK(rodsort::runner::summarize_run(run).status == "stopped");
  const auto frames = rodsort::metrics::read_rods_csv(rods);
  CHECK(frames.error.empty());
  CHECK(frames.frames.size() >= 2);
  CHECK_NOTHROW(read_csv(run / kMetricsCsvFile));

  const auto resumed = run_rodsort({"run", "--resume", run.string(), "-q"}, scratch.path());
  CHECK(resumed.status == kExitOk);
  const auto after = rodsort::metrics::read_rods_csv(rods);
  REQUIRE(after.error.empty());
  CHECK(after.warning.empty());
  // Frames every 350 steps of 1e-4 s up to 6 s: steps 0, 350, ..., 59850, each once, and the
  // run's last step, t = 6 s.
  REQUIRE(after.frames.size() == 173);
  for (std::size_t f = 0; f + 1 < after.frames.size(); ++f) {
    CHECK(after.frames[f].time == Approx(0.035 * static_cast<double>(f)).margin(1e-9));
  }
  CHECK(after.frames.back().time == Approx(6.0).margin(1e-9));
  CHECK(read_run_record(run)->status == RunStatus::kComplete);

  // And it is the same run as one never stopped.
  const auto whole = scratch / "whole";
  REQUIRE(run_rodsort({"run", kTiny, "-o", whole.string(), "-q", "--set", "run.duration=6", "--set",
                       "output.checkpoint_interval=0.7"},
                      scratch.path())
              .status == kExitOk);
  for (const char* file : {kRodsCsvFile, kMetricsCsvFile, kTrajectoryFile}) {
    INFO(file);
    CHECK(read_file(whole / file) == read_file(run / file));
  }
}

TEST_CASE("a sweep file given to run, or a scenario given to sweep, gets a hint", "[runner][cli]") {
  TempDirectory scratch;
  const std::string sweep = RODSORT_SOURCE_DIR "/tests/runner/data/tiny-sweep.yaml";
  const auto validated = run_rodsort({"validate", sweep}, scratch.path());
  CHECK(validated.status == kExitUsage);
  CHECK_THAT(validated.err, Catch::Contains("looks like a sweep file"));
  const auto swept = run_rodsort({"sweep", kTiny, "--dry-run"}, scratch.path());
  CHECK(swept.status == kExitUsage);
  CHECK_THAT(swept.err, Catch::Contains("looks like a scenario"));
}

TEST_CASE("a warning about the scenario is printed by run, not again by render and analyze",
          "[runner][cli]") {
  TempDirectory scratch;
  const auto run = scratch / "run";
  const auto ran = run_rodsort({"run", kTiny, "-o", run.string(), "-q", "--set",
                                "output.frame_interval=0.03505", "--set", "run.duration=0.14"},
                               scratch.path());
  REQUIRE(ran.status == kExitOk);
  CHECK_THAT(ran.err, Catch::Contains("warning: ") && Catch::Contains("not a multiple of run.dt"));
  const auto analyzed = run_rodsort({"analyze", run.string()}, scratch.path());
  CHECK(analyzed.status == kExitOk);
  CHECK_THAT(analyzed.err, !Catch::Contains("warning"));
  const auto rendered =
      run_rodsort({"render", run.string(), "-o", (scratch / "pictures").string()}, scratch.path());
  CHECK(rendered.status == kExitOk);
  CHECK_THAT(rendered.err, !Catch::Contains("warning"));
  // A warning of analyze's own --set is new, and said.
  const auto reanalyzed = run_rodsort({"analyze", run.string(), "--set", "metrics.window=0.09",
                                       "-o", (scratch / "again.csv").string()},
                                      scratch.path());
  CHECK_THAT(reanalyzed.err, Catch::Contains("--set metrics.window=0.09: warning") &&
                                 Catch::Contains("over 3 frame intervals (0.10515 s)"));
}

TEST_CASE("sweep takes --set before its sweep file, and --status without one", "[runner][cli]") {
  TempDirectory scratch;
  const std::string sweep = RODSORT_SOURCE_DIR "/tests/runner/data/tiny-sweep.yaml";
  const auto planned = run_rodsort({"sweep", "--set", "run.duration=0.42", sweep, "--dry-run", "-o",
                                    (scratch / "sweep").string()},
                                   scratch.path());
  INFO(planned.err);
  CHECK(planned.status == kExitOk);
  CHECK_THAT(planned.out, Catch::Contains("angle-40: to run (4 rods"));
  const auto both =
      run_rodsort({"sweep", sweep, "--status", scratch.path().string()}, scratch.path());
  CHECK(both.status == kExitUsage);
  CHECK_THAT(both.err, Catch::Contains("takes no SWEEP"));
  const auto no_sweep = run_rodsort({"sweep", "--status", scratch.path().string()}, scratch.path());
  CHECK(no_sweep.status == kExitUsage);
  CHECK_THAT(no_sweep.err, Catch::Contains("holds no sweep (no sweep.csv)"));
}
