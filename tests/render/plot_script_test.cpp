#include "render/plot_script.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "metrics/critical_angle.hpp"
#include "metrics/metrics_observer.hpp"
#include "render/png_pixels.hpp"
#include "render/synthetic_run.hpp"
#include "support/temp_directory.hpp"

using namespace rodsort;
using render::testing::kFrameInterval;
using render::testing::PngPixels;
using rodsort::testing::TempDirectory;
using render::testing::TestScene;

namespace {

/// The plots need a python with matplotlib; CI installs it, so its absence is a failure.
void require_plot_python() {
  const render::PythonLookup lookup = render::find_plot_python();
  if (!lookup.python) FAIL(lookup.error);
  REQUIRE(render::find_plot_script());
}

/// rods.csv and metrics.csv of the synthetic run, metrics.csv as the metrics layer writes it.
void write_run_with_metrics(const std::filesystem::path& directory, const TestScene& test,
                            int frames) {
  render::testing::write_test_run(directory, test, frames);
  metrics::MetricsObserver observer(test.metrics_config());
  std::ofstream out(directory / "metrics.csv");
  out << observer.csv_header() << '\n';
  for (int k = 0; k < frames; ++k) {
    if (const auto row =
            observer.observe(render::testing::test_frame(test.trap, kFrameInterval * k))) {
      out << observer.csv_line(*row) << '\n';
    }
  }
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void check_png(const std::filesystem::path& path) {
  INFO(path.string());
  REQUIRE(std::filesystem::is_regular_file(path));
  const PngPixels png(path);
  CHECK(png.width() > 300);
  CHECK(png.height() > 200);
}

}  // namespace

TEST_CASE("The plot script draws eta(t), the trap population and P(dtheta) of a run",
          "[render][plot]") {
  require_plot_python();
  const TestScene test;
  const TempDirectory run;
  write_run_with_metrics(run.path(), test, 12);
  const render::ProgramOutput plotted = render::run_plot_script({run.path().string()});
  INFO(plotted.output);
  REQUIRE(plotted.exit_status == 0);
  for (const char* name : {"eta", "population", "dtheta"}) {
    check_png(run / "plots" / (std::string(name) + ".png"));
    const std::string svg = read_text(run / "plots" / (std::string(name) + ".svg"));
    CHECK(svg.find("<svg") != std::string::npos);
    // Text stays text (editable in a figure), and a plot of one run is titled with its name.
    CHECK_THAT(svg, Catch::Contains("<text") && Catch::Contains(run.path().filename().string()));
  }
}

TEST_CASE("The plot script draws a run up to --until", "[render][plot]") {
  require_plot_python();
  const TestScene test;
  const TempDirectory run;
  write_run_with_metrics(run.path(), test, 12);
  // The vertices of the drawn lines: matplotlib writes each line as one SVG path, "M x y L x y
  // ...".
  const auto vertices = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> arguments = {run.path().string(), "--what", "eta,population",
                                          "--format", "svg"};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    const render::ProgramOutput plotted = render::run_plot_script(arguments);
    INFO(plotted.output);
    REQUIRE(plotted.exit_status == 0);
    std::vector<std::size_t> counts;
    for (const char* name : {"eta.svg", "population.svg"}) {
      const std::string svg = read_text(run / "plots" / name);
      std::size_t count = 0;
      for (auto at = svg.find("L "); at != std::string::npos; at = svg.find("L ", at + 1)) ++count;
      counts.push_back(count);
    }
    return counts;
  };
  const auto whole = vertices({});
  // Up to the 6th frame: 5 of the 11 metrics rows, so each line loses 6 of its points.
  const auto cut = vertices({"--until", std::to_string(5.5 * kFrameInterval)});
  for (std::size_t k = 0; k < whole.size(); ++k) {
    INFO("plot " << k);
    CHECK(cut[k] + 6 <= whole[k]);
  }
  const render::ProgramOutput refused =
      render::run_plot_script({run.path().string(), "--until", "0"});
  CHECK(refused.exit_status == 2);
  CHECK_THAT(refused.output, Catch::Contains("--until: must be positive"));
}

