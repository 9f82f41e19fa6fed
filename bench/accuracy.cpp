#include "bench/accuracy.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <ostream>
#include <stdexcept>

#include "bench/benchmark.hpp"
#include "bench/measures.hpp"
#include "bench/standard_system.hpp"
#include "engine/random_stream.hpp"
#include "engine/simulation.hpp"
#include "engine/units.hpp"
#include "metrics/sample_statistics.hpp"
#include "metrics/single_rod.hpp"

namespace rodsort::bench {
namespace {

/// The paper's frame interval [s].
constexpr double kFrameInterval = 0.07;
/// Lags of the D_r fit, in frame intervals.
constexpr int kMinLag = 1, kMaxLag = 10;

/// One rod A at the centre of a 30 mm cell, the paper's drive.
engine::Model single_rod(double dt, const AccuracyOptions& options, std::uint64_t seed) {
  engine::Model model;
  model.solver_iterations = options.solver_iterations;
  model.reverse_contact_order = options.reverse_contact_order;
  model.fixed_sweep_order = options.fixed_sweep_order;
  model.full_turn_correction = options.full_turn_correction;
  model.exact_contact_solver = options.exact_contact_solver;
  model.constraint_force_mixing = options.constraint_force_mixing;
  model.box_x = model.box_y = 30.0;
  model.drive = engine::Drive::paper();
  model.dt = dt;
  model.seed = seed;
  model.species.push_back(rod_a_species(options.kick_eps));
  model.rods.push_back({0, 15.0, 15.0, 0.0});
  return model;
}

/// Speed at which drop_restitution's rod meets the base [mm/s].
constexpr double kDropSpeed = 150.0;

constexpr const char* kTableHeader =
    "      dt   v0 [mm/s]        D_r [rad^2/s]    events/s  1 rod CPU-s/sim-s  319 rods "
    "CPU-s/sim-s   restitution   exact fallbacks";
constexpr const char* kCsvHeader =
    "dt_s,v0_mm_s,v0_sem_mm_s,Dr_rad2_s,Dr_sem_rad2_s,events_per_s,single_cpu_s_per_simulated_s,"
    "cpu_s_per_simulated_s_319,events_sem_per_s,restitution,restitution_sem,exact_fallback_"
    "fraction";

void write_row(std::ostream& out, const AccuracyResult& r, bool csv) {
  if (csv) {
    out << format("%.6g", r.dt) << ',' << format("%.4f", r.speed) << ','
        << format("%.4f", r.speed_error) << ',' << format("%.4f", r.diffusion) << ','
        << format("%.4f", r.diffusion_error) << ',' << format("%.1f", r.events_per_second) << ','
        << format("%.5f", r.single_cpu_per_simulated) << ',' << format("%.4f", r.cost_319) << ','
        << format("%.2f", r.events_error) << ',' << format("%.5f", r.restitution) << ','
        << format("%.5f", r.restitution_error) << ',' << format("%.5f", r.exact_fallback_fraction)
        << '\n';
    return;
  }
  char line[220];
  std::snprintf(
      line, sizeof line,
      "%8.3g %6.2f +- %4.2f   %5.3f +- %5.3f %11.0f %18.4f %20.3f   %5.3f +- %5.3f %17.5f", r.dt,
      r.speed, r.speed_error, r.diffusion, r.diffusion_error, r.events_per_second,
      r.single_cpu_per_simulated, r.cost_319, r.restitution, r.restitution_error,
      r.exact_fallback_fraction);
  out << line << '\n';
}

}  // namespace

void add_accuracy_options(CLI::App& app, AccuracyOptions& options, bool& selected) {
  app.add_flag("--accuracy", selected,
               "measure single-rod speed and D_r against dt instead of the cost of the systems");
  app.add_option("--dts", options.dts, "time steps of --accuracy [s]")
      ->delimiter(',')
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--rods", options.rods, "independent single rods per dt in --accuracy")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--seconds", options.seconds, "measured simulated time per rod in --accuracy [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--kick-eps", options.kick_eps, "collision kick in --accuracy [1/mm]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_option(
         "--cost-time", options.cost_time,
         "simulated time of the 319-rod cost measurement per dt in --accuracy, 0 to skip [s]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app.add_flag(
      "--reverse-contact-order", options.reverse_contact_order,
      "in --accuracy, the solver meets each rod's contacts in the reverse of the canonical "
      "order (a check that results do not depend on it)");
  app.add_flag("--fixed-sweep-order", options.fixed_sweep_order,
               "in --accuracy, every solver sweep meets the contacts in the canonical order "
               "instead of a random one");
  app.add_flag("--full-turn-correction", options.full_turn_correction,
               "in --accuracy, the turns of the solver's position correction are applied in full "
               "(scenario key run.turn_correction: full)");
  app.add_flag("--exact-solver", options.exact_contact_solver,
               "in --accuracy, solve each step's contacts exactly (Bullet's MLCP solver, Dantzig's "
               "algorithm) instead of by the solver's sweeps");
  app.add_option("--cfm", options.constraint_force_mixing,
                 "in --accuracy, the solvers' constraint force mixing, a compliance of every "
                 "contact [s/g]")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

double drop_restitution(double dt, const AccuracyOptions& options, std::uint64_t seed) {
  engine::Model model = single_rod(dt, options, seed);
  model.drive.amplitude = 0.0;
  model.drive.gap = 10.0;  // nothing reaches the lid
  engine::Simulation simulation(model);
  engine::RandomStream pose(seed, 0, engine::StreamPurpose::kPlacement);
  const double heading = 2.0 * M_PI * pose.uniform();
  // Tilted enough that one end touches well before the other (the thin end is lower from about
  // 0.09 rad on): with both ends landing in one step the sequential-impulse solver shares the
  // rebound between the two contacts, and a single end's ratio is no longer the coefficient.
  const double tilt = pose.sign() * (0.15 + 0.2 * pose.uniform());  // > 0: thin end first
  const Eigen::Matrix3d basis = (Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(tilt, Eigen::Vector3d::UnitY()))
                                    .toRotationMatrix();
  const std::vector<engine::Sphere>& spheres = model.species.front().shape.spheres;
  // The sphere whose bottom is lowest touches first; its bottom point is the one measured.
  std::size_t lowest = 0;
  const auto bottom = [&](std::size_t i, const Eigen::Vector3d& axis) {
    return spheres[i].axial * axis.z() - spheres[i].radius;
  };
  for (std::size_t i = 1; i < spheres.size(); ++i) {
    if (bottom(i, basis.col(0)) < bottom(lowest, basis.col(0))) lowest = i;
  }
  engine::State state = simulation.state();
  engine::RodState& rod = state.rods.front();
  rod.position[2] = simulation.base_surface_z() + 0.3 - bottom(lowest, basis.col(0));
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) rod.basis[3 * row + column] = basis(row, column);
  }
  rod.velocity = {0.0, 0.0, -kDropSpeed};
  rod.angular_velocity = {0.0, 0.0, 0.0};
  simulation.restore(state);
  const auto point_velocity = [&] {
    const engine::RodFrame frame = simulation.frame().rods.front();
    const Eigen::Vector3d arm =
        spheres[lowest].axial * frame.axis - spheres[lowest].radius * Eigen::Vector3d::UnitZ();
    return frame.velocity.z() + frame.angular_velocity.cross(arm).z();
  };
  double before = point_velocity();
  for (int step = 0; step < 100000; ++step) {
    simulation.step();
    const double after = point_velocity();
    // Gravity adds g dt to the approach in the step of the impact, before the solver acts.
    if (after > 0.0) return after / (-before + kGravity * dt);
    before = after;
  }
  throw std::runtime_error("drop_restitution: the rod never rebounded");
}

