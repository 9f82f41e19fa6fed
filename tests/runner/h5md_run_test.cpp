// rods.h5 as a run writes it: the metrics are computed from it exactly, a run killed at any moment
// leaves it readable, and a resumed run's frames are those of a run never stopped.

#include <catch2/catch.hpp>
#include <csignal>
#include <thread>

#include "metrics/rods_csv.hpp"
#include "metrics/rods_h5md.hpp"
#include "rodsort_program.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_directory.hpp"
#include "runner/run_record.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::engine::Frame;
using rodsort::runner::testing::run_rodsort;
using rodsort::testing::TempDirectory;

namespace {

const std::string kTiny = RODSORT_SOURCE_DIR "/tests/runner/data/tiny.yaml";

std::vector<Frame> read_h5md(const std::filesystem::path& path, std::string* warning = nullptr) {
  rodsort::metrics::RodsH5mdReader reader(path, {"A"});
  std::vector<Frame> frames;
  Frame frame;
  while (reader.next(frame)) frames.push_back(frame);
  REQUIRE(reader.error().empty());
  if (warning != nullptr) *warning = reader.warning();
  return frames;
}

void require_same_frames(const std::vector<Frame>& a, const std::vector<Frame>& b) {
  REQUIRE(a.size() == b.size());
  for (std::size_t f = 0; f < a.size(); ++f) {
    REQUIRE(a[f].time == b[f].time);
    REQUIRE(a[f].rods.size() == b[f].rods.size());
    for (std::size_t i = 0; i < a[f].rods.size(); ++i) {
      REQUIRE(a[f].rods[i].unwrapped == b[f].rods[i].unwrapped);
      REQUIRE(a[f].rods[i].axis == b[f].rods[i].axis);
      REQUIRE(a[f].rods[i].velocity == b[f].rods[i].velocity);
    }
  }
}

}  // namespace

TEST_CASE("a run killed with SIGKILL leaves a readable rods.h5 and resumes exactly",
          "[runner][h5md]") {
  TempDirectory scratch;
  const std::vector<std::string> settings = {"--set", "run.duration=6",
                                             "--set", "output.checkpoint_interval=0.7",
                                             "--set", "output.rods_format=h5md"};
  const auto whole = scratch / "whole";
  std::vector<std::string> arguments = {"run", kTiny, "-o", whole.string(), "-q"};
  arguments.insert(arguments.end(), settings.begin(), settings.end());
  REQUIRE(run_rodsort(arguments, scratch.path()).status == kExitOk);
  CHECK_FALSE(std::filesystem::exists(whole / kRodsCsvFile));
  const std::vector<Frame> reference = read_h5md(whole / kRodsH5mdFile);
  // Frames every 350 steps of 1e-4 s to 6 s, and the run's last step.
  REQUIRE(reference.size() == 173);
  CHECK(reference.back().time == Approx(6.0).margin(1e-9));

  // `analyze` computes from rods.h5 exactly the rows the run wrote.
  const auto analyzed = scratch / "analyzed.csv";
  REQUIRE(
      run_rodsort({"analyze", whole.string(), "-o", analyzed.string()}, scratch.path()).status ==
      kExitOk);
  CHECK(read_file(analyzed) == read_file(whole / kMetricsCsvFile));

  // Killed at several moments, between and during its writes.
  for (const int after_steps : {7000, 21000, 38500}) {
    INFO("killed after step " << after_steps);
    const auto run = scratch / ("run-" + std::to_string(after_steps));
    std::vector<std::string> start = {"run", kTiny, "-o", run.string()};
    start.insert(start.end(), settings.begin(), settings.end());
    const pid_t pid =
        rodsort::runner::testing::start_rodsort(start, scratch / "out.txt", scratch / "err.txt");
    while (true) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      const auto record = read_run_record(run);
      if (record && record->steps >= after_steps) break;
    }
    kill(pid, SIGKILL);
    REQUIRE(rodsort::runner::testing::wait_rodsort(pid) == 128 + SIGKILL);
    const std::vector<Frame> left = read_h5md(run / kRodsH5mdFile);
    CHECK(left.size() >= static_cast<std::size_t>(after_steps / 350));
    // What it holds is the beginning of the whole run.
    require_same_frames(
        left,
        std::vector<Frame>(reference.begin(), reference.begin() + static_cast<long>(left.size())));

    REQUIRE(run_rodsort({"run", "--resume", run.string(), "-q"}, scratch.path()).status == kExitOk);
    require_same_frames(read_h5md(run / kRodsH5mdFile), reference);
    CHECK(read_file(run / kMetricsCsvFile) == read_file(whole / kMetricsCsvFile));
  }
}