TEST_CASE("P(dtheta) leaves out the pairs that reach a run's shorter last interval",
          "[render][plot]") {
  require_plot_python();
  const TempDirectory run;
  // Frames every 0.07 s and a last one at 0.25 s, where a run of 0.25 s ends: the rod turns by
  // 2 degrees per frame, then by 50 degrees in the last 0.04 s.
  std::ofstream rods(run / "rods.csv");
  rods << "t,rod,species,ux,uy\n";
  const double times[] = {0.0, 0.07, 0.14, 0.21, 0.25};
  const double degrees[] = {0.0, 2.0, 4.0, 6.0, 56.0};
  for (int k = 0; k < 5; ++k) {
    const double angle = degrees[k] * M_PI / 180.0;
    rods << times[k] << ",0,A," << std::cos(angle) << ',' << std::sin(angle) << '\n';
  }
  rods.close();
  std::ofstream(run / "metrics.csv") << "t,n_rods\n";
  const render::ProgramOutput plotted =
      render::run_plot_script({run.path().string(), "--what", "dtheta", "--format", "svg"});
  INFO(plotted.output);
  REQUIRE(plotted.exit_status == 0);
  const std::string svg = read_text(run / "plots" / "dtheta.svg");
  // The lag is the frames' interval, not their mean spacing (0.0625 s), and the axis holds the
  // 2-degree turns (+-10) without the 50-degree one of the short last interval (+-60).
  CHECK_THAT(svg, Catch::Contains("over 0.07 s") && Catch::Contains(">10.0</text>"));
  CHECK_THAT(svg, !Catch::Contains(">60</text>"));
}

TEST_CASE("Runs beyond the palette's colours are drawn dashed", "[render][plot]") {
  require_plot_python();
  const TestScene test;
  const TempDirectory scratch;
  // eta(t) of n runs as SVG: how many of its paths are dashed.
  const auto dashed_lines = [&](int runs) {
    std::vector<std::string> arguments;
    for (int r = 0; r < runs; ++r) {
      const auto run = scratch / ("n" + std::to_string(runs)) / ("run" + std::to_string(r));
      std::filesystem::create_directories(run);
      write_run_with_metrics(run, test, 6);
      arguments.push_back(run.string());
    }
    for (const char* extra : {"--what", "eta", "--format", "svg", "-o"}) arguments.push_back(extra);
    arguments.push_back((scratch / ("plots" + std::to_string(runs))).string());
    const render::ProgramOutput plotted = render::run_plot_script(arguments);
    INFO(plotted.output);
    REQUIRE(plotted.exit_status == 0);
    const std::string svg = read_text(scratch / ("plots" + std::to_string(runs)) / "eta.svg");
    std::size_t count = 0;
    for (auto at = svg.find("stroke-dasharray"); at != std::string::npos;
         at = svg.find("stroke-dasharray", at + 1)) {
      ++count;
    }
    return count;
  };
  // Seven colours: the eighth run repeats the first one's colour, and its line (with its legend
  // entry) is dashed.
  CHECK(dashed_lines(7) == 0);
  CHECK(dashed_lines(8) == 2);
}

TEST_CASE("The plot script names a missing column", "[render][plot]") {
  require_plot_python();
  const TempDirectory run;
  std::ofstream(run / "metrics.csv") << "t,n_rods\n0.07,4\n";
  const render::ProgramOutput plotted =
      render::run_plot_script({run.path().string(), "--what", "eta"});
  CHECK(plotted.exit_status == 1);
  CHECK_THAT(plotted.output, Catch::Contains("metrics.csv: no column 'eta'") &&
                                 Catch::Contains("the columns are: t, n_rods"));
  // A kind that is not drawn from a run directory is a usage error.
  const render::ProgramOutput unknown =
      render::run_plot_script({run.path().string(), "--what", "eta-theta"});
  CHECK(unknown.exit_status == 2);
  CHECK_THAT(unknown.output, Catch::Contains("'eta-theta' is drawn from a sweep directory"));
}

