// The golden physics test: the whole tool (scenario, engine, trap, metrics, runner) on a small
// system in which a narrow trap fills and a wide one stays nearly empty, compared with reference
// values kept in tests/golden/reference.yaml (section trap_filling: mean and spread over six seeds,
// regenerated on purpose only by scripts/golden-reference). A change that moves the physics beyond
// the seed-to-seed spread fails it; a change that keeps the physics but not the bits does not.

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "runner/run_command.hpp"
#include "runner/run_directory.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::testing::TempDirectory;

namespace {

const std::string kGolden = RODSORT_SOURCE_DIR "/tests/golden/";

/// Runs the golden system with a trap of `angle` degrees and the given seed; returns eta_trap
/// averaged over the last 10 simulated seconds.
double late_eta_trap(const TempDirectory& directory, double angle, int seed) {
  const std::string label = std::to_string(static_cast<int>(angle)) + "-" + std::to_string(seed);
  RunRequest request;
  request.scenario = kGolden + "trap-filling.yaml";
  request.set_options = {"trap.angle=" + std::to_string(angle), "seed=" + std::to_string(seed)};
  request.output = directory / label;
  request.options.log = nullptr;
  std::ostringstream err;
  const int status = run_scenario_file(request, err);
  INFO(err.str());
  REQUIRE(status == kExitOk);
  const CsvTable table = read_csv(request.output / kMetricsCsvFile);
  const std::vector<double> times = table.numbers(*table.column("t"));
  const std::vector<double> eta = table.numbers(*table.column("eta_trap"));
  double sum = 0.0;
  int samples = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (times[i] < 30.0 - 1e-9) continue;
    sum += eta[i];
    ++samples;
  }
  REQUIRE(samples > 0);
  return sum / samples;
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
