// `rodsort single` as a user meets it: a small study writes its tables, bad requests are refused
// with a message that names what is wrong.

#include <yaml-cpp/yaml.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "rodsort_program.hpp"
#include "runner/csv_table.hpp"
#include "runner/exit_code.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort::runner;
using rodsort::runner::testing::run_rodsort;
using rodsort::testing::TempDirectory;

namespace {

const std::string kSingleRods = RODSORT_SOURCE_DIR "/scenarios/library/single-rods.yaml";

}  // namespace

TEST_CASE("rodsort single writes the study of one species", "[runner][single]") {
  TempDirectory scratch;
  const auto out = scratch / "study";
  const auto result = run_rodsort({"single", kSingleRods, "--species", "A", "--rods", "3",
                                   "--duration", "2", "--warmup", "0.5", "-o", out.string()},
                                  scratch.path());
  INFO(result.err);
  REQUIRE(result.status == kExitOk);
  CHECK_THAT(result.out, Catch::Contains("v0"));
  const CsvTable summary = read_csv(out / "summary.csv");
  REQUIRE(summary.rows.size() == 1);
  const double v0 = summary.numbers(*summary.column("v0_mm_s"))[0];
  // Rod A of the default model moves toward its thin end (docs/model.md).
  CHECK(v0 > 5.0);
  // ... with its thin end down (0.96 of the frames of 16 rods x 40 s).
  REQUIRE(summary.column("thin_end_down_fraction"));
  CHECK(summary.numbers(*summary.column("thin_end_down_fraction"))[0] > 0.8);
  CHECK_THAT(result.out, Catch::Contains("thin end down in"));
  CHECK(summary.numbers(*summary.column("rods"))[0] == 3.0);
  // A straight rod has no roll to speak of: no roll line, no roll table, NaN in its columns.
  CHECK_THAT(result.out, !Catch::Contains("roll "));
  CHECK(!std::filesystem::exists(out / "roll_windows.csv"));
  REQUIRE(summary.column("Droll_rad2_s"));
  CHECK(std::isnan(summary.numbers(*summary.column("Droll_rad2_s"))[0]));
  // Rod A keeps a persistent heading: none of its rods circles.
  REQUIRE(summary.column("circling_rods"));
  CHECK(summary.numbers(*summary.column("circling_rods"))[0] == 0.0);
  CHECK_THAT(result.out, Catch::Contains("0 of 3 rods circle"));
  const CsvTable per_rod = read_csv(out / "per_rod.csv");
  CHECK(per_rod.rows.size() == 3);
  CHECK(per_rod.column("turn_rate_rad_s"));
  CHECK(per_rod.column("Dr_about_turn_rad2_s"));
  CHECK(summary.column("run_turn_rms_rad"));
  CHECK(summary.column("tumble_turn_rms_rad"));
  CHECK_THAT(result.out, Catch::Contains("RMS over a tumble"));
  // At the paper's gap rod A never goes backward.
  REQUIRE(summary.column("backward_fraction"));
  CHECK(summary.numbers(*summary.column("backward_fraction"))[0] == 0.0);
  const CsvTable lags = read_csv(out / "lags.csv");
  const auto msd = lags.numbers(*lags.column("position_msd_mm2"));
  REQUIRE(msd.size() > 10);
  CHECK(msd.back() > msd.front());
  const CsvTable distribution = read_csv(out / "axial_velocity.csv");
  double integral = 0.0;
  for (const double density : distribution.numbers(1)) integral += 0.5 * density;
  CHECK(integral == Approx(1.0).epsilon(1e-9));
}

