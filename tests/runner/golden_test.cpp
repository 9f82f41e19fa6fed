// The golden physics tests: the whole tool (scenario, engine, trap, metrics, runner) on small
// systems, compared with reference values kept in tests/golden/reference.yaml, each regenerated on
// purpose only by its script. In one a narrow trap fills and a wide one stays nearly empty (section
// trap_filling, scripts/golden-reference); in the others a trap keeps A from a mixture with RnT,
// with the lid at 1.31 mm, or at the paper's gap where RnT stops and goes, and does not where RnT
// runs steadily (section sorting, scripts/golden-sorting-reference). Each reference is a mean and
// spread over six seeds. A change that moves the physics beyond the seed-to-seed spread
// fails them; a change that keeps the physics but not the bits does not.

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_command.hpp"
#include "runner/run_directory.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::testing::TempDirectory;

namespace {

const std::string kGolden = RODSORT_SOURCE_DIR "/tests/golden/";

/// Runs one of the golden scenarios with the given --set options into directory/label; returns
/// the mean of `column` of metrics.csv over the frames from t = `from` s on, leaving out NaN (a
/// measure of no rods).
double late_mean(const TempDirectory& directory, const std::string& scenario,
                 const std::vector<std::string>& set_options, const std::string& label,
                 const std::string& column, double from) {
  RunRequest request;
  request.scenario = kGolden + scenario;
  request.set_options = set_options;
  request.output = directory / label;
  request.options.log = nullptr;
  std::ostringstream err;
  const int status = run_scenario_file(request, err);
  INFO(err.str());
  REQUIRE(status == kExitOk);
  const CsvTable table = read_csv(request.output / kMetricsCsvFile);
  const std::vector<double> times = table.numbers(*table.column("t"));
  const std::vector<double> values = table.numbers(*table.column(column));
  double sum = 0.0;
  int samples = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (times[i] < from - 1e-9 || std::isnan(values[i])) continue;
    sum += values[i];
    ++samples;
  }
  REQUIRE(samples > 0);
  return sum / samples;
}

/// The golden trap system with a trap of `angle` degrees and the given seed: eta_trap averaged
/// over the last 10 simulated seconds.
double late_eta_trap(const TempDirectory& directory, double angle, int seed) {
  return late_mean(directory, "trap-filling.yaml",
                   {"trap.angle=" + std::to_string(angle), "seed=" + std::to_string(seed)},
                   std::to_string(static_cast<int>(angle)) + "-" + std::to_string(seed), "eta_trap",
                   30.0);
}

/// The golden sorting system with the given seed and --set options: A's share of the rods the trap
/// holds, averaged over the last 75 simulated seconds.
double late_purity_held_a(const TempDirectory& directory, int seed,
                          std::vector<std::string> set_options = {},
                          const std::string& label = "sorting") {
  set_options.push_back("seed=" + std::to_string(seed));
  return late_mean(directory, "sorting-gap131.yaml", set_options,
                   label + "-" + std::to_string(seed), "purity_held_A", 75.0);
}

/// The options of scripts/golden-sorting-reference for the paper's gap with another RnT outline,
/// the counts of the preset mixture kept.
std::vector<std::string> paper_gap_with_rnt(std::vector<std::string> outline) {
  outline.insert(outline.end(), {"drive.gap=1.2", "species[0].count=31", "species[0].fraction=null",
                                 "species[1].count=47", "species[1].fraction=null"});
  return outline;
}

}  // namespace

