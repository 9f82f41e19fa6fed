#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>

#include "engine/frame.hpp"
#include "engine/model.hpp"
#include "engine/state.hpp"

namespace rodsort::engine {

/// Counters of what the engine did, for tests and diagnostics.
struct SimulationCounters {
  std::int64_t kicks = 0;  ///< collision kicks applied (events of a rod hitting base or lid)
  /// The deepest any rod has gone into a neighbour, a wall or a plate over the steps taken since
  /// the Simulation was built or its counters reset (contact depths at the start of each step)
  /// [mm].
  double deepest_overlap = 0.0;
  /// Contact solves that Model::exact_contact_solver gave up on and left to the sequential-impulse
  /// iterations, since the world was built (from the Model or a restored State).
  std::int64_t exact_solver_fallbacks = 0;
  /// Tests of a pair of rods, or of a rod and a wall, skipped because the two could not have
  /// touched yet (rod_rod_collision.cpp), since the Simulation was built or its counters reset.
  std::int64_t pair_tests_skipped = 0;
};

/// A Bullet world built from a Model, stepped with the Model's fixed dt.
class Simulation {
 public:
  explicit Simulation(Model model);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Takes one step of dt. Throws std::runtime_error, naming the rod, the step and the quantity,
  /// when the model breaks down: a rod not finite, out of the space between base and lid, or a
  /// contact as deep as the two bodies' reach there (the sum of two spheres' radii, or a sphere's
  /// radius and a wall's or plate's half-thickness: that deep the contact no longer pushes them
  /// apart). The Simulation must not be stepped on after that. Shallower overlaps are only
  /// recorded (SimulationCounters::deepest_overlap).
  void step();
  void advance(std::int64_t steps);

  double time() const;  ///< [s]
  std::int64_t step_count() const;
  const Model& model() const;
  Frame frame() const;
  SimulationCounters counters() const;
  void reset_counters();

  State state() const;
  void restore(const State& state);

  /// Heights of the plates' top (base) and bottom (lid) surfaces at the current time [mm].
  double base_surface_z() const;
  double lid_surface_z() const;
  /// Vertical velocity Bullet gave the base over the last step [mm/s].
  double base_velocity_z() const;

  /// Writes the Bullet world (shapes, poses, contacts) as a .bullet file.
  void write_bullet_snapshot(const std::filesystem::path& path) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rodsort::engine