// The cliff of docs/model.md, "The clearance to the lid": with the lid 1.31 mm above the base, rod
// A's thick end reaches it only now and then, and the rod moves at the experiments' 3.6 +- 2.5 mm/s
// by stopping and going, where at the paper's 1.2 mm it runs without stopping at 14 mm/s
// (tests/bench/reference_test.cpp). Its reference, from other rods, is tests/golden/reference.yaml
// (section clearance, scripts/clearance-reference); 12 rods x 20 s take about 3 CPU-s.
TEST_CASE("rod A stops and goes at the experiments' speed when the lid is out of its reach",
          "[runner][single][physics]") {
  const YAML::Node reference =
      YAML::LoadFile(RODSORT_SOURCE_DIR "/tests/golden/reference.yaml")["clearance"];
  REQUIRE(reference.IsMap());
  TempDirectory scratch;
  const auto out = scratch / "study";
  const auto result = run_rodsort({"single", kSingleRods, "--species", "A", "--set",
                                   "drive.gap=" + reference["gap_mm"].as<std::string>(), "--rods",
                                   "12", "--duration", "20", "-o", out.string()},
                                  scratch.path());
  INFO(result.err);
  REQUIRE(result.status == kExitOk);
  const CsvTable summary = read_csv(out / "summary.csv");
  const double v0 = summary.numbers(*summary.column("v0_mm_s"))[0];
  const double v0_error = summary.numbers(*summary.column("v0_sem_mm_s"))[0];
  const double running = summary.numbers(*summary.column("running_fraction"))[0];
  const double reference_v0 = reference["v0_mm_s"]["mean"].as<double>();
  const double tolerance =
      3.0 * std::hypot(v0_error, reference["v0_mm_s"]["standard_error"].as<double>());
  INFO("v0 " << v0 << " +- " << v0_error << " mm/s, reference " << reference_v0 << ", running "
             << running);
  // Within the experiments' range (Nat. Commun. 5, 4688: 3.6 +- 2.5 mm/s) ...
  CHECK(v0 > 3.6 - 2.5);
  CHECK(v0 < 3.6 + 2.5);
  // ... and within three standard errors of the reference.
  CHECK(std::abs(v0 - reference_v0) <= tolerance);
  // It runs in fewer than half of the 0.07 s windows: 0.42-0.45 over four sets of 12 rods, so
  // 0.05 is about four times that spread; on the plateau it runs in all of them.
  CHECK(std::abs(running - reference["running_fraction"].as<double>()) < 0.05);
  // It stops, but it does not go backward: 0.1% of the windows of 16 rods x 40 s.
  CHECK(summary.numbers(*summary.column("backward_fraction"))[0] < 0.02);
}

// docs/model.md, "The clearance to the lid", item 8: at the same gap a lone RnT with no imposed
// noise reverses, where rod A only stops: it goes backward in 0.179-0.210 of the windows over six
// sets of 8 rods x 20 s (seeds 1-6; mean 0.192, standard deviation 0.012), and the trap sorts the
// A + RnT mixture on it (docs/reproduction.md, section 7). About 1.5 CPU-s.
TEST_CASE("at a 1.31 mm gap a lone RnT goes backward in about a fifth of its windows",
          "[runner][single][physics]") {
  TempDirectory scratch;
  const auto out = scratch / "study";
  const auto result =
      run_rodsort({"single", kSingleRods, "--species", "RnT", "--set", "drive.gap=1.31", "--rods",
                   "8", "--duration", "20", "-o", out.string()},
                  scratch.path());
  INFO(result.err << result.out);
  REQUIRE(result.status == kExitOk);
  CHECK_THAT(result.out, Catch::Contains("backward  "));
  const CsvTable summary = read_csv(out / "summary.csv");
  const double backward = summary.numbers(*summary.column("backward_fraction"))[0];
  // Five standard deviations of the six sets either side of their mean.
  CHECK(backward > 0.192 - 0.06);
  CHECK(backward < 0.192 + 0.06);
}

