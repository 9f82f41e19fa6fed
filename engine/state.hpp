#pragma once
// Everything that changes during a run, and nothing else: a checkpoint is a State. Restoring one
// means rebuilding the world from the Model and loading the State into it, and a restored world
// steps on exactly as the one it was saved from did, bit for bit (simulation.cpp, "Restoring").

#include <array>
#include <cstdint>
#include <iosfwd>
#include <tuple>
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

/// One point of a persistent contact manifold, every field of Bullet's btManifoldPoint that the
/// next step reads or carries on (the warm-start impulses above all).
struct ContactPointState {
  std::array<double, 3> local_a, local_b;  ///< in the rod's and the surface's frames [mm]
  std::array<double, 3> world_a, world_b;  ///< [mm]
  std::array<double, 3> normal;            ///< on the surface, toward the rod
  std::array<double, 3> friction_dir1, friction_dir2;
  double distance;                  ///< negative: penetration [mm]
  std::array<double, 4> combined;   ///< friction, rolling, spinning, restitution
  std::array<double, 9> solver;     ///< applied impulse, previous rhs, lateral impulses 1 and 2,
                                    ///< contact motion 1 and 2, cfm, erp, friction cfm
  std::array<std::int32_t, 6> ids;  ///< part 0, part 1, index 0, index 1, flags, lifetime
};

/// The persistent manifold of one sphere of a rod with the base, the lid or a wall. Contacts
/// between rods are rebuilt at every step and carry nothing over.
struct SurfaceContactState {
  std::int32_t rod = 0;
  std::int32_t surface = 0;  ///< 0 the base, 1 the lid, 2 + w wall w
  std::int32_t sphere = 0;
  std::vector<ContactPointState> points;  ///< 1 to 4, in the manifold's order
};

/// The order of State::contacts: by rod, then surface, then sphere.
inline bool comes_before(const SurfaceContactState& a, const SurfaceContactState& b) {
  return std::tie(a.rod, a.surface, a.sphere) < std::tie(b.rod, b.surface, b.sphere);
}

struct State {
  double time = 0.0;       ///< [s]
  std::int64_t step = 0;
  std::vector<RodState> rods;
  /// Sorted by rod, surface and sphere.
  std::vector<SurfaceContactState> contacts;
};

void write_state(std::ostream& out, const State& state);
/// Throws std::runtime_error on a truncated or foreign stream.
State read_state(std::istream& in);
/// A hash of every bit of the state, for determinism tests.
std::uint64_t hash_state(const State& state);

/// Throws std::invalid_argument, naming the rod and the quantity, unless `state` holds
/// `rod_count` rods with finite positions and velocities and orthonormal frames, at a finite,
/// non-negative time and step, and contacts of existing rods, surfaces (`surface_count`: 2 plus
/// the walls) and spheres (`sphere_counts`, per rod), in order, with finite values.
/// Simulation::restore calls it before it tears anything down.
void check_state(const State& state, std::size_t rod_count, int surface_count,
                 const std::vector<int>& sphere_counts);

}  // namespace rodsort::engine