TEST_CASE("The plot script finds theta_c of a sweep as the metrics layer does", "[render][plot]") {
  require_plot_python();
  const TempDirectory sweep;
  // Two noise levels, two seeds per point; eta falls past 120° at the lower noise, past 110° at
  // the higher one.
  const std::vector<double> angles = {60, 80, 100, 110, 120, 130, 140};
  const std::vector<std::vector<double>> etas = {{0.9, 0.88, 0.91, 0.86, 0.7, 0.2, 0.05},
                                                 {0.85, 0.9, 0.8, 0.6, 0.1, 0.02, 0.0}};
  const std::vector<double> noises = {0.01, 0.02};
  std::ofstream csv(sweep / "sweep.csv");
  csv << "point,trap.angle,species[0].noise.kick_eps,seed,status,eta_mean\n";
  int point = 0;
  for (std::size_t n = 0; n < noises.size(); ++n) {
    for (std::size_t a = 0; a < angles.size(); ++a) {
      for (const double offset : {-0.01, 0.01}) {
        csv << "p" << point++ << ',' << angles[a] << ',' << noises[n] << ",1,complete,"
            << etas[n][a] + offset << '\n';
      }
    }
  }
  csv << "p" << point++ << ",150,0.01,1,failed,nan\n";
  csv << "p" << point << ",160,0.01,1,running,0.01\n";
  csv.close();

  const render::ProgramOutput plotted = render::run_plot_script({sweep.path().string()});
  INFO(plotted.output);
  REQUIRE(plotted.exit_status == 0);
  CHECK_THAT(plotted.output, Catch::Contains("2 point(s)"));
  check_png(sweep / "plots" / "eta-theta.png");
  check_png(sweep / "plots" / "thetac-eps.png");

  std::ifstream theta_c(sweep / "plots" / "theta_c.csv");
  std::string line;
  std::getline(theta_c, line);
  CHECK(line ==
        "species[0].noise.kick_eps,theta_c,below,above,plateau,reason,theta_c_seed_mean,"
        "theta_c_seed_stderr,seeds_found");
  // One seed: no seeds' error bar, and the figure says that its bars bracket the drop.
  CHECK_THAT(read_text(sweep / "plots" / "thetac-eps.svg"),
             Catch::Contains("bar: the angles that bracket the drop") &&
                 !Catch::Contains("mean ± standard error"));
  for (std::size_t n = 0; n < noises.size(); ++n) {
    std::vector<metrics::SweepPoint> points;
    for (std::size_t a = 0; a < angles.size(); ++a) points.push_back({angles[a], etas[n][a]});
    const metrics::CriticalAngle expected = metrics::critical_angle(points);
    REQUIRE(expected.found);
    REQUIRE(std::getline(theta_c, line));
    double eps = 0.0, angle = 0.0, below = 0.0, above = 0.0, plateau = 0.0;
    REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf", &eps, &angle, &below, &above,
                        &plateau) == 5);
    CHECK(eps == Approx(noises[n]));
    CHECK(angle == Approx(expected.angle).epsilon(1e-6));
    CHECK(below == expected.below);
    CHECK(above == expected.above);
    CHECK(plateau == Approx(expected.plateau).epsilon(1e-6));
  }
}