// docs/model.md, "Where the RnT's step lies", item 8: an RnT with a thin half 0.4 mm thick from
// 1.3 mm, solved to convergence, breaks its mirror symmetry and circles at 1.5-1.8 rad/s and
// 3.2-3.3 mm/s (8 rods x 15-30 s at dt = 3.125e-6, 6.25e-6 and 1.25e-5 s, 30 and 100 sweeps;
// 7 of 8 rods each time, both senses). Rod 0 starts with its axis along x, on a mirror plane of
// the cell to the last bit, and keeps that symmetry: it never turns. About 7 CPU-s.
TEST_CASE("a straight RnT can break its mirror symmetry and circle either way",
          "[runner][single][physics]") {
  TempDirectory scratch;
  const auto out = scratch / "study";
  const auto result = run_rodsort(
      {"single", kSingleRods, "--species", "RnT", "--set", "species[1].shape.thin_radius=0.2",
       "--set", "species[1].shape.step=1.3", "--set", "run.dt=1.25e-5", "--set",
       "run.solver_iterations=30", "--rods", "4", "--duration", "6", "-o", out.string()},
      scratch.path());
  INFO(result.err << result.out);
  REQUIRE(result.status == kExitOk);
  const CsvTable per_rod = read_csv(out / "per_rod.csv");
  const std::vector<double> turn = per_rod.numbers(*per_rod.column("turn_rate_rad_s"));
  const std::vector<double> circles = per_rod.numbers(*per_rod.column("circles"));
  const std::vector<double> v0 = per_rod.numbers(*per_rod.column("v0_mm_s"));
  REQUIRE(turn.size() == 4);
  CHECK(turn[0] == 0.0);
  CHECK(circles[0] == 0.0);
  for (std::size_t rod = 1; rod < turn.size(); ++rod) {
    INFO("rod " << rod << ": turn rate " << turn[rod] << " rad/s, v0 " << v0[rod] << " mm/s");
    CHECK(circles[rod] == 1.0);
    CHECK(std::abs(turn[rod]) > 1.2);
    CHECK(std::abs(turn[rod]) < 2.2);
    CHECK(std::abs(v0[rod] - 3.3) < 0.3);
  }
}

namespace {

// One rod's track in rods.csv: time, unwrapped centre and in-plane axis per frame.
struct Track {
  std::vector<double> t, x, y, ux, uy;
};

Track read_track(const std::filesystem::path& run) {
  const CsvTable rods = read_csv(run / "rods.csv");
  const auto column = [&](const char* name) { return rods.numbers(*rods.column(name)); };
  return {column("t"), column("xu"), column("yu"), column("ux"), column("uy")};
}

// Two copies of one rod compared as scripts/divergence does: after their centres have parted by
// 0.1 mm, the share of 0.07 s windows in which one goes forward and the other backward (|V_x|
// above 1 mm/s in both), that share for independent rods with the same shares of forward and
// backward windows, and the angle between their axes at the last frame.
struct Divergence {
  double opposite = 0.0, independent = 0.0, heading_deg = 0.0;
  int windows = 0;
};

Divergence compare_copies(const Track& a, const Track& b) {
  REQUIRE(a.t.size() == b.t.size());
  std::size_t start = 0;
  while (start < a.t.size() &&
         std::hypot(a.x[start] - b.x[start], a.y[start] - b.y[start]) <= 0.1) {
    ++start;
  }
  const std::size_t step = 7;  // 0.07 s of frames every 0.01 s
  const auto axial = [&](const Track& track, std::size_t i) {
    const double norm = std::hypot(track.ux[i], track.uy[i]);
    return ((track.x[i + step] - track.x[i]) * track.ux[i] +
            (track.y[i + step] - track.y[i]) * track.uy[i]) /
           norm / (track.t[i + step] - track.t[i]);
  };
  Divergence out;
  double forward_a = 0, backward_a = 0, forward_b = 0, backward_b = 0, opposite = 0;
  for (std::size_t i = start; i + step < a.t.size(); i += step) {
    const double va = axial(a, i), vb = axial(b, i);
    forward_a += va > 1.0;
    backward_a += va < -1.0;
    forward_b += vb > 1.0;
    backward_b += vb < -1.0;
    opposite += (va > 1.0 && vb < -1.0) || (va < -1.0 && vb > 1.0);
    ++out.windows;
  }
  if (out.windows > 0) {
    const double n = out.windows;
    out.opposite = opposite / n;
    out.independent = (forward_a * backward_b + backward_a * forward_b) / (n * n);
  }
  const std::size_t last = a.t.size() - 1;
  out.heading_deg = std::abs(std::atan2(a.ux[last] * b.uy[last] - a.uy[last] * b.ux[last],
                                        a.ux[last] * b.ux[last] + a.uy[last] * b.uy[last])) *
                    180.0 / std::numbers::pi;
  return out;
}

// A lone RnT, no imposed noise, 30 s with frames every 0.01 s, under the lid at `gap` mm.
Track lone_rnt(const TempDirectory& scratch, const std::string& name, const std::string& gap) {
  const auto out = scratch / name;
  const auto result =
      run_rodsort({"run", kSingleRods, "--set", "species[0].count=0", "--set", "box.size=[60,60]",
                   "--set", "run.duration=30", "--set", "output.frame_interval=0.01", "--set",
                   "seed=1", "--set", "drive.gap=" + gap, "-o", out.string()},
                  scratch.path());
  INFO(result.err << result.out);
  REQUIRE(result.status == kExitOk);
  return read_track(out);
}

}  // namespace