AccuracyResult measure_accuracy(double dt, const AccuracyOptions& options) {
  const std::int64_t steps_per_frame = std::llround(kFrameInterval / dt);
  const int frame_count = static_cast<int>(std::lround(options.seconds / kFrameInterval)) + 1;
  std::vector<double> speeds, diffusions, event_rates;
  double events = 0.0, cpu = 0.0, simulated = 0.0, fallbacks = 0.0, steps = 0.0;
  for (int rod = 0; rod < options.rods; ++rod) {
    engine::Simulation simulation(
        single_rod(dt, options, options.seed + static_cast<std::uint64_t>(rod)));
    simulation.advance(std::llround(options.warmup / dt));
    const std::int64_t events_before = simulation.counters().kicks;
    const double cpu_start = process_cpu_seconds();
    std::vector<engine::Frame> frames{simulation.frame()};
    for (int f = 1; f < frame_count; ++f) {
      simulation.advance(steps_per_frame);
      frames.push_back(simulation.frame());
    }
    cpu += process_cpu_seconds() - cpu_start;
    const double elapsed = frames.back().time - frames.front().time;
    simulated += elapsed;
    events += static_cast<double>(simulation.counters().kicks - events_before);
    event_rates.push_back(static_cast<double>(simulation.counters().kicks - events_before) /
                          elapsed);
    fallbacks += static_cast<double>(simulation.counters().exact_solver_fallbacks);
    steps += static_cast<double>(simulation.step_count());
    speeds.push_back(metrics::mean_axial_speed(frames, {0}, 1));
    diffusions.push_back(metrics::rotational_diffusion(frames, {0}, kMinLag, kMaxLag).coefficient);
  }
  AccuracyResult result;
  result.dt = dt;
  const metrics::SampleStatistics speed = metrics::sample_statistics(speeds);
  const metrics::SampleStatistics diffusion = metrics::sample_statistics(diffusions);
  result.speed = speed.mean;
  result.speed_error = speed.standard_error;
  result.diffusion = diffusion.mean;
  result.diffusion_error = diffusion.standard_error;
  result.events_per_second = events / simulated;
  result.events_error = metrics::sample_statistics(event_rates).standard_error;
  result.single_cpu_per_simulated = cpu / simulated;
  result.exact_fallback_fraction = fallbacks / steps;
  std::vector<double> restitutions;
  for (int drop = 0; drop < options.rods; ++drop) {
    restitutions.push_back(
        drop_restitution(dt, options, options.seed + static_cast<std::uint64_t>(drop)));
  }
  const metrics::SampleStatistics restitution = metrics::sample_statistics(restitutions);
  result.restitution = restitution.mean;
  result.restitution_error = restitution.standard_error;
  if (options.cost_time > 0.0) {
    Options cost;
    cost.dt = dt;
    cost.simulated_time = options.cost_time;
    cost.seed = options.seed;
    cost.solver_iterations = options.solver_iterations;
    result.cost_319 = run_system("319", cost, std::cerr).cpu_per_simulated;
  }
  return result;
}

int run_accuracy(const AccuracyOptions& options, std::ostream& out) {
  out << (options.csv ? kCsvHeader : kTableHeader) << '\n' << std::flush;
  for (const double dt : options.dts) {
    write_row(out, measure_accuracy(dt, options), options.csv);
    out << std::flush;
  }
  return 0;
}

}  // namespace rodsort::bench