TEST_CASE("The plot script gives each seed's theta_c and the differences seed by seed",
          "[render][plot]") {
  require_plot_python();
  const TempDirectory sweep;
  const std::vector<double> angles = {100, 110, 120, 130, 140};
  // eta by noise and seed: seeds 1-3 drop at both noises; seed 4 runs at the higher noise only,
  // and seed 5's traps all fill at the higher noise, so neither enters a difference.
  const std::map<std::pair<std::string, int>, std::vector<double>> etas = {
      {{"0.01", 1}, {0.9, 0.85, 0.8, 0.3, 0.0}}, {{"0.01", 2}, {0.8, 0.8, 0.2, 0.1, 0.0}},
      {{"0.01", 3}, {0.9, 0.9, 0.9, 0.9, 0.1}},  {{"0.01", 5}, {0.9, 0.8, 0.5, 0.1, 0.0}},
      {{"0.05", 1}, {0.9, 0.6, 0.1, 0.0, 0.0}},  {{"0.05", 2}, {0.7, 0.75, 0.7, 0.05, 0.0}},
      {{"0.05", 3}, {0.9, 0.85, 0.4, 0.0, 0.0}}, {{"0.05", 4}, {0.9, 0.1, 0.0, 0.0, 0.0}},
      {{"0.05", 5}, {0.9, 0.9, 0.9, 0.9, 0.9}}};
  std::ofstream csv(sweep / "sweep.csv");
  csv << "point,trap.angle,species[0].noise.kick_eps,seed,status,eta_mean\n";
  int point = 0;
  std::map<std::pair<std::string, int>, double> expected;
  for (const auto& [curve, eta] : etas) {
    std::vector<metrics::SweepPoint> points;
    for (std::size_t a = 0; a < angles.size(); ++a) {
      csv << "p" << point++ << ',' << angles[a] << ',' << curve.first << ',' << curve.second
          << ",complete," << eta[a] << '\n';
      points.push_back({angles[a], eta[a]});
    }
    const metrics::CriticalAngle found = metrics::critical_angle(points);
    if (found.found) expected[curve] = found.angle;
  }
  csv.close();
  REQUIRE(expected.size() == etas.size() - 1);  // all but seed 5 at the higher noise

  const render::ProgramOutput plotted =
      render::run_plot_script({sweep.path().string(), "--what", "thetac-eps"});
  INFO(plotted.output);
  REQUIRE(plotted.exit_status == 0);

  // One row per noise and seed, each seed's theta_c as the metrics layer finds it.
  std::ifstream seeds(sweep / "plots" / "theta_c_seeds.csv");
  std::string line;
  std::getline(seeds, line);
  CHECK(line == "species[0].noise.kick_eps,seed,theta_c,reason");
  std::size_t rows = 0;
  while (std::getline(seeds, line)) {
    ++rows;
    char eps[16] = {};
    int seed = 0;
    double angle = 0.0;
    REQUIRE(std::sscanf(line.c_str(), "%15[^,],%d,%lf", eps, &seed, &angle) == 3);
    const auto known = expected.find({eps, seed});
    if (known == expected.end()) {
      CHECK(std::isnan(angle));
      CHECK_THAT(line, Catch::Contains("never falls below half"));
    } else {
      CHECK(angle == Approx(known->second).epsilon(1e-6));
    }
  }
  CHECK(rows == etas.size());

  // The difference at the higher noise, over the seeds that have theta_c at both: 1, 2 and 3.
  std::vector<double> differences;
  for (const int seed : {1, 2, 3}) {
    differences.push_back(expected.at({"0.05", seed}) - expected.at({"0.01", seed}));
  }
  const double mean = (differences[0] + differences[1] + differences[2]) / 3.0;
  double variance = 0.0;
  for (const double d : differences) variance += (d - mean) * (d - mean) / 2.0;
  std::ifstream paired(sweep / "plots" / "theta_c_paired.csv");
  std::getline(paired, line);
  CHECK(line ==
        "species[0].noise.kick_eps,reference_species[0].noise.kick_eps,difference_mean,"
        "difference_stderr,seeds_paired,seeds");
  REQUIRE(std::getline(paired, line));
  double eps = 0.0, reference = 0.0, difference = 0.0, error = 0.0;
  int count = 0;
  REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%d", &eps, &reference, &difference, &error,
                      &count) == 5);
  CHECK(eps == 0.05);
  CHECK(reference == 0.01);
  CHECK(difference == Approx(mean).epsilon(1e-6));
  CHECK(error == Approx(std::sqrt(variance / 3.0)).epsilon(1e-6));
  CHECK(count == 3);
  CHECK_THAT(line, Catch::EndsWith(",1 2 3"));
  CHECK_FALSE(std::getline(paired, line));
  paired.close();

  // Plotted again into the same directory from one seed, nothing is left of the seeds' files.
  std::ofstream one_seed(sweep / "sweep.csv");
  one_seed << "point,trap.angle,species[0].noise.kick_eps,seed,status,eta_mean\n";
  for (std::size_t a = 0; a < angles.size(); ++a) {
    for (const char* eps : {"0.01", "0.05"}) {
      one_seed << "q" << a << eps << ',' << angles[a] << ',' << eps << ",1,complete,"
               << etas.at({eps, 1})[a] << '\n';
    }
  }
  one_seed.close();
  const render::ProgramOutput again =
      render::run_plot_script({sweep.path().string(), "--what", "thetac-eps"});
  INFO(again.output);
  REQUIRE(again.exit_status == 0);
  CHECK(std::filesystem::exists(sweep / "plots" / "theta_c.csv"));
  CHECK_FALSE(std::filesystem::exists(sweep / "plots" / "theta_c_seeds.csv"));
  CHECK_FALSE(std::filesystem::exists(sweep / "plots" / "theta_c_paired.csv"));
}