// docs/model.md, "Sensitivity to initial conditions, measured": raising the lid by 1e-9 mm makes
// a lone RnT at a 1.31 mm gap reverse at other times, as an independent rod would (seeds 1-4 over
// 60 s: opposite 0.24-0.26 of the windows after parting against 0.24-0.27 for independent rods;
// by 10 s blocks within 0.07 of it); at the paper's 1.2 mm gap the same perturbation reaches
// neither the preset RnT's direction (it never goes backward) nor its heading (within 0.1 deg
// after 60 s, 1e-5 deg in three seeds of four). About 2 CPU-s.
TEST_CASE(
    "a 1e-9 mm change of the lid moves a reversing RnT's reversals, not a running RnT's heading",
    "[runner][single][physics]") {
  TempDirectory scratch;
  const Divergence reversing = compare_copies(lone_rnt(scratch, "gap131", "1.31"),
                                              lone_rnt(scratch, "gap131+", "1.310000001"));
  INFO("gap 1.31: " << reversing.windows << " windows, opposite " << reversing.opposite
                    << ", independent " << reversing.independent);
  CHECK(reversing.windows > 300);
  CHECK(reversing.independent > 0.15);
  CHECK(reversing.opposite > 0.6 * reversing.independent);
  CHECK(reversing.opposite < 1.4 * reversing.independent);

  const Divergence running = compare_copies(lone_rnt(scratch, "gap120", "1.2"),
                                            lone_rnt(scratch, "gap120+", "1.200000001"));
  INFO("gap 1.2: " << running.windows << " windows, opposite " << running.opposite
                   << ", independent " << running.independent << ", heading "
                   << running.heading_deg);
  CHECK(running.windows > 100);  // the copies do part: the bouncing is chaotic
  CHECK(running.independent < 0.01);
  CHECK(running.opposite < 0.01);
  CHECK(running.heading_deg < 0.1);
}

// docs/model.md, "A rough lid": under a lid of RMS slope 0.03, at the step where its gait is
// converged enough to read (2.5e-5 s), a lone RnT with no imposed noise stops about as long as it
// runs, and a stop turns it less than a run does: a pause, not the experiments' tumble to a new
// direction. Four sets of 8 rods x 20 s (seeds 100-400) gave mean tumble / mean run 1.46, 1.47,
// 0.90, 1.12, running 0.27-0.46, and RMS turns of 11.2-13.6 deg over a stop against 15.9-18.1 over
// a run. About 15 CPU-s.
TEST_CASE("under a rough lid a lone RnT stops as long as it runs, and its stops do not turn it",
          "[runner][single][physics]") {
  TempDirectory scratch;
  const auto out = scratch / "study";
  const auto result = run_rodsort(
      {"single", kSingleRods, "--species", "RnT", "--set", "roughness.lid_slope=0.03", "--set",
       "run.dt=2.5e-5", "--set", "seed=100", "--rods", "8", "--duration", "20", "-o", out.string()},
      scratch.path());
  INFO(result.err << result.out);
  REQUIRE(result.status == kExitOk);
  const CsvTable summary = read_csv(out / "summary.csv");
  const auto value = [&](const char* column) {
    return summary.numbers(*summary.column(column))[0];
  };
  // Stops and runs alternate, the stops at least about as long as the runs ...
  CHECK(value("running_fraction") > 0.15);
  CHECK(value("running_fraction") < 0.7);
  CHECK(value("tumbles") >= 40.0);
  CHECK(value("mean_tumble_s") > 0.75 * value("mean_run_s"));
  // ... but a stop turns the rod less than a run does, far from a new direction at random.
  CHECK(value("tumble_turn_rms_rad") < value("run_turn_rms_rad"));
  CHECK(value("tumble_turn_rms_rad") < 0.5);
}

