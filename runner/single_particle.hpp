#pragma once
// `rodsort single SCENARIO`: what one rod of a species does alone on the vibrated plate, measured
// as the experiments measure it. Everything physical comes from the scenario (drive, gap,
// materials, shape, noise, dt, solver), so a factor is varied with `--set` exactly as in a run;
// the trap, the other species and the rod count are left out. Each rod runs in its own periodic
// cell, from its own noise seed (scenario seed + rod index) and its own phase of the drive (the
// warm-up of rod i is longer by i / rods of a drive period), so rods without noise are
// independent samples too. The report: v0 with its standard error over rods, P(V_x) over the
// window, the MSD of the centre, the heading's correlation and D_r, and runs and tumbles.

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace rodsort::runner {

struct SingleParticleRequest {
  std::filesystem::path scenario;
  std::vector<std::string> set_options;  ///< "key.path=value", applied in order
  std::string species;                   ///< name; empty: the scenario's first species
  int rods = 16;                         ///< independent rods
  double duration = 40.0;                ///< measured simulated time per rod [s]
  double warmup = 2.0;                   ///< simulated time before measuring [s]
  double sample_interval = 0.01;         ///< between recorded frames [s]; divides the window
  double cell = 30.0;                    ///< side of each rod's periodic cell [mm]
  double run_threshold = -1.0;           ///< [mm/s]; negative: half the 90th percentile of V_x
  std::filesystem::path output;          ///< directory for the CSV files; empty: print only
  /// Also repeat the study at dt / 2, dt / 4, ... (this many halvings), each under
  /// output/dt-<dt>, and say whether the finest two agree (a check of the gait's convergence).
  int dt_halvings = 0;
};

/// Runs the study, prints its summary on `out` and progress on `err`, writes the files when an
/// output directory is given; with dt_halvings, runs it at each step and then compares them.
/// Returns an exit status (runner/exit_code.hpp).
int run_single_particle(const SingleParticleRequest& request, std::ostream& out, std::ostream& err);

}  // namespace rodsort::runner