TEST_CASE("golden: a narrow trap fills and a wide one stays nearly empty", "[golden][physics]") {
  const YAML::Node reference = YAML::LoadFile(kGolden + "reference.yaml")["trap_filling"];
  REQUIRE(reference.IsMap());
  TempDirectory directory;
  // Where the narrow trap's content levels off differs much from seed to seed (0.28 to 0.88 over
  // six: in this small cell the rods outside can flock, all heading one way, and stop feeding the
  // trap; docs/reproduction.md). So the test compares the mean of seeds 1 and 2 with the
  // reference mean, within three standard errors of a two-seed mean, and never closer than 0.05.
  for (const char* trap : {"narrow", "wide"}) {
    const double angle = reference[trap]["angle"].as<double>();
    const double mean = reference[trap]["eta_trap"]["mean"].as<double>();
    const double sd = reference[trap]["eta_trap"]["sd"].as<double>();
    const double tolerance = std::max(0.05, 3.0 * sd / std::sqrt(2.0));
    const double measured =
        0.5 * (late_eta_trap(directory, angle, 1) + late_eta_trap(directory, angle, 2));
    INFO(trap << " trap, " << angle << " degrees, seeds 1 and 2: eta_trap " << measured
              << ", reference " << mean << " +- " << tolerance);
    CHECK(std::abs(measured - mean) <= tolerance);
  }
  // And the physics the test is for: the narrow trap holds far more than the wide one.
  CHECK(reference["narrow"]["eta_trap"]["mean"].as<double>() >
        reference["wide"]["eta_trap"]["mean"].as<double>() + 0.3);
}

TEST_CASE("golden: at a 1.31 mm gap the trap holds mostly A from a mixture of RnT and A",
          "[golden][physics]") {
  const YAML::Node reference = YAML::LoadFile(kGolden + "reference.yaml")["sorting"];
  REQUIRE(reference.IsMap());
  const double mean = reference["gap_1.31"]["purity_held_A"]["mean"].as<double>();
  const double sd = reference["gap_1.31"]["purity_held_A"]["sd"].as<double>();
  TempDirectory directory;
  // Seed 1 against the reference mean, within three standard deviations of one seed, and never
  // closer than 0.05 (one 150 s run; a second seed doubled the suite's longest test).
  const double tolerance = std::max(0.05, 3.0 * sd);
  const double measured = late_purity_held_a(directory, 1);
  INFO("seed 1: A's share of the held rods " << measured << ", reference " << mean << " +- "
                                            << tolerance);
  CHECK(std::abs(measured - mean) <= tolerance);
  // And the physics the test is for: from a mixture of 40% A the pile is mostly A, where at the
  // paper's gap it is not.
  CHECK(measured > 0.6);
  CHECK(mean > reference["gap_1.2"]["purity_held_A"]["mean"].as<double>() + 0.15);
}

TEST_CASE("golden: at the paper's gap the trap lets go an RnT that stops and goes",
          "[golden][physics]") {
  // RnT 1.0 mm thick, slower than rod A (6.1 against 14.2 mm/s alone) and not reversing, runs in
  // about half of its 0.07 s windows at this step; an RnT with a thin part 0.4 mm thick from
  // 1.5 mm, as slow (8.1 mm/s), runs in all of them, and the trap holds it with A as they come
  // (docs/model.md, "The clearance to the lid", item 7). The first is run here, seed 1, against
  // its reference mean within three standard deviations of one seed, and never closer than 0.05;
  // the second, whose reference was made the same way, is the contrast.
  const YAML::Node reference = YAML::LoadFile(kGolden + "reference.yaml")["sorting"];
  REQUIRE(reference.IsMap());
  const double mean = reference["rnt_stop_and_go"]["purity_held_A"]["mean"].as<double>();
  const double sd = reference["rnt_stop_and_go"]["purity_held_A"]["sd"].as<double>();
  const double steady = reference["rnt_steady"]["purity_held_A"]["mean"].as<double>();
  TempDirectory directory;
  const double tolerance = std::max(0.05, 3.0 * sd);
  const double measured = late_purity_held_a(
      directory, 1, paper_gap_with_rnt({"species[1].shape.thick_radius=0.5"}), "stop-and-go");
  INFO("seed 1: A's share of the held rods " << measured << ", reference " << mean << " +- "
                                             << tolerance << "; with the steady RnT " << steady);
  CHECK(std::abs(measured - mean) <= tolerance);
  // And the physics the test is for: from a mixture of 40% A the pile is at least 80% A, where
  // with the steady RnT it is about as mixed as the population.
  CHECK(measured > 0.8);
  CHECK(measured > steady + 0.3);
  CHECK(steady < 0.6);
}