TEST_CASE("The plot script cautions about theta_c as the metrics layer does", "[render][plot]") {
  require_plot_python();
  const TempDirectory sweep;
  // At 80 degrees eta reached 90% of its level only at 120 s of a 150 s run.
  const std::vector<double> angles = {60, 80, 100, 120, 140};
  const std::vector<double> etas = {0.8, 0.7, 0.8, 0.1, 0.0};
  const std::vector<double> levelled = {20, 120, 30, 5, 1};
  std::ofstream csv(sweep / "sweep.csv");
  csv << "point,trap.angle,seed,status,eta_mean,eta_time_to_90_s,simulated_s\n";
  std::vector<metrics::SweepPoint> points;
  for (std::size_t a = 0; a < angles.size(); ++a) {
    csv << "p" << a << ',' << angles[a] << ",1,complete," << etas[a] << ',' << levelled[a]
        << ",150\n";
    points.push_back({angles[a], etas[a], levelled[a], 150});
  }
  csv.close();
  const metrics::CriticalAngle expected = metrics::critical_angle(points);
  REQUIRE(expected.found);
  REQUIRE_FALSE(expected.caution.empty());

  const render::ProgramOutput plotted =
      render::run_plot_script({sweep.path().string(), "--what", "eta-theta"});
  INFO(plotted.output);
  REQUIRE(plotted.exit_status == 0);
  std::ifstream theta_c(sweep / "plots" / "theta_c.csv");
  std::string header, line;
  std::getline(theta_c, header);
  REQUIRE(std::getline(theta_c, line));
  CHECK_THAT(line, Catch::Contains("caution: " + expected.caution));
}

TEST_CASE("The plot script draws a sweep over noise against its swept key", "[render][plot]") {
  require_plot_python();
  const TempDirectory sweep;
  std::ofstream csv(sweep / "sweep.csv");
  csv << "point,species[1].noise.white_Dr,seed,status,eta_mean,eta_trap_mean,purity_A_mean,"
         "purity_RnT_mean,sorting_index_mean\n";
  csv << "p1,0,1,complete,0.8,0.7,0.5,0.5,0.1\np2,0,2,complete,0.82,0.72,0.52,0.48,0.12\n";
  csv << "p3,0.5,1,complete,0.7,0.6,0.6,0.4,0.3\np4,2,1,complete,0.6,0.5,0.8,0.2,0.6\n";
  csv.close();
  // By default: the measures, and no complaint that the sweep is not over the angle.
  const render::ProgramOutput plotted = render::run_plot_script({sweep.path().string()});
  INFO(plotted.output);
  REQUIRE(plotted.exit_status == 0);
  CHECK_THAT(plotted.output, !Catch::Contains("not over trap.angle"));
  check_png(sweep / "plots" / "measures.png");
  // Axes and legends speak physics, not key paths.
  const std::string svg = read_text(sweep / "plots" / "measures.svg");
  CHECK_THAT(svg, Catch::Contains("rotational noise D_r of species 2 [rad²/s]"));
  CHECK_THAT(svg, !Catch::Contains("species[1].noise.white_Dr"));
  // Asked for eta-theta, it says why not and what to ask for instead.
  const render::ProgramOutput refused =
      render::run_plot_script({sweep.path().string(), "--what", "eta-theta"});
  CHECK(refused.exit_status != 0);
  CHECK_THAT(refused.output, Catch::Contains("`--what measures` plots it against its swept key"));
}
