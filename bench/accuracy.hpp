#pragma once
// Accuracy against cost: how the physics of one free rod A depends on the time step.
//
// The default dt must be small enough that a rod's self-propulsion is converged (the speed comes
// from many impacts per drive period and depends on how well each is resolved) and as large as
// possible, since cost grows as 1/dt. For each dt this runs several independent single rods with
// the paper's collision kick (different noise seeds), records frames at the paper's interval
// (0.07 s) after a warm-up, and reports, as mean and standard error over the rods:
//  - v0, the mean axial speed toward the thin end (metrics::mean_axial_speed, over one interval);
//  - D_r, the rotational diffusion of the heading (metrics::rotational_diffusion, lags of 1 to 10
//    intervals);
//  - the collision events per second;
//  - the restitution of rod A on the base: dropped as many times, on a still base, at 150 mm/s,
//    at a random heading and a random tilt of 0.15-0.35 rad (thick or thin end first), the ratio
//    of the normal velocities of its first-touching point after and before the impact (the
//    paper's rod-base coefficient is 0.1);
// and the cost of the paper's 319-rod system at that dt.

#include <CLI/CLI.hpp>
#include <cstdint>
#include <iosfwd>
#include <vector>

namespace rodsort::bench {

struct AccuracyOptions {
  std::vector<double> dts = {2.0e-4, 1.0e-4, 5.0e-5, 2.5e-5, 1.25e-5};  ///< [s]
  int rods = 8;                ///< independent single-rod runs per dt
  double seconds = 20.0;       ///< measured simulated time per rod [s]
  double warmup = 1.0;         ///< simulated time before measuring [s]
  double kick_eps = 0.01;      ///< collision kick [1/mm]
  double cost_time = 0.05;     ///< simulated time of the 319-rod cost measurement, 0 to skip [s]
  int solver_iterations = 10;  ///< engine::Model::solver_iterations
  bool reverse_contact_order = false;  ///< engine::Model::reverse_contact_order
  bool fixed_sweep_order = false;      ///< engine::Model::fixed_sweep_order
  bool full_turn_correction = false;   ///< engine::Model::full_turn_correction
  bool exact_contact_solver = false;   ///< engine::Model::exact_contact_solver
  double constraint_force_mixing = 0.0;  ///< engine::Model::constraint_force_mixing [s/g]
  std::uint64_t seed = 1;
  bool csv = false;
};

struct AccuracyResult {
  double dt = 0.0;                        ///< [s]
  double speed = 0.0;                     ///< v0 toward the thin end [mm/s]
  double speed_error = 0.0;               ///< standard error of the mean over rods [mm/s]
  double diffusion = 0.0;                 ///< D_r [rad^2/s]
  double diffusion_error = 0.0;           ///< [rad^2/s]
  double events_per_second = 0.0;         ///< collisions with base or lid per rod [1/s]
  double events_error = 0.0;              ///< standard error over rods [1/s]
  double restitution = 0.0;               ///< rod A on the base, mean over drops
  double restitution_error = 0.0;         ///< standard error over drops
  /// Steps whose contacts the exact solver left to the sweeps, over all steps of the rods' runs.
  double exact_fallback_fraction = 0.0;
  double single_cpu_per_simulated = 0.0;  ///< one rod, CPU seconds per simulated second
  double cost_319 = 0.0;  ///< 319-rod system, CPU seconds per simulated second (0: not measured)
};

/// Declares the accuracy options (with an --accuracy flag that selects this mode).
void add_accuracy_options(CLI::App& app, AccuracyOptions& options, bool& selected);

AccuracyResult measure_accuracy(double dt, const AccuracyOptions& options);

/// The restitution of one drop of rod A on a still base (see above), its pose drawn from `seed`.
double drop_restitution(double dt, const AccuracyOptions& options, std::uint64_t seed);

/// Measures every dt of `options`, printing each row as it is done. Returns an exit status.
int run_accuracy(const AccuracyOptions& options, std::ostream& out);

}  // namespace rodsort::bench
