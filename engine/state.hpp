#pragma once
// Everything that changes during a run, and nothing else: a checkpoint is a State. Restoring one
// means rebuilding the world from the Model and loading the State into it.

#include <array>
#include <cstdint>
#include <iosfwd>
#include <vector>

namespace rodsort::engine {

struct RodState {
  std::array<double, 3> position;          ///< wrapped centre of mass [mm]
  std::array<double, 9> basis;             ///< rotation matrix, row-major (body x = rod axis)
  std::array<double, 3> velocity;          ///< [mm/s]
  std::array<double, 3> angular_velocity;  ///< [rad/s]
  std::array<std::int64_t, 2> image;       ///< periodic image counts: unwrapped = wrapped + image*box
  std::array<bool, 2> touching;            ///< kick memory: touching base, lid after the last step
  std::array<std::uint64_t, 4> kick_rng;   ///< random stream of the collision kick
  std::array<std::uint64_t, 4> noise_rng;  ///< random stream of the white angular noise
};

struct State {
  double time = 0.0;       ///< [s]
  std::int64_t step = 0;
  std::vector<RodState> rods;
};

void write_state(std::ostream& out, const State& state);
/// Throws std::runtime_error on a truncated or foreign stream.
State read_state(std::istream& in);
/// A hash of every bit of the state, for determinism tests.
std::uint64_t hash_state(const State& state);

/// Throws std::invalid_argument, naming the rod and the quantity, unless `state` holds
/// `rod_count` rods with finite positions and velocities and orthonormal frames, at a finite,
/// non-negative time and step. Simulation::restore calls it before it tears anything down.
void check_state(const State& state, std::size_t rod_count);

}  // namespace rodsort::engine
