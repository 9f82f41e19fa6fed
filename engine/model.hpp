#pragma once
// The compiled, constant description of a simulation: every default resolved, every derived value
// computed. No YAML here; scenarios/ builds it, engine/ runs it.

#include <cstdint>
#include <string>
#include <vector>

#include "engine/materials.hpp"
#include "engine/plate_roughness.hpp"
#include "engine/rod_shape.hpp"

namespace rodsort::engine {

/// Vertical drive of base and lid: z_base(t) = amplitude cos(2 pi frequency t), z_lid = z_base +
/// gap.
struct Drive {
  double frequency;  ///< [Hz], paper: 200
  double amplitude;  ///< [mm], paper: Gamma = 7 -> 0.0435
  double gap;        ///< lid height above base [mm], paper: 1.2

  /// Amplitude from the dimensionless acceleration Gamma = A (2 pi f)^2 / g.
  static double amplitude_from_gamma(double gamma, double frequency);
  /// The paper's drive: f = 200 Hz, Gamma = 7, w = 1.2 mm.
  static Drive paper();
  double gamma() const;
};

struct Noise {
  double kick_eps = 0.0;  ///< collision kick: omega_z += s eps v_rel at base/lid impacts [1/mm]
  double white_Dr = 0.0;  ///< white angular noise, rotational diffusion coefficient [rad^2/s]
};

struct Species {
  std::string name;
  RodShape shape;
  Noise noise;
  int material = MaterialTable::kFirstRod;  ///< index into Model::materials
};

/// Initial condition of one rod, resting on the base plate.
struct RodInit {
  int species;     ///< index into Model::species
  double x, y;     ///< centre of mass in the cell [mm]
  double heading;  ///< direction from the thick to the thin end, in the plane [rad]
  /// Turn about the rod's own axis [rad], counter-clockwise seen from the thin end: at 0 the body
  /// y axis lies in the plane, to the left of the heading. It matters only for a rod that is not
  /// straight (RodShape::spheres with an offset), whose off-axis part it places.
  double roll = 0.0;
};

/// A static vertical wall spanning the gap (trap arms and other obstacles), a box in 3D.
struct Wall {
  double center_x, center_y;  ///< [mm]
  double half_length;         ///< along the wall [mm]
  double half_thickness;      ///< across the wall [mm]
  double yaw;                 ///< direction of the wall's length in the plane [rad]
  int material = MaterialTable::kWall;
};

struct Model {
  double box_x = 0.0, box_y = 0.0;  ///< periodic cell [0, box_x) x [0, box_y) [mm]
  Drive drive{};
  Roughness roughness{};
  std::vector<Species> species;
  std::vector<RodInit> rods;
  std::vector<Wall> walls;
  MaterialTable materials = MaterialTable::paper();
  double dt = 1.0e-4;  ///< time step [s]
  std::uint64_t seed = 1;
  int solver_iterations = 10;
  /// Apply the turn velocities of Bullet's position correction (split impulse) in full instead of
  /// a tenth (Bullet's default), and turn the white noise through it so that contacts resist it
  /// (docs/model.md, "Checks while a run goes"). Off by default: see there why.
  bool full_turn_correction = false;
  /// A diagnostic for tests and the benchmark: the solver meets each rod's contacts in the reverse
  /// of the canonical order (solver_batches.cpp); results must agree within their errors.
  bool reverse_contact_order = false;
  /// A diagnostic for the benchmark: every solver sweep meets the contacts in the canonical order
  /// instead of a random one (periodic_boundary.cpp, "Sweep order"), as Bullet does by default.
  bool fixed_sweep_order = false;
  /// A diagnostic for tests: the solver takes every contact island in one call instead of batch by
  /// batch (solver_batches.cpp); with fixed_sweep_order the results must be bit for bit the same.
  bool single_solver_batch = false;
  /// A diagnostic for tests: every pair of rods, and of a rod and a wall, that the broadphase finds
  /// is tested at every step, none skipped for being apart (rod_rod_collision.cpp); the results
  /// must be bit for bit the same.
  bool test_every_pair = false;
  /// A diagnostic for the benchmark: each batch of contacts is solved exactly, as one linear
  /// complementarity problem with box friction (Bullet's MLCP solver, Dantzig's algorithm), instead
  /// of by ten sweeps; a problem it cannot solve falls back to the sweeps and is counted
  /// (SimulationCounters::exact_solver_fallbacks). Its cost grows as the cube of a batch's
  /// contacts: for lone rods only (docs/model.md, "An exact contact solve").
  bool exact_contact_solver = false;
  /// Bullet's constraint force mixing (btContactSolverInfo::m_globalCfm), used by both solvers: a
  /// compliance of every contact row, added as cfm / dt to the diagonal of the problem, whose
  /// entries are velocity per impulse [1/g] (rod A: 1/m = 61 per g) [s/g]. Zero, Bullet's
  /// default, is a rigid contact.
  double constraint_force_mixing = 0.0;
};

/// The compliance the scenario key run.contact_solver: exact sets (Model::constraint_force_mixing)
/// [s/g]: small against every entry of the problem, it keeps rigid contacts along a line
/// solvable and changes no measured figure (docs/model.md, "An exact contact solve").
inline constexpr double kExactSolverCompliance = 1.0e-8;

}  // namespace rodsort::engine