TEST_CASE(
    "rods_format both writes the same frames twice, and render, analyze and plot read rods.h5",
    "[runner][h5md]") {
  TempDirectory scratch;
  const auto run = scratch / "run";
  REQUIRE(run_rodsort({"run", kTiny, "-o", run.string(), "-q", "--set", "output.rods_format=both"},
                      scratch.path())
              .status == kExitOk);
  const auto csv = rodsort::metrics::read_rods_csv(run / kRodsCsvFile);
  REQUIRE(csv.error.empty());
  const std::vector<Frame> h5 = read_h5md(run / kRodsH5mdFile);
  REQUIRE(h5.size() == csv.frames.size());
  for (std::size_t f = 0; f < h5.size(); ++f) {
    CHECK(h5[f].time == Approx(csv.frames[f].time).margin(1e-9));
    for (std::size_t i = 0; i < h5[f].rods.size(); ++i) {
      // Single precision against 9 significant digits.
      CHECK((h5[f].rods[i].unwrapped - csv.frames[f].rods[i].unwrapped).norm() < 1e-5);
      CHECK((h5[f].rods[i].axis - csv.frames[f].rods[i].axis).norm() < 1e-6);
      CHECK((h5[f].rods[i].velocity - csv.frames[f].rods[i].velocity).norm() <
            1e-6 * (1.0 + csv.frames[f].rods[i].velocity.norm()));
    }
  }

  // Without rods.csv, render and analyze take rods.h5.
  std::filesystem::remove(run / kRodsCsvFile);
  const auto rendered =
      run_rodsort({"render", run.string(), "--at", "0.35", "-o", (scratch / "pictures").string()},
                  scratch.path());
  CHECK(rendered.status == kExitOk);
  CHECK(std::filesystem::exists(scratch / "pictures" / "frame-t0.35.png"));
  const auto analyzed = run_rodsort(
      {"analyze", run.string(), "-o", (scratch / "metrics.csv").string()}, scratch.path());
  CHECK(analyzed.status == kExitOk);
  CHECK_THAT(analyzed.err, Catch::Contains("rods.h5"));
  const auto plotted =
      run_rodsort({"plot", run.string(), "--what", "dtheta", "-o", (scratch / "plots").string()},
                  scratch.path());
  CHECK(plotted.status == kExitOk);
  CHECK(std::filesystem::exists(scratch / "plots" / "dtheta.png"));
}

TEST_CASE("convert writes a stopped run's rods.csv into rods.h5", "[runner][h5md]") {
  TempDirectory scratch;
  const auto run = scratch / "run";
  REQUIRE(run_rodsort({"run", kTiny, "-o", run.string(), "-q"}, scratch.path()).status == kExitOk);
  CHECK_FALSE(std::filesystem::exists(run / kRodsH5mdFile));
  const auto converted = run_rodsort({"convert", run.string()}, scratch.path());
  REQUIRE(converted.status == kExitOk);
  CHECK_THAT(converted.err, Catch::Contains("11 frames of"));
  const auto csv = rodsort::metrics::read_rods_csv(run / kRodsCsvFile);
  const std::vector<Frame> h5 = read_h5md(run / kRodsH5mdFile);
  REQUIRE(h5.size() == csv.frames.size());
  for (std::size_t f = 0; f < h5.size(); ++f) {
    CHECK(h5[f].time == csv.frames[f].time);
    for (std::size_t i = 0; i < h5[f].rods.size(); ++i) {
      CHECK((h5[f].rods[i].unwrapped - csv.frames[f].rods[i].unwrapped).norm() < 1e-5);
      CHECK((h5[f].rods[i].axis - csv.frames[f].rods[i].axis).norm() < 1e-6);
    }
  }
  // Once only; and only where there is a rods.csv.
  CHECK(run_rodsort({"convert", run.string()}, scratch.path()).status == kExitUsage);
  std::filesystem::remove(run / kRodsCsvFile);
  const auto without = run_rodsort({"convert", run.string()}, scratch.path());
  CHECK(without.status == kExitUsage);
  CHECK_THAT(without.err, Catch::Contains("no scenario.resolved.yaml and rods.csv"));
}
