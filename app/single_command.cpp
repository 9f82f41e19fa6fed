#include <iostream>
#include <memory>

#include "app/command.hpp"
#include "app/number_checks.hpp"
#include "runner/single_particle.hpp"

namespace rodsort::app {

Command add_single_command(CLI::App& app) {
  auto request = std::make_shared<runner::SingleParticleRequest>();
  CLI::App* single = app.add_subcommand(
      "single",
      "One species alone on the vibrated plate: v0, P(V_x), MSD, D_r, runs and tumbles "
      "(docs/single-particle.md)");
  single
      ->add_option("SCENARIO", request->scenario, "Scenario file (YAML): drive, materials, shapes")
      ->required()
      ->check(CLI::ExistingFile);
  single->add_option("--set", request->set_options,
                     "Override a scenario key, e.g. --set drive.gap=1.3 (repeatable)");
  single->add_option("--species", request->species,
                     "Name of the species to study (default: the scenario's first)");
  single->add_option("--rods", request->rods, "Independent rods")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  single->add_option("--duration", request->duration, "Measured simulated time per rod [s]")
      ->check(positive_number())
      ->capture_default_str();
  single->add_option("--warmup", request->warmup, "Simulated time before measuring [s]")
      ->check(non_negative_number())
      ->capture_default_str();
  single
      ->add_option("--sample", request->sample_interval,
                   "Interval between recorded frames [s]; divides metrics.window")
      ->check(positive_number())
      ->capture_default_str();
  single->add_option("--cell", request->cell, "Side of each rod's periodic cell [mm]")
      ->check(positive_number())
      ->capture_default_str();
  single
      ->add_option("--run-threshold", request->run_threshold,
                   "A window runs when V_x exceeds this [mm/s] (default: half the 90th "
                   "percentile of V_x)")
      ->check(non_negative_number());
  single
      ->add_option("--dt-halvings", request->dt_halvings,
                   "Also run the study at dt/2, dt/4, ... (this many halvings), each under "
                   "OUTPUT/dt-<dt>, and say whether the finest two agree")
      ->check(CLI::Range(0, 6))
      ->capture_default_str();
  single->add_option("-o,--output", request->output,
                     "Directory for summary.csv, per_rod.csv, axial_velocity.csv, lags.csv");
  return {single,
          [request] { return runner::run_single_particle(*request, std::cout, std::cerr); }};
}

}  // namespace rodsort::app
