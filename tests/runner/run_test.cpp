#include "runner/run.hpp"

#include <catch2/catch.hpp>
#include <csignal>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "metrics/rods_csv.hpp"
#include "runner/atomic_file.hpp"
#include "runner/checkpoint.hpp"
#include "runner/cost_estimate.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_command.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_lock.hpp"
#include "runner/run_record.hpp"
#include "runner/version.hpp"
#include "scenarios/scenario.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::testing::TempDirectory;

namespace {

// tiny.yaml: 4 rods, 0.35 s at dt = 1e-4 (3500 steps); frames every 350 steps, trajectory every
// 700, checkpoints every 1050, a .bullet snapshot at 0.07 s.
const std::string kTiny = RODSORT_SOURCE_DIR "/tests/runner/data/tiny.yaml";
constexpr int kRods = 4;
constexpr int kFrames = 11;
constexpr int kTrajectoryFrames = 6;
constexpr int kSpheresPerRod = 12;

RunOptions silent() {
  RunOptions options;
  options.log = nullptr;
  return options;
}

/// Raises SIGINT after step 1234: the run stops at the next frame, step 1400, and writes a
/// checkpoint there.
RunOptions sigint_at_step_1234() {
  RunOptions options = silent();
  options.after_step = [](std::int64_t step) {
    if (step == 1234) std::raise(SIGINT);
  };
  return options;
}

/// Throws "simulated crash" after step 2000: the last checkpoint is then at step 1050, and frames
/// up to step 1750 are written.
RunOptions crash_at_step_2000() {
  RunOptions options = silent();
  options.after_step = [](std::int64_t step) {
    if (step == 2000) throw std::runtime_error("simulated crash");
  };
  return options;
}

int run_tiny(const std::filesystem::path& directory, RunOptions options = silent(),
             std::vector<std::string> set_options = {}) {
  RunRequest request;
  request.scenario = kTiny;
  request.set_options = std::move(set_options);
  request.output = directory;
  request.options = std::move(options);
  std::ostringstream err;
  const int status = run_scenario_file(request, err);
  INFO(err.str());
  return status;
}

std::vector<std::string> lines_of(const std::filesystem::path& path) {
  std::vector<std::string> lines;
  std::istringstream in(read_file(path));
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::size_t count_of(const std::vector<std::string>& lines, const std::string& text) {
  std::size_t count = 0;
  for (const std::string& line : lines) count += line == text;
  return count;
}

/// The outputs that must come out identical from the same scenario and seed.
void check_same_outputs(const std::filesystem::path& a, const std::filesystem::path& b) {
  for (const char* file : {kRodsCsvFile, kMetricsCsvFile, kTrajectoryFile}) {
    INFO(file);
    CHECK(read_file(a / file) == read_file(b / file));
  }
}

}  // namespace

TEST_CASE("a run writes every file of the run directory", "[runner][run]") {
  TempDirectory directory;
  const auto run = directory / "tiny";
  REQUIRE(run_tiny(run) == kExitOk);

  const auto rods = lines_of(run / kRodsCsvFile);
  REQUIRE(rods.size() == 1 + kFrames * kRods);
  CHECK(rods[0] == "t,rod,species,x,y,xu,yu,z,ux,uy,uz,vx,vy,vz,wz");
  const rodsort::metrics::RodsCsv read = rodsort::metrics::read_rods_csv(run / kRodsCsvFile);
  REQUIRE(read.error.empty());
  CHECK(read.warning.empty());
  REQUIRE(read.frames.size() == kFrames);
  CHECK(read.frames.back().time == Approx(0.35).margin(1e-9));

  const auto metrics = lines_of(run / kMetricsCsvFile);
  CHECK_THAT(metrics[0], Catch::StartsWith("t,eta,eta_trap,"));
  CHECK_THAT(metrics[0], Catch::Contains(",n_stationary,n_trap,"));
  CHECK_THAT(metrics[0], Catch::Contains(",eta_A,"));
  CHECK(metrics.size() == kFrames - 1);  // the first frame has no frame tau earlier

  const auto dump = lines_of(run / kTrajectoryFile);
  CHECK(count_of(dump, "ITEM: TIMESTEP") == kTrajectoryFrames);
  CHECK(count_of(dump, "ITEM: BOX BOUNDS pp pp ff") == kTrajectoryFrames);
  CHECK(count_of(dump, "ITEM: ATOMS id mol type x y z radius") == kTrajectoryFrames);
  CHECK(dump.size() == kTrajectoryFrames * (9 + kRods * kSpheresPerRod));
  CHECK(dump[3] == std::to_string(kRods * kSpheresPerRod));

  CHECK(std::filesystem::exists(run / snapshot_file_name(0.07)));
  // The trap's walls for a viewer: one snapshot of spheres along the two walls.
  const auto walls = lines_of(run / kWallsDumpFile);
  REQUIRE(walls.size() > 9);
  CHECK(walls[8] == "ITEM: ATOMS id mol type x y z radius");
  CHECK(walls.size() == 9 + std::stoul(walls[3]));
  CHECK(std::filesystem::exists(run / kCheckpointFile));

  const auto record = read_run_record(run);
  REQUIRE(record.has_value());
  CHECK(record->status == RunStatus::kComplete);
  CHECK(record->name == "tiny");
  CHECK(record->seed == 7);
  CHECK(record->rods == kRods);
  CHECK(record->steps == 3500);
  CHECK(record->total_steps == 3500);
  CHECK(record->simulated_s == Approx(0.35));
  CHECK(record->cpu_s > 0.0);
  CHECK(record->cpu_per_simulated_second() > 0.0);

  // The resolved scenario loads back as the same scenario.
  const auto reloaded = rodsort::scenarios::load_scenario(run / kResolvedScenarioFile);
  INFO(rodsort::scenarios::format_diagnostics(reloaded.diagnostics));
  REQUIRE(reloaded.ok());
  CHECK(reloaded.scenario->model.rods.size() == kRods);
}

TEST_CASE("the same scenario and seed give identical output files", "[runner][run]") {
  TempDirectory directory;
  REQUIRE(run_tiny(directory / "first") == kExitOk);
  REQUIRE(run_tiny(directory / "second") == kExitOk);
  check_same_outputs(directory / "first", directory / "second");
  REQUIRE(run_tiny(directory / "other-seed", silent(), {"seed=8"}) == kExitOk);
  CHECK(read_file(directory / "first" / kRodsCsvFile) !=
        read_file(directory / "other-seed" / kRodsCsvFile));
}

TEST_CASE("how often frames are written does not change the trajectory", "[runner][run]") {
  TempDirectory directory;
  REQUIRE(run_tiny(directory / "fine") == kExitOk);
  REQUIRE(run_tiny(directory / "coarse", silent(),
                   {"output.frame_interval=0.07", "output.checkpoint_interval=0.14"}) == kExitOk);
  // The trajectory is written every 0.07 s in both.
  CHECK(read_file(directory / "fine" / kTrajectoryFile) ==
        read_file(directory / "coarse" / kTrajectoryFile));
  // Every line of the coarse run's frames is in the fine run's, to the last digit.
  const auto fine = lines_of(directory / "fine" / kRodsCsvFile);
  const auto coarse = lines_of(directory / "coarse" / kRodsCsvFile);
  REQUIRE(coarse.size() == 1 + 6 * kRods);
  for (const std::string& line : coarse) {
    INFO(line);
    CHECK(count_of(fine, line) == 1);
  }
}

TEST_CASE("a run stopped by SIGINT resumes to exactly the same files", "[runner][run][resume]") {
  TempDirectory directory;
  REQUIRE(run_tiny(directory / "whole") == kExitOk);

  const auto stopped = directory / "stopped";
  REQUIRE(run_tiny(stopped, sigint_at_step_1234()) == kExitInterrupted);
  const auto record = read_run_record(stopped);
  REQUIRE(record.has_value());
  CHECK(record->status == RunStatus::kInterrupted);
  CHECK(record->steps == 1400);  // acted on at the next frame (frames every 350 steps)
  CHECK_THAT(record->message, Catch::Contains("SIGINT"));

  std::ostringstream err;
  RunOptions logged = silent();
  std::FILE* log = std::tmpfile();
  logged.log = log;
  REQUIRE(resume_run_directory(stopped, logged, err) == kExitOk);
  check_same_outputs(directory / "whole", stopped);
  // 1400 of 3500 steps, two fifths of the run: what is left is costed at the run's own rate.
  std::rewind(log);
  char line[512] = {};
  REQUIRE(std::fgets(line, sizeof line, log) != nullptr);
  std::fclose(log);
  CHECK_THAT(std::string(line),
             Catch::StartsWith("rodsort: resuming tiny at t = 0.14 s of 0.35 s"));
  double left_cpu_s = 0.0;
  const char* about = std::strstr(line, "; about ");
  REQUIRE(about != nullptr);
  REQUIRE(std::sscanf(about, "; about %lf CPU-s left, at its own rate so far", &left_cpu_s) == 1);
  // The checkpoint's CPU time, a moment before run.json's, and two digits.
  CHECK(left_cpu_s == Approx(record->cpu_s / 1400 * 2100).epsilon(0.2));
  CHECK_THAT(std::string(line), Catch::EndsWith(" CPU-s left, at its own rate so far\n"));
  const auto resumed = read_run_record(stopped);
  CHECK(resumed->status == RunStatus::kComplete);
  CHECK(resumed->sessions == 2);
  CHECK(resumed->steps == 3500);
}

TEST_CASE("a resumed run has the frames its held count looks back to", "[runner][run][resume]") {
  // Held over 0.21 s: the resumed observer needs the frame at 0 s again for its row at 0.21 s,
  // further back than the window (0.07 s) and a frame.
  const std::vector<std::string> lag = {"metrics.held_lag=0.21"};
  TempDirectory directory;
  REQUIRE(run_tiny(directory / "whole", silent(), lag) == kExitOk);
  const auto metrics = lines_of(directory / "whole" / kMetricsCsvFile);
  REQUIRE(metrics.size() == kFrames - 1);
  CHECK_THAT(metrics[0],
             Catch::EndsWith(",n_held_trap,n_held_trap_A,fraction_held_A,purity_held_A"));
  // t = 0.21 s is the first row with a frame 0.21 s earlier.
  CHECK_THAT(metrics[4], Catch::StartsWith("0.175,"));
  CHECK_THAT(metrics[4], Catch::EndsWith(",nan,nan,nan,nan"));
  CHECK_THAT(metrics[5], Catch::StartsWith("0.21,"));
  CHECK_THAT(metrics[5], !Catch::EndsWith(",nan,nan,nan,nan"));

  const auto stopped = directory / "stopped";
  REQUIRE(run_tiny(stopped, sigint_at_step_1234(), lag) == kExitInterrupted);
  std::ostringstream err;
  REQUIRE(resume_run_directory(stopped, silent(), err) == kExitOk);
  check_same_outputs(directory / "whole", stopped);
}

TEST_CASE("a run whose metrics.csv has other columns is not resumed", "[runner][run][resume]") {
  TempDirectory directory;
  const auto stopped = directory / "stopped";
  REQUIRE(run_tiny(stopped, sigint_at_step_1234()) == kExitInterrupted);
  // As an older build wrote it, without the held columns.
  std::string text = read_file(stopped / kMetricsCsvFile);
  const std::size_t at = text.find(",n_held_trap,");
  REQUIRE(at != std::string::npos);
  text.erase(at, text.find('\n') - at);
  write_file_atomically(stopped / kMetricsCsvFile, text);
  const std::string record_before = read_file(stopped / kRunRecordFile);
  const std::string rods_before = read_file(stopped / kRodsCsvFile);
  std::ostringstream err;
  CHECK_THROWS_WITH(resume_run_directory(stopped, silent(), err),
                    Catch::Contains("has other columns than this build writes"));
  CHECK(read_file(stopped / kMetricsCsvFile) == text);
  CHECK(read_file(stopped / kRodsCsvFile) == rods_before);
  CHECK(read_file(stopped / kRunRecordFile) == record_before);
}

TEST_CASE("a run that died after its checkpoint is cut back and resumed exactly",
          "[runner][run][resume]") {
  TempDirectory directory;
  REQUIRE(run_tiny(directory / "whole") == kExitOk);

  // Dies at step 2000: the last checkpoint is at step 1050, but frames up to step 1750 are written.
  const auto crashed = directory / "crashed";
  const RunOptions crash = crash_at_step_2000();
  CHECK_THROWS_WITH(run_tiny(crashed, crash), "simulated crash");
  const auto record = read_run_record(crashed);
  REQUIRE(record.has_value());
  CHECK(record->status == RunStatus::kFailed);
  CHECK(record->message == "simulated crash");
  CHECK(lines_of(crashed / kRodsCsvFile).size() == 1 + 6 * kRods);

  std::ostringstream err;
  REQUIRE(resume_run_directory(crashed, silent(), err) == kExitOk);
  check_same_outputs(directory / "whole", crashed);
}

TEST_CASE("a refused scenario writes nothing", "[runner][run]") {
  TempDirectory directory;
  const auto run = directory / "refused";
  RunRequest request;
  request.scenario = kTiny;
  request.set_options = {"trap.angle=190"};
  request.output = run;
  request.options = silent();
  std::ostringstream err;
  CHECK(run_scenario_file(request, err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("trap.angle"));
  CHECK_THAT(err.str(), Catch::Contains("nothing was written"));
  CHECK_FALSE(std::filesystem::exists(run));
}

TEST_CASE("a directory that holds a run is kept unless forced", "[runner][run]") {
  TempDirectory directory;
  const auto run = directory / "tiny";
  REQUIRE(run_tiny(run) == kExitOk);
  const std::string before = read_file(run / kRodsCsvFile);

  RunRequest request;
  request.scenario = kTiny;
  request.set_options = {"seed=8"};
  request.output = run;
  request.options = silent();
  std::ostringstream err;
  CHECK(run_scenario_file(request, err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("already holds a run of 'tiny' (complete"));
  CHECK_THAT(err.str(), Catch::Contains("--resume"));
  CHECK_THAT(err.str(), Catch::Contains("--force"));
  CHECK(read_file(run / kRodsCsvFile) == before);

  request.force = true;
  CHECK(run_scenario_file(request, err) == kExitOk);
  CHECK(read_file(run / kRodsCsvFile) != before);
  CHECK(read_run_record(run)->seed == 8);
}

TEST_CASE("resuming a complete run changes nothing", "[runner][run][resume]") {
  TempDirectory directory;
  const auto run = directory / "tiny";
  REQUIRE(run_tiny(run) == kExitOk);
  const std::string before = read_file(run / kRodsCsvFile);
  std::ostringstream err;
  CHECK(resume_run_directory(run, silent(), err) == kExitOk);
  CHECK_THAT(err.str(), Catch::Contains("already complete"));
  CHECK(read_file(run / kRodsCsvFile) == before);
  CHECK(resume_run_directory(directory / "nothing", silent(), err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("holds no run to resume"));
}

TEST_CASE("one process at a time runs in a run directory", "[runner][run]") {
  TempDirectory directory;
  const auto run = directory / "tiny";
  REQUIRE(run_tiny(run) == kExitOk);
  const auto held = RunLock::acquire(run);
  REQUIRE(held.has_value());
  std::ostringstream err;
  CHECK(resume_run_directory(run, silent(), err) == kExitFailure);
  RunRequest request;
  request.scenario = kTiny;
  request.output = run;
  request.force = true;
  request.options = silent();
  CHECK(run_scenario_file(request, err) == kExitFailure);
  CHECK_THAT(err.str(), Catch::Contains("another process is running in"));
  CHECK(read_run_record(run)->status == RunStatus::kComplete);
}

TEST_CASE("an edited resolved scenario is refused on resume, not run", "[runner][run][resume]") {
  TempDirectory directory;
  const auto crashed = directory / "crashed";
  const RunOptions crash = crash_at_step_2000();
  CHECK_THROWS(run_tiny(crashed, crash));
  // A shorter run, still a valid scenario: resuming it would end early with exit 0.
  const auto resolved = crashed / kResolvedScenarioFile;
  std::string text = read_file(resolved);
  const std::size_t at = text.find("duration: 0.35");
  REQUIRE(at != std::string::npos);
  text.replace(at, 14, "duration: 0.28");
  write_file_atomically(resolved, text);
  const std::string rods_before = read_file(crashed / kRodsCsvFile);
  const std::string record_before = read_file(crashed / kRunRecordFile);
  std::ostringstream err;
  CHECK_THROWS_WITH(resume_run_directory(crashed, silent(), err),
                    Catch::Contains("has changed since the run wrote it"));
  CHECK(read_file(crashed / kRodsCsvFile) == rods_before);
  CHECK(read_file(crashed / kRunRecordFile) == record_before);
  // Continued to a longer duration, it is refused before the edited file is rewritten.
  CHECK_THROWS_WITH(resume_run_directory(crashed, silent(), err, 0.7),
                    Catch::Contains("has changed since the run wrote it"));
  CHECK(read_file(resolved) == text);
  CHECK(read_file(crashed / kRunRecordFile) == record_before);
}

TEST_CASE("a checkpoint of another build is resumed only when asked to", "[runner][run][resume]") {
  TempDirectory directory;
  REQUIRE(run_tiny(directory / "whole") == kExitOk);
  const auto crashed = directory / "crashed";
  REQUIRE(run_tiny(crashed, sigint_at_step_1234()) == kExitInterrupted);
  Checkpoint checkpoint = read_checkpoint(crashed / kCheckpointFile);
  CHECK(checkpoint.build == build_identity());
  CHECK_THAT(checkpoint.build, Catch::Contains("rodsort ") && Catch::Contains(", executable "));
  checkpoint.build = "rodsort 0.0.1, another build";
  write_checkpoint(crashed / kCheckpointFile, checkpoint);
  const std::string rods_before = read_file(crashed / kRodsCsvFile);
  const std::string record_before = read_file(crashed / kRunRecordFile);

  std::ostringstream err;
  CHECK_THROWS_WITH(resume_run_directory(crashed, silent(), err),
                    Catch::Contains("written by another build of rodsort (rodsort 0.0.1, another "
                                    "build) than this one (" +
                                    build_identity() + ")") &&
                        Catch::Contains("--any-build"));
  // Refused, the run keeps its record: still interrupted at its checkpoint, resumable.
  CHECK(read_file(crashed / kRodsCsvFile) == rods_before);
  CHECK(read_file(crashed / kRunRecordFile) == record_before);
  CHECK(read_run_record(crashed)->status == RunStatus::kInterrupted);
  // Continued to a longer duration, it is refused before its scenario is rewritten.
  const std::string resolved_before = read_file(crashed / kResolvedScenarioFile);
  CHECK_THROWS_WITH(resume_run_directory(crashed, silent(), err, 0.7),
                    Catch::Contains("written by another build of rodsort"));
  CHECK(read_file(crashed / kResolvedScenarioFile) == resolved_before);
  CHECK(read_file(crashed / kRunRecordFile) == record_before);

  // Asked to, it continues; with the same physics in this test the files come out the same.
  RunOptions any_build = silent();
  any_build.any_build = true;
  REQUIRE(resume_run_directory(crashed, any_build, err) == kExitOk);
  check_same_outputs(directory / "whole", crashed);
  CHECK(read_checkpoint(crashed / kCheckpointFile).build == build_identity());
}

TEST_CASE("a complete run continued to a longer duration equals a run of that duration",
          "[runner][run][resume]") {
  TempDirectory directory;
  REQUIRE(run_tiny(directory / "whole") == kExitOk);
  const auto shorter = directory / "shorter";
  REQUIRE(run_tiny(shorter, silent(), {"run.duration=0.21"}) == kExitOk);
  REQUIRE(read_run_record(shorter)->status == RunStatus::kComplete);

  std::ostringstream err;
  // Not before the time it has reached; nothing changes.
  const std::string resolved_before = read_file(shorter / kResolvedScenarioFile);
  CHECK(resume_run_directory(shorter, silent(), err, 0.14) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("has already reached t = 0.21 s"));
  // Nor to a time the scenario's checks refuse.
  CHECK(resume_run_directory(shorter, silent(), err, 1e9) == kExitUsage);
  CHECK(read_file(shorter / kResolvedScenarioFile) == resolved_before);

  REQUIRE(resume_run_directory(shorter, silent(), err, 0.35) == kExitOk);
  INFO(err.str());
  check_same_outputs(directory / "whole", shorter);
  const auto record = read_run_record(shorter);
  CHECK(record->status == RunStatus::kComplete);
  CHECK(record->duration_s == Approx(0.35));
  CHECK(record->sessions == 2);
  CHECK_THAT(read_file(shorter / kResolvedScenarioFile), Catch::Contains("duration: 0.35"));
}

TEST_CASE("a run ends with a frame at its end, which a longer continuation leaves out",
          "[runner][run][resume]") {
  TempDirectory directory;
  REQUIRE(run_tiny(directory / "whole") == kExitOk);
  // 0.2 s is not a whole number of frames (0.035 s) or trajectory frames (0.07 s).
  const auto shorter = directory / "shorter";
  REQUIRE(run_tiny(shorter, silent(), {"run.duration=0.2"}) == kExitOk);
  const auto frames = rodsort::metrics::read_rods_csv(shorter / kRodsCsvFile);
  REQUIRE(frames.error.empty());
  CHECK(frames.frames.size() == 7);  // 0, 0.035, ..., 0.175, and 0.2
  CHECK(frames.frames.back().time == Approx(0.2).margin(1e-12));
  const std::string dump = read_file(shorter / kTrajectoryFile);
  CHECK(dump.substr(dump.rfind("ITEM: TIMESTEP\n")).rfind("ITEM: TIMESTEP\n2000\n", 0) == 0);
  const CsvTable metrics = read_csv(shorter / kMetricsCsvFile);
  CHECK(metrics.numbers(*metrics.column("t")).back() == Approx(0.2).margin(1e-12));

  std::ostringstream err;
  REQUIRE(resume_run_directory(shorter, silent(), err, 0.35) == kExitOk);
  INFO(err.str());
  check_same_outputs(directory / "whole", shorter);
}

TEST_CASE("resuming a directory without a run leaves it as it was", "[runner][run][resume]") {
  TempDirectory directory;
  const auto empty = directory / "empty";
  std::filesystem::create_directories(empty);
  std::ostringstream err;
  CHECK(resume_run_directory(empty, silent(), err) == kExitUsage);
  CHECK_THAT(err.str(), Catch::Contains("holds no run to resume"));
  CHECK(std::filesystem::is_empty(empty));
}

TEST_CASE("a damaged frame read back on resume is named at its line of rods.csv",
          "[runner][run][resume]") {
  TempDirectory directory;
  const auto crashed = directory / "crashed";
  const RunOptions crash = crash_at_step_2000();
  CHECK_THROWS(run_tiny(crashed, crash));
  // The checkpoint at step 1050 keeps the header and four frames of four rods: lines 1-17. The
  // last of them, read back to refill the metrics' window, gets a word for a number.
  std::vector<std::string> lines = lines_of(crashed / kRodsCsvFile);
  REQUIRE(lines.size() > 17);
  lines[16].replace(lines[16].rfind(',') + 1, std::string::npos, "oops");
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  write_file_atomically(crashed / kRodsCsvFile, text);
  std::ostringstream err;
  CHECK_THROWS_WITH(resume_run_directory(crashed, silent(), err), Catch::Contains("rods.csv:17:"));
  // The failure is recorded with the run's progress at its checkpoint, not from zero.
  const auto record = read_run_record(crashed);
  REQUIRE(record.has_value());
  CHECK(record->status == RunStatus::kFailed);
  CHECK_THAT(record->message, Catch::Contains("rods.csv:17:"));
  CHECK(record->steps == 1050);
  CHECK(record->sessions == 2);
  CHECK(record->wall_s < 600.0);
}