TEST_CASE(
    "an RnT with its thin part off its axis settles on one side of straight down, and turns "
    "toward that side",
    "[runner][single][physics]") {
  // On flat plates the roll of such an RnT (0.02 mm off) locks: 14 of 16 rods rest with the
  // off-axis part 19-20 degrees to one side of straight down and circle at +-1.0 rad/s toward it,
  // 2 with it straight up, not turning (docs/model.md, "An RnT whose thin part is off its axis").
  // Four rods whose first rolls (0, 222, 85 and 307 degrees) reach all three states.
  TempDirectory scratch;
  const auto out = scratch / "study";
  const auto result = run_rodsort(
      {"single", kSingleRods, "--species", "RnT", "--set", "species[1].shape.thin_offset=0.02",
       "--rods", "4", "--duration", "10", "--warmup", "1", "-o", out.string()},
      scratch.path());
  INFO(result.err << result.out);
  REQUIRE(result.status == kExitOk);
  CHECK_THAT(result.out, Catch::Contains("roll      about its axis"));
  const CsvTable per_rod = read_csv(out / "per_rod.csv");
  REQUIRE(per_rod.rows.size() == 4);
  const auto roll = per_rod.numbers(*per_rod.column("roll_mean_rad"));
  const auto turn = per_rod.numbers(*per_rod.column("turn_rate_rad_s"));
  const auto roll_diffusion = per_rod.numbers(*per_rod.column("Droll_rad2_s"));
  int left = 0, right = 0, up = 0;
  for (std::size_t r = 0; r < 4; ++r) {
    const double degrees = roll[r] * 180.0 / std::numbers::pi;
    const double from_down = std::remainder(degrees + 90.0, 360.0);
    INFO("rod " << r << ": roll " << degrees << " degrees, turn rate " << turn[r] << " rad/s");
    // The roll stays where it settled.
    CHECK(roll_diffusion[r] < 0.02);
    if (std::abs(degrees - 90.0) < 5.0) {
      ++up;
      CHECK(std::abs(turn[r]) < 0.1);
    } else {
      CHECK(std::abs(std::abs(from_down) - 19.5) < 5.0);
      CHECK(std::abs(turn[r]) > 0.8);
      CHECK(std::abs(turn[r]) < 1.2);
      // The part to the left of the axis (roll above -90 degrees) turns it counter-clockwise.
      CHECK((turn[r] > 0.0) == (from_down > 0.0));
      (from_down > 0.0 ? left : right) += 1;
    }
  }
  CHECK(left >= 1);
  CHECK(right >= 1);
  CHECK(up == 1);
  const CsvTable windows = read_csv(out / "roll_windows.csv");
  CHECK(windows.rows.size() == 4 * 142);
}

// docs/model.md, "Restitution of base and lid together": with restitutions of 0.8 against base and
// lid, rod A at dt = 1e-4 s goes backward at about 11 mm/s and at 5e-5 s forward at about 2
// (16 rods x 40 s each); without noise at the default restitutions its gait holds from 5e-5 to
// 2.5e-5 s. Six rods x 4 s per step, about 2 CPU-s in all.
TEST_CASE(
    "rodsort single --dt-halvings repeats the study at smaller steps and says whether they "
    "agree",
    "[runner][single]") {
  TempDirectory scratch;
  const std::vector<std::string> lively = {"single",     kSingleRods,
                                           "--species",  "A",
                                           "--rods",     "6",
                                           "--duration", "4",
                                           "--warmup",   "1",
                                           "--set",      "materials.rod-base.restitution=0.8",
                                           "--set",      "materials.rod-lid.restitution=0.8"};
  auto halved = lively;
  halved.insert(halved.end(), {"--dt-halvings", "1", "-o", (scratch / "lively").string()});
  const auto result = run_rodsort(halved, scratch.path());
  INFO(result.err);
  REQUIRE(result.status == kExitOk);
  CHECK_THAT(result.out, Catch::Contains("at run.dt = 1e-4 s:") &&
                             Catch::Contains("at run.dt = 5e-5 s:") &&
                             Catch::Contains("not settled between run.dt = 1e-4 and 5e-5 s: v0 "));
  const CsvTable table = read_csv(scratch / "lively" / "dt_convergence.csv");
  REQUIRE(table.rows.size() == 2);
  CHECK(table.rows[0][0] == "1e-4");
  CHECK(table.rows[1][0] == "5e-5");
  const auto v0 = table.numbers(*table.column("v0_mm_s"));
  CHECK(v0[0] < -5.0);  // backward at the default step
  CHECK(v0[1] > v0[0] + 5.0);
  // Each step's study is written whole, and the coarse one is the plain study at that step.
  for (const char* step : {"dt-1e-4", "dt-5e-5"}) {
    const CsvTable summary = read_csv(scratch / "lively" / step / "summary.csv");
    REQUIRE(summary.rows.size() == 1);
    CHECK(summary.numbers(*summary.column("v0_mm_s"))[0] ==
          v0[std::string(step) == "dt-1e-4" ? 0 : 1]);
  }
  auto plain = lively;
  plain.push_back("-o");
  plain.push_back((scratch / "plain").string());
  REQUIRE(run_rodsort(plain, scratch.path()).status == kExitOk);
  CsvTable coarse = read_csv(scratch / "lively" / "dt-1e-4" / "summary.csv");
  CsvTable alone = read_csv(scratch / "plain" / "summary.csv");
  const std::size_t cpu = *coarse.column("cpu_s");
  coarse.rows[0][cpu] = alone.rows[0][cpu] = "";
  CHECK(coarse.rows == alone.rows);

  // Without noise at the paper's restitutions rod A's gait holds from 5e-5 to 2.5e-5 s.
  const auto steady = run_rodsort(
      {"single", kSingleRods, "--species", "A", "--rods", "6", "--duration", "4", "--warmup", "1",
       "--set", "species[0].noise.kick_eps=0", "--set", "run.dt=5e-5", "--dt-halvings", "1"},
      scratch.path());
  REQUIRE(steady.status == kExitOk);
  CHECK_THAT(steady.out, Catch::Contains("\nsettled between run.dt = 5e-5 and 2.5e-5 s"));

  const auto too_many =
      run_rodsort({"single", kSingleRods, "--duration", "2", "--dt-halvings", "7"}, scratch.path());
  CHECK(too_many.status == kExitUsage);
  CHECK_THAT(too_many.err, Catch::Contains("--dt-halvings"));
}

TEST_CASE("rodsort single refuses what it cannot measure", "[runner][single]") {
  TempDirectory scratch;
  const auto species =
      run_rodsort({"single", kSingleRods, "--species", "B", "--duration", "2"}, scratch.path());
  CHECK(species.status == kExitUsage);
  CHECK_THAT(species.err, Catch::Contains("no species 'B'") && Catch::Contains("A, RnT"));
  const auto sample =
      run_rodsort({"single", kSingleRods, "--sample", "0.03", "--duration", "2"}, scratch.path());
  CHECK(sample.status == kExitUsage);
  CHECK_THAT(sample.err, Catch::Contains("metrics.window"));
  const auto cell =
      run_rodsort({"single", kSingleRods, "--cell", "10", "--duration", "2"}, scratch.path());
  CHECK(cell.status == kExitUsage);
  CHECK_THAT(cell.err, Catch::Contains("--cell"));
  const auto short_run = run_rodsort({"single", kSingleRods, "--duration", "1"}, scratch.path());
  CHECK(short_run.status == kExitUsage);
  CHECK_THAT(short_run.err, Catch::Contains("--duration"));
  const auto bad_key = run_rodsort(
      {"single", kSingleRods, "--set", "drive.gapp=1.3", "--duration", "2"}, scratch.path());
  CHECK(bad_key.status == kExitUsage);
  CHECK_THAT(bad_key.err, Catch::Contains("drive.gap"));
}
